// Distance ranks among the vertices of the topological coder's front
// (topological_coder.h, symbol 4: an apex elsewhere on the front).
//
// The candidates are the front's vertices other than two skipped ones (the
// edge's fan ends) that are admissible, ordered by their squared distance
// to a point, then by id: keys are unique, so the order is strict and the
// encoder's rank names one vertex. Admissibility costs the caller edge
// look-ups, so it is asked only of vertices that come before the one
// wanted; distances are exact 64-bit integers (grid coordinates below
// 2^21, the point within 2^23 of them).
#ifndef DRM_FRONT_RANKS_H
#define DRM_FRONT_RANKS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "common.h"

namespace drm {

using RankKey = std::pair<int64_t, uint32_t>;  // (squared distance, id)

// The front: ids[k] at grid point (xs[k], ys[k], zs[k]), the coordinates
// as doubles (exact: below 2^21), one array an axis, so that distances are
// worked out several at once.
struct FrontView {
    const double* xs = nullptr;
    const double* ys = nullptr;
    const double* zs = nullptr;
    const uint32_t* ids = nullptr;
    size_t count = 0;
};

constexpr int64_t kAnyDistance = std::numeric_limits<int64_t>::max();

// Front vertices whose distances are worked out at once, before any is read.
constexpr size_t kFrontBlock = 64;

// Calls visit(key) for each front vertex but skipA and skipB whose squared
// distance to p is at most *within (which visit may lower as it goes), in
// front order: most vertices are passed over on their distance alone. The
// distances of a block of vertices are taken first, in doubles, which
// hold them exactly (differences below 2^23, their squares' sum below
// 2^48) and which a compiler takes two or more at a time.
template <class Visit>
void forEachFrontKey(const FrontView& front, const int64_t p[3], uint32_t skipA, uint32_t skipB, const int64_t* within,
                     Visit visit) {
    const double px = double(p[0]), py = double(p[1]), pz = double(p[2]);
    double d2s[kFrontBlock];
    for (size_t first = 0; first < front.count; first += kFrontBlock) {
        const size_t n = std::min(kFrontBlock, front.count - first);
        const double *xs = front.xs + first, *ys = front.ys + first, *zs = front.zs + first;
        for (size_t i = 0; i < n; ++i) {
            const double dx = xs[i] - px, dy = ys[i] - py, dz = zs[i] - pz;
            d2s[i] = dx * dx + dy * dy + dz * dz;
        }
        for (size_t i = 0; i < n; ++i) {
            const int64_t d2 = int64_t(d2s[i]);
            if (d2 > *within) continue;
            const uint32_t v = front.ids[first + i];
            if (v == skipA || v == skipB) continue;
            visit(RankKey(d2, v));
        }
    }
}

// The encoder's side: how many admissible candidates come before `apex`.
template <class Admissible>
uint32_t rankAmongFront(const FrontView& front, const int64_t p[3], uint32_t skipA, uint32_t skipB, RankKey apex,
                        Admissible admissible, std::vector<RankKey>& scratch) {
    scratch.clear();
    forEachFrontKey(front, p, skipA, skipB, &apex.first, [&](RankKey key) {
        if (key < apex) scratch.push_back(key);
    });
    uint32_t rank = 0;
    for (const RankKey& key : scratch) rank += admissible(key.second) ? 1 : 0;
    return rank;
}

// The decoder's side: the admissible candidate of the given rank (0: the
// nearest), or kNoVertex if there are not that many. One pass keeps the
// rank + 8 nearest (up to kNearestKept of them) in a small sorted array;
// where fewer than rank + 1 of those are admissible, or the rank is too
// large for the array, every candidate is listed, the admissible ones
// kept, and the rank's found by nth_element: linear in the front either
// way (the format bounds the front read in all, OtherSearchBound).
constexpr size_t kNearestKept = 64;
template <class Admissible>
uint32_t frontVertexOfRank(const FrontView& front, const int64_t p[3], uint32_t skipA, uint32_t skipB, uint32_t rank,
                           Admissible admissible, std::vector<RankKey>& scratch) {
    if (rank >= front.count) return kNoVertex;  // a corrupt rank costs nothing
    const size_t keep = size_t(rank) + 8;
    if (keep <= kNearestKept) {
        RankKey nearest[kNearestKept];
        size_t count = 0;
        int64_t within = kAnyDistance;  // once `keep` are kept: the farthest kept one's distance
        forEachFrontKey(front, p, skipA, skipB, &within, [&](RankKey key) {
            if (count == keep && !(key < nearest[keep - 1])) return;
            size_t at = count < keep ? count++ : keep - 1;
            for (; at > 0 && key < nearest[at - 1]; --at) nearest[at] = nearest[at - 1];
            nearest[at] = key;
            if (count == keep) within = nearest[keep - 1].first;
        });
        uint32_t seen = 0;
        for (size_t i = 0; i < count; ++i)
            if (admissible(nearest[i].second) && seen++ == rank) return nearest[i].second;
        if (count < keep) return kNoVertex;  // every candidate was kept and looked at
    }
    scratch.clear();
    const int64_t any = kAnyDistance;
    forEachFrontKey(front, p, skipA, skipB, &any, [&](RankKey key) {
        if (admissible(key.second)) scratch.push_back(key);
    });
    if (rank >= scratch.size()) return kNoVertex;
    std::nth_element(scratch.begin(), scratch.begin() + std::ptrdiff_t(rank), scratch.end());
    return scratch[rank].second;
}

}  // namespace drm

#endif  // DRM_FRONT_RANKS_H
