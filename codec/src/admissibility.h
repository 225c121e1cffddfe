// Which vertices may close the triangle across an open edge.
//
// This is the one place that decides it, for the ranking and for the
// predictors' searches alike; encoder and decoder must apply the same rule,
// and filters that go beyond the paper belong here.
#ifndef DRM_ADMISSIBILITY_H
#define DRM_ADMISSIBILITY_H

#include "traversal.h"

namespace drm {

// The paper's rule: culled vertices (whose fans are complete) are out. The
// edge's own ends can never be its apex either; counting them as candidates
// costs 3-12% (method notes).
inline bool isAdmissibleApex(uint32_t v, const OpenEdge& edge, const Traversal& traversal) {
    return v != edge.vi && v != edge.vj && !traversal.isCulled(v);
}

}  // namespace drm

#endif  // DRM_ADMISSIBILITY_H
