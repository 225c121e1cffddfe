// Exact distance ranks (paper, Section 3.1).
//
// The predicted point is snapped to a fixed-point grid (1/16 of a
// quantization step) and distances are squared integers in 64 bits, so the
// order is the same on every machine; equal distances are ordered by vertex
// index. Rank 1 is the nearest admissible vertex, unless a vertex is
// `preferred` (gap closing): then it has rank 1 and the distance order
// follows from rank 2.
#ifndef DRM_RANK_SEARCH_H
#define DRM_RANK_SEARCH_H

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "connectivity/admissibility.h"
#include "exact_math.h"
#include "spatial/spatial_index.h"

namespace drm {

// The prediction on the fixed-point grid, clamped well outside the model's
// box so that squared distances cannot overflow.
FixedPoint snapPrediction(Vec3 prediction, int bits);

class RankSearch {
public:
    RankSearch(const std::vector<int32_t>& grid, const SpatialIndex& candidates,
               const Admissibility& admissible);

    // Ranks come in two parts: `listed` vertices first, in the caller's
    // order (the forecast's nearest candidates), then every other
    // admissible vertex by distance. With a `preferred` vertex (gap
    // closing) it alone is listed. The listed vertices need not be the
    // nearest ones: counts skip them, wherever they lie.

    // Encoder: the rank of apex (>= 1), apex not among `listed`.
    uint32_t rankOf(const FixedPoint& p, uint32_t apex, const OpenEdge& edge, uint32_t preferred = kNoVertex,
                    const std::vector<RankedVertex>& listed = {});

    // Decoder: the vertex of the given rank (> listed.size()). Throws Error
    // if there are fewer admissible vertices.
    uint32_t vertexOfRank(const FixedPoint& p, uint32_t rank, const OpenEdge& edge, uint32_t preferred = kNoVertex,
                          const std::vector<RankedVertex>& listed = {});

    // The `count` admissible vertices nearest p, nearest first; fewer if
    // fewer exist.
    const std::vector<RankedVertex>& nearest(const FixedPoint& p, size_t count, const OpenEdge& edge);
    // The same among the vertices some other search has found (the ball
    // the predictor searched, which holds most answers): calls
    // forEachCandidate(offer, bound), which calls offer(v, point) for each
    // (point: v's grid x, y, z), and may pass over vertices farther from p
    // than bound() says the answer needs (a squared fixed-point distance:
    // none farther can enter it).
    template <class ForEach>
    const std::vector<RankedVertex>& nearestAmong(const FixedPoint& p, size_t count, const OpenEdge& edge,
                                                  ForEach forEachCandidate) {
        ranked_.clear();
        if (count == 0) return ranked_;
        if (count > kFew) {
            auto bound = [&] { return ranked_.size() == count ? ranked_.back().first : INT64_MAX; };
            forEachCandidate([&](uint32_t v, const int32_t* point) {
                const RankedVertex c{fixedDistance2(point, p), v};
                if (ranked_.size() == count && !(c < ranked_.back())) return;
                if (!admissible_(v, edge)) return;  // edge look-ups: only for vertices that would enter
                // An insertion into a few, sorted: every candidate is offered
                // once, so no two keys are equal.
                size_t at = ranked_.size();
                if (at < count) ranked_.push_back(c);
                else --at;
                for (; at > 0 && c < ranked_[at - 1]; --at) ranked_[at] = ranked_[at - 1];
                ranked_[at] = c;
            }, bound);
            return ranked_;
        }
        // The usual case, a few: a fixed list padded with "farther than
        // any", into which a candidate is inserted without branches (where
        // it goes is as good as a coin toss).
        int64_t d2s[kFew];
        uint32_t vs[kFew];
        std::fill(d2s, d2s + kFew, INT64_MAX);
        std::fill(vs, vs + kFew, kNoVertex);
        const size_t last = count - 1;
        auto bound = [&] { return d2s[last]; };  // INT64_MAX until the list is full
        forEachCandidate([&](uint32_t v, const int32_t* point) {
            const int64_t d2 = fixedDistance2(point, p);
            if (!(d2 < d2s[last] || (d2 == d2s[last] && v < vs[last]))) return;
            if (!admissible_(v, edge)) return;  // edge look-ups: only for vertices that would enter
            for (size_t i = last; i > 0; --i) {
                const bool below = (d2 < d2s[i - 1]) | ((d2 == d2s[i - 1]) & (v < vs[i - 1]));
                const bool here = (d2 < d2s[i]) | ((d2 == d2s[i]) & (v < vs[i]));
                d2s[i] = below ? d2s[i - 1] : (here ? d2 : d2s[i]);
                vs[i] = below ? vs[i - 1] : (here ? v : vs[i]);
            }
            const bool first = (d2 < d2s[0]) | ((d2 == d2s[0]) & (v < vs[0]));
            d2s[0] = first ? d2 : d2s[0];
            vs[0] = first ? v : vs[0];
        }, bound);
        for (size_t i = 0; i < count && vs[i] != kNoVertex; ++i) ranked_.push_back({d2s[i], vs[i]});
        return ranked_;
    }

    int64_t distance2(const FixedPoint& p, uint32_t v) const;

private:
    static constexpr size_t kFew = 4;  // nearestAmong's lists up to this long need no heap
    const std::vector<int32_t>& grid_;
    const SpatialIndex& index_;
    const Admissibility& admissible_;
    std::vector<uint32_t> nearby_;
    std::vector<RankedVertex> ranked_;  // the answer
};

}  // namespace drm

#endif  // DRM_RANK_SEARCH_H
