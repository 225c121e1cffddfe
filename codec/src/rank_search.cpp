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

Vec3 toGridUnits(const FixedPoint& p) {  // for collectNear, which takes a superset radius
    return {double(p.x) / kSubUnits, double(p.y) / kSubUnits, double(p.z) / kSubUnits};
}

}  // namespace

FixedPoint snapPrediction(Vec3 p, int bits) { return {snapAxis(p.x, bits), snapAxis(p.y, bits), snapAxis(p.z, bits)}; }

RankSearch::RankSearch(const std::vector<int32_t>& grid, const VertexIndex& candidates,
                       const Admissibility& admissible)
    : grid_(grid), index_(candidates), admissible_(admissible) {}

int64_t RankSearch::distance2(const FixedPoint& p, uint32_t v) const {
    const int64_t dx = int64_t(grid_[3 * size_t(v)]) * kSubUnits - p.x;
    const int64_t dy = int64_t(grid_[3 * size_t(v) + 1]) * kSubUnits - p.y;
    const int64_t dz = int64_t(grid_[3 * size_t(v) + 2]) * kSubUnits - p.z;
    return dx * dx + dy * dy + dz * dz;
}

uint32_t RankSearch::rankOf(const FixedPoint& p, uint32_t apex, const OpenEdge& edge, uint32_t preferred) {
    if (apex == preferred) return 1;
    const int64_t apexDistance = distance2(p, apex);
    index_.collectNear(toGridUnits(p), std::sqrt(double(apexDistance)) / kSubUnits, nearby_);
    uint32_t closer = preferred == kNoPreference ? 0 : 1;
    for (uint32_t v : nearby_) {
        if (v == apex || v == preferred) continue;
        const int64_t d = distance2(p, v);
        if ((d < apexDistance || (d == apexDistance && v < apex)) && admissible_(v, edge)) ++closer;
    }
    return closer + 1;
}

uint32_t RankSearch::vertexOfRank(const FixedPoint& p, uint32_t rank, const OpenEdge& edge, uint32_t preferred) {
    if (preferred != kNoPreference) {
        if (rank == 1) return preferred;
        --rank;
    }
    if (rank == 0 || rank > index_.presentCount())
        throw Error("rank " + std::to_string(rank) + " is impossible: only " +
                    std::to_string(index_.presentCount()) + " candidate vertices remain");
    const std::vector<RankedVertex>& order = nearest(p, rank, edge, preferred);
    if (order.size() < rank)
        throw Error("rank " + std::to_string(rank) + " is impossible: only " + std::to_string(order.size()) +
                    " admissible vertices remain for edge " + std::to_string(edge.vi) + "-" +
                    std::to_string(edge.vj));
    return order[rank - 1].second;
}

// Rings of cells outwards from p's cell, until `count` admissible vertices
// lie nearer than anything outside the rings can be: they are then the
// nearest, exactly (ties ordered by index), whatever the cell size.
const std::vector<RankedVertex>& RankSearch::nearest(const FixedPoint& p, size_t count, const OpenEdge& edge,
                                                     uint32_t skip) {
    ranked_.clear();
    if (count == 0) return ranked_;
    if (count > kFewNearest) return manyNearest(p, count, edge, skip);
    // Admissibility costs edge look-ups: it is asked only of vertices that
    // would enter the answer.
    index_.nearestFew(
        p, count, [&](uint32_t v) { return distance2(p, v); },
        [&](uint32_t v) { return v != skip && admissible_(v, edge); }, ranked_, nearby_);
    return ranked_;
}

// For long rank lists (a decoder asked for a far rank): everything in the
// rings, sorted, then admissibility in rank order. Sorting is what costs, so
// it waits until the rings hold `count` vertices at all, and after a failed
// attempt until they have doubled.
const std::vector<RankedVertex>& RankSearch::manyNearest(const FixedPoint& p, size_t count, const OpenEdge& edge,
                                                         uint32_t skip) {
    candidates_.clear();
    auto collect = [&](const uint32_t* first, size_t n) {
        for (size_t i = 0; i < n; ++i)
            if (first[i] != skip) candidates_.emplace_back(distance2(p, first[i]), first[i]);
    };
    auto settle = [&](int64_t clear) {  // true once `count` admissible vertices are nearer than clear
        std::sort(candidates_.begin(), candidates_.end());
        ranked_.clear();
        for (const RankedVertex& c : candidates_) {
            if (c.first >= clear) return false;
            if (admissible_(c.second, edge)) {
                ranked_.push_back(c);
                if (ranked_.size() == count) return true;
            }
        }
        return false;
    };
    size_t settleFrom = count;
    uint64_t cellsVisited = 0;
    for (int ring = index_.firstRing(p);; ++ring) {
        cellsVisited += VertexIndex::ringCellCount(ring);
        if (cellsVisited > index_.cellBudget()) {
            candidates_.clear();
            nearby_.clear();
            index_.collectAll(nearby_);
            collect(nearby_.data(), nearby_.size());
            settle(INT64_MAX);
            return ranked_;
        }
        index_.forEachCellOfRing(p, ring, INT64_MAX, collect);
        if (index_.ringsCoverGrid(p, ring)) {
            settle(INT64_MAX);
            return ranked_;
        }
        if (candidates_.size() < settleFrom) continue;
        if (settle(index_.clearance2(p, ring))) return ranked_;
        settleFrom = 2 * candidates_.size();
    }
}

}  // namespace drm
