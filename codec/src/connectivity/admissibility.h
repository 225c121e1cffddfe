// Which vertices may close the triangle across an open edge.
//
// This is the one place that decides it, for the ranking and for the
// predictors' searches alike: encoder and decoder must apply the same rule.
#ifndef DRM_ADMISSIBILITY_H
#define DRM_ADMISSIBILITY_H

#include "connectivity/traversal.h"

namespace drm {

class Admissibility {
public:
    Admissibility(const Traversal& traversal, bool topologicalFilter)
        : traversal_(traversal), topologicalFilter_(topologicalFilter) {}

    bool operator()(uint32_t v, const OpenEdge& edge) const {
        // The paper's rule: culled vertices (whose fans are complete) are
        // out. The edge's own ends can never be its apex either; counting
        // them costs 3-12% (method notes).
        if (v == edge.vi || v == edge.vj || traversal_.isCulled(v)) return false;
        // The first of two connectivity parts (connectivity_parts.h): a face
        // over three vertices from the seam on is the second part's.
        if (v >= seam_ && edge.vi >= seam_ && edge.vj >= seam_) return false;
        if (!topologicalFilter_) return true;
        // A vertex not yet in the mesh has no edges, and the opposite
        // vertex is in it: nothing below can refuse it (most candidates
        // ahead of the front), so the edge look-ups are skipped.
        if (!traversal_.isTouched(v)) return true;
        // The new triangle (vj, vi, v) adds the directed edges vi->v and
        // v->vj: neither may exist yet, as a rebuilt edge or as the missing
        // twin of a coded boundary.
        if (traversal_.thirdVertex(edge.vi, v) != Traversal::kNoTriangle) return false;
        if (traversal_.thirdVertex(v, edge.vj) != Traversal::kNoTriangle) return false;
        // The opposite vertex closes the edge only in a two-triangle
        // component, the back face of the start triangle.
        if (v == edge.opposite && traversal_.componentTriangleCount() > 1) return false;
        return true;
    }

    const Traversal& traversal() const { return traversal_; }
    // The first part of a two-part connectivity: vertices from `first` on
    // hold the second part's faces among themselves.
    void setSeam(uint32_t first) { seam_ = first; }

private:
    const Traversal& traversal_;
    bool topologicalFilter_;
    uint32_t seam_ = 0xFFFFFFFFu;  // no vertex: a whole mesh's traversal
};

}  // namespace drm

#endif  // DRM_ADMISSIBILITY_H
