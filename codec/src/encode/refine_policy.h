// GeometryCoder::Auto's choice between the spanning tree and refine: the
// tree's attempt always, refine's where an estimate of its vertex bits
// promises a smaller file, the smaller file kept (docs/design.md, "The
// geometry coders").
#ifndef DRM_REFINE_POLICY_H
#define DRM_REFINE_POLICY_H

#include "encode/encode_session.h"
#include "encode/vertex_section.h"
#include "progress.h"

namespace drm {

// `section`: the tree's vertex section on the full grid when the caller
// has coded it already (encodeConnectivity), else coded here.
// `early` (may be null): the tree attempt's connectivity, coded before its
// section (encodeBeforeVertexSection).
Attempt encodeWithChosenGeometry(const EncodeSession& session, VertexSection section, EarlyConnectivity* early,
                                 ProgressReporter& progress);

}  // namespace drm

#endif  // DRM_REFINE_POLICY_H
