#include "rank_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "drm/drm.h"
#include "vertex_index.h"

namespace drm {
namespace {

int64_t snapAxis(double x, int bits) {
    // Grid coordinates lie in [0, 2^bits); predictions far outside are as
    // good as clamped ones for ranking purposes, and the clamp bounds every
    // difference by 2^(bits+2) steps, so 3 squared differences in 1/16 steps
    // stay below 2^61 for bits <= 21.
    const double limit = double(int64_t(1) << (bits + 1));
    const double clamped = std::min(std::max(x, -limit), limit);  // inputs are finite
    return int64_t(std::floor(clamped * double(kSubUnits) + 0.5));
}

Vec3 toGridUnits(const FixedPoint& p) {
    return {double(p.x) / kSubUnits, double(p.y) / kSubUnits, double(p.z) / kSubUnits};
}

}  // namespace

FixedPoint snapPrediction(Vec3 p, int bits) { return {snapAxis(p.x, bits), snapAxis(p.y, bits), snapAxis(p.z, bits)}; }

RankSearch::RankSearch(const std::vector<int32_t>& grid, int bits, const VertexIndex& candidates,
                       const Admissibility& admissible)
    : grid_(grid), bits_(bits), candidates_(candidates), admissible_(admissible) {}

int64_t RankSearch::distance2(const FixedPoint& p, uint32_t v) const {
    const int64_t dx = int64_t(grid_[3 * size_t(v)]) * kSubUnits - p.x;
    const int64_t dy = int64_t(grid_[3 * size_t(v) + 1]) * kSubUnits - p.y;
    const int64_t dz = int64_t(grid_[3 * size_t(v) + 2]) * kSubUnits - p.z;
    return dx * dx + dy * dy + dz * dz;
}

uint32_t RankSearch::rankOf(const FixedPoint& p, uint32_t apex, const OpenEdge& edge, uint32_t preferred) {
    if (apex == preferred) return 1;
    const int64_t apexDistance = distance2(p, apex);
    candidates_.collectNear(toGridUnits(p), std::sqrt(double(apexDistance)) / kSubUnits, nearby_);
    uint32_t closer = preferred == kNoPreference ? 0 : 1;
    for (uint32_t v : nearby_) {
        if (v == apex || v == preferred || !admissible_(v, edge)) continue;
        const int64_t d = distance2(p, v);
        if (d < apexDistance || (d == apexDistance && v < apex)) ++closer;
    }
    return closer + 1;
}

uint32_t RankSearch::vertexOfRank(const FixedPoint& p, uint32_t rank, const OpenEdge& edge, uint32_t preferred) {
    if (preferred != kNoPreference) {
        if (rank == 1) return preferred;
        --rank;
    }
    if (rank == 0 || rank > candidates_.presentCount())
        throw Error("rank " + std::to_string(rank) + " is impossible: only " +
                    std::to_string(candidates_.presentCount()) + " candidate vertices remain");
    const std::vector<RankedVertex>& order = nearest(p, rank, edge, preferred);
    if (order.size() < rank)
        throw Error("rank " + std::to_string(rank) + " is impossible: only " + std::to_string(order.size()) +
                    " admissible vertices remain for edge " + std::to_string(edge.vi) + "-" +
                    std::to_string(edge.vj));
    return order[rank - 1].second;
}

const std::vector<RankedVertex>& RankSearch::nearest(const FixedPoint& p, size_t count, const OpenEdge& edge,
                                                     uint32_t skip) {
    const Vec3 center = toGridUnits(p);
    // Start with a radius that holds a few more vertices than asked for (the
    // edge's ends and filtered vertices may be among them) and double it
    // until enough admissible vertices lie inside; everything within the
    // radius is then known exactly, so the nearest of them are the answer
    // whatever radius the float search suggested.
    double radius = candidates_.radiusHolding(center, std::min(count + 3, candidates_.presentCount()));
    const double everything = double(int64_t(1) << (bits_ + 3));  // covers the box from any clamped point
    for (;;) {
        const bool complete = !(radius < everything);
        candidates_.collectNear(center, complete ? everything : radius, nearby_);
        const double limit = radius * double(kSubUnits);
        const int64_t inside = complete ? std::numeric_limits<int64_t>::max() : int64_t(std::floor(limit * limit));
        ranked_.clear();
        for (uint32_t v : nearby_) {
            if (v == skip || !admissible_(v, edge)) continue;
            const int64_t d = distance2(p, v);
            if (d <= inside) ranked_.emplace_back(d, v);
        }
        if (ranked_.size() >= count || complete) {
            const size_t keep = std::min(count, ranked_.size());
            std::partial_sort(ranked_.begin(), ranked_.begin() + keep, ranked_.end());
            ranked_.resize(keep);
            return ranked_;
        }
        radius *= 2;
    }
}

}  // namespace drm
