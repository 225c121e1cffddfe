// The candidate set: a FLANN kd-tree over the quantized vertices, from which
// culled vertices are removed as the traversal closes their fans.
//
// FLANN works in single precision, so it is used only to gather a superset of
// the vertices near a point; every decision that encoder and decoder must
// agree on (inside a radius, rank order) is made afterwards by exact tests on
// the integer grid coordinates.
#ifndef DRM_VERTEX_INDEX_H
#define DRM_VERTEX_INDEX_H

#include <cstdint>
#include <memory>
#include <vector>

#include "exact_math.h"

namespace drm {

class VertexIndex {
public:
    explicit VertexIndex(const std::vector<int32_t>& grid);
    ~VertexIndex();
    VertexIndex(const VertexIndex&) = delete;
    VertexIndex& operator=(const VertexIndex&) = delete;

    // Takes v out of every later search (the paper's vertex culling).
    void remove(uint32_t v);
    size_t presentCount() const { return present_; }

    // Appends to out every present vertex whose distance from q is at most
    // radius (grid units), plus possibly some slightly farther ones: callers
    // apply their own exact test. out is cleared first.
    void collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const;

    // A radius that holds at least k present vertices around q (an
    // estimate from the float search, padded); infinity if fewer than k
    // vertices are present.
    double radiusHolding(Vec3 q, size_t k) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    size_t present_ = 0;
};

}  // namespace drm

#endif  // DRM_VERTEX_INDEX_H
