#include "connectivity/ranked/rank_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "drmcodec/drmcodec.h"
#include "spatial/spatial_index.h"

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

RankSearch::RankSearch(const std::vector<int32_t>& grid, const SpatialIndex& candidates,
                       const Admissibility& admissible)
    : grid_(grid), index_(candidates), admissible_(admissible) {}

int64_t RankSearch::distance2(const FixedPoint& p, uint32_t v) const { return fixedDistance2(grid_, p, v); }

namespace {

bool isListed(uint32_t v, const std::vector<RankedVertex>& listed) {
    for (const RankedVertex& l : listed)
        if (l.second == v) return true;
    return false;
}

}  // namespace

uint32_t RankSearch::rankOf(const FixedPoint& p, uint32_t apex, const OpenEdge& edge, uint32_t preferred,
                            const std::vector<RankedVertex>& listed) {
    if (apex == preferred) return 1;
    const int64_t apexDistance = distance2(p, apex);
    index_.collectNear(toGridUnits(p), std::sqrt(double(apexDistance)) / kSubUnits, nearby_);
    uint32_t closer = uint32_t(listed.size()) + (preferred == kNoVertex ? 0 : 1);
    for (uint32_t v : nearby_) {
        if (v == apex || v == preferred) continue;
        const int64_t d = distance2(p, v);
        if ((d < apexDistance || (d == apexDistance && v < apex)) && !isListed(v, listed) && admissible_(v, edge))
            ++closer;
    }
    return closer + 1;
}

uint32_t RankSearch::vertexOfRank(const FixedPoint& p, uint32_t rank, const OpenEdge& edge, uint32_t preferred,
                                  const std::vector<RankedVertex>& listed) {
    if (preferred != kNoVertex) {
        if (rank == 1) return preferred;
        --rank;
    }
    if (rank == 0) throw Error(ErrorKind::Corrupt, "rank 0 names no vertex (it codes a boundary edge)");
    if (rank <= listed.size())  // callers look the listed ranks up themselves
        throw Error(ErrorKind::Internal, "vertexOfRank asked for listed rank " + std::to_string(rank));
    rank -= uint32_t(listed.size());
    if (rank > index_.presentCount())
        throw Error(ErrorKind::Corrupt, "rank " + std::to_string(rank + listed.size()) + " is impossible: only " +
                    std::to_string(index_.presentCount()) + " candidate vertices remain");
    RankedVertex found;
    const size_t admissible = index_.nthNearest(
        p, rank, [&](uint32_t v) { return v != preferred && !isListed(v, listed) && admissible_(v, edge); }, found);
    if (admissible < rank)
        throw Error(ErrorKind::Corrupt, "rank " + std::to_string(rank + listed.size()) + " is impossible: only " +
                    std::to_string(admissible + listed.size()) + " admissible vertices remain for edge " +
                    std::to_string(edge.vi) + "-" + std::to_string(edge.vj));
    return found.second;
}

// The index finds them exactly (ties ordered by index), whichever it is.
const std::vector<RankedVertex>& RankSearch::nearest(const FixedPoint& p, size_t count, const OpenEdge& edge) {
    // Admissibility costs edge look-ups: the index asks it only of vertices
    // that would enter the answer.
    index_.nearest(p, count, [&](uint32_t v) { return admissible_(v, edge); }, ranked_);
    return ranked_;
}

}  // namespace drm
