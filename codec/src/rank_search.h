// Exact distance ranks (paper, Section 3.1).
//
// The predicted point is snapped to a fixed-point grid (1/16 of a
// quantization step) and distances are squared integers in 64 bits, so the
// order is the same on every machine; equal distances are ordered by vertex
// index. Rank 1 is the nearest admissible vertex.
#ifndef DRM_RANK_SEARCH_H
#define DRM_RANK_SEARCH_H

#include <cstdint>
#include <utility>
#include <vector>

#include "exact_math.h"
#include "traversal.h"

namespace drm {

class VertexIndex;

struct FixedPoint {
    int64_t x = 0, y = 0, z = 0;
};

// The prediction on the fixed-point grid, clamped well outside the model's
// box so that squared distances cannot overflow.
FixedPoint snapPrediction(Vec3 prediction, int bits);

class RankSearch {
public:
    RankSearch(const std::vector<int32_t>& grid, int bits, const VertexIndex& candidates,
               const Traversal& traversal);

    // Encoder: the rank of apex among the admissible vertices around the
    // prediction (1 = nearest).
    uint32_t rankOf(Vec3 prediction, uint32_t apex, const OpenEdge& edge);

    // Decoder: the admissible vertex of the given rank (>= 1). Throws Error
    // if fewer admissible vertices exist.
    uint32_t vertexOfRank(Vec3 prediction, uint32_t rank, const OpenEdge& edge);

    int64_t distance2(const FixedPoint& p, uint32_t v) const;

private:
    const std::vector<int32_t>& grid_;
    int bits_;
    const VertexIndex& candidates_;
    const Traversal& traversal_;
    std::vector<uint32_t> nearby_;
    std::vector<std::pair<int64_t, uint32_t>> ranked_;
};

}  // namespace drm

#endif  // DRM_RANK_SEARCH_H
