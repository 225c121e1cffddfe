#include "edge_model.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gap_closing.h"
#include "quantize.h"

namespace drm {
namespace {

// Confidence of the distance order: the ratio of the two nearest candidate
// distances (method notes). A clear winner (small ratio) makes rank 1 far
// likelier than a near tie does. Large meshes have codes enough to teach six
// buckets; small ones learn faster with three (nefertiti, 562 faces: 1.66 bpv
// with three, 1.71 with six). Ratios are compared on squared distances in
// 128 bits, exactly: r < t  <=>  d1 * 10000 < d2 * (100 t)^2.
constexpr int kMaxConfidenceBuckets = 6;
constexpr uint64_t kFineBucketsFromFaces = 4096;
// Gap-closing edges get two contexts of their own: the gap vertex is, or is
// not, also the nearest candidate.
constexpr int kGapContext = kMaxConfidenceBuckets;
constexpr int kDistanceContexts = kGapContext + 2;
// With angle order, every distance context comes twice: the angle order's
// first candidate is, or is not, also the nearest one.
constexpr int kDisagreementOffset = kDistanceContexts;
// Four: 3 and 5 are within 1% of it; 2 and 6 lose 2-8% (paper models).
constexpr size_t kAngleOrdered = 4;

int confidenceBucket(const std::vector<RankedVertex>& nearest, bool fine) {
    static const int kFine[kMaxConfidenceBuckets - 1] = {400, 1600, 3600, 5625, 8100};  // 0.2 0.4 0.6 0.75 0.9
    static const int kCoarse[2] = {900, 5625};                                          // 0.3 0.75
    if (nearest.size() < 2) return 0;
    const __int128 d1 = nearest[0].first, d2 = nearest[1].first;
    const int* limits = fine ? kFine : kCoarse;
    const int count = fine ? kMaxConfidenceBuckets - 1 : 2;
    int bucket = 0;
    while (bucket < count && !(d1 * 10000 < d2 * limits[bucket])) ++bucket;
    return bucket;
}

// On regular meshes the distance order is usually right and the angle order
// would swap in the other diagonal of a stretched quad (torus: rank 1 drops
// from 100% to 77%); on irregular ones the angle order wins. So when the two
// disagree on rank 1, the model follows the one that was right more often on
// the last disagreements, which both sides see once the apex is known.
constexpr uint32_t kOrderMemory = 64;

// Cosine of the angle at v subtended by the edge (a, b); 1 (no angle) when v
// coincides with an end. Candidates behind the edge, on the side of the
// rebuilt triangle, get 4 added so that they follow every candidate ahead.
double cosineSubtended(Vec3 a, Vec3 b, Vec3 v) {
    const Vec3 u = a - v, w = b - v;
    const double uu = norm2(u), ww = norm2(w);
    return uu == 0 || ww == 0 ? 1.0 : dot(u, w) / std::sqrt(uu * ww);
}

}  // namespace

EdgeModel::EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature,
                     const Levers& levers, uint64_t faceCount, const SpatialIndex& candidates,
                     const Traversal& traversal, int formatVersion)
    : grid_(grid),
      bits_(bits),
      levers_(levers),
      fineBuckets_(faceCount >= kFineBucketsFromFaces),
      ballCandidates_(formatVersion >= 4),
      admissible_(traversal, levers.topologicalFilter),
      predictor_(predictor, curvature, grid, candidates, admissible_),
      ranks_(grid, candidates, admissible_) {}

int EdgeModel::contextCount() const { return levers_.confidenceContext ? 2 * kDistanceContexts : 1; }

const EdgeForecast& EdgeModel::forecast(const OpenEdge& edge) {
    EdgeForecast& f = forecast_;
    f.prediction = snapPrediction(predictor_.predict(edge), bits_);
    f.preferred = levers_.gapClosing ? gapClosingVertex(edge, grid_, admissible_) : kNoVertex;
    f.context = 0;
    f.nearest.clear();
    disagreement_ = Disagreement();  // only an edge where the orders disagree teaches resolved()
    if (f.preferred != kNoVertex) {
        if (levers_.confidenceContext) {
            const std::vector<RankedVertex>& first = nearestCandidates(f.prediction, 1, edge);
            f.context = kGapContext + (!first.empty() && first[0].second == f.preferred ? 0 : 1);
        }
        return f;
    }
    if (!levers_.confidenceContext && !levers_.angleOrder) return f;
    f.nearest = nearestCandidates(f.prediction, levers_.angleOrder ? kAngleOrdered : 2, edge);
    if (levers_.confidenceContext) f.context = confidenceBucket(f.nearest, fineBuckets_);
    if (levers_.angleOrder && f.nearest.size() >= 2) {
        const uint32_t nearestByDistance = f.nearest[0].second;
        std::vector<RankedVertex>& byAngle = byAngle_;
        byAngle = f.nearest;
        orderByAngle(edge, byAngle);
        if (byAngle[0].second != nearestByDistance) {
            // The two orders disagree on rank 1: follow the one that was
            // right more often on recent disagreements.
            disagreement_ = {nearestByDistance, byAngle[0].second};
            if (angleWins_ >= distanceWins_) f.nearest = byAngle;
            if (levers_.confidenceContext) f.context += kDisagreementOffset;
        } else {
            f.nearest = byAngle;
        }
    }
    return f;
}

const std::vector<RankedVertex>& EdgeModel::nearestCandidates(const FixedPoint& p, size_t count, const OpenEdge& edge) {
    if (ballCandidates_ && predictor_.searchedBall())
        return ranks_.nearestAmong(p, count, edge, [&](auto offer) { predictor_.forEachInBall(offer); });
    return ranks_.nearest(p, count, edge);
}

void EdgeModel::orderByAngle(const OpenEdge& edge, std::vector<RankedVertex>& nearest) const {
    const Vec3 a = gridPoint(grid_, edge.vi), b = gridPoint(grid_, edge.vj);
    const Vec3 mid = (a + b) * 0.5;
    const Vec3 towardRebuilt = rejectFrom(gridPoint(grid_, edge.opposite) - mid, b - a);
    std::pair<double, RankedVertex> keyed[kAngleOrdered];
    const size_t count = std::min(nearest.size(), kAngleOrdered);
    for (size_t k = 0; k < count; ++k) {
        const Vec3 v = gridPoint(grid_, nearest[k].second);
        const bool behind = dot(v - mid, towardRebuilt) > 0;
        keyed[k] = {cosineSubtended(a, b, v) + (behind ? 4.0 : 0.0), nearest[k]};
    }
    // Ahead before behind, then largest angle (smallest cosine) first; equal
    // keys keep distance order. An insertion sort, stable, of at most four:
    // std::stable_sort asked for a temporary buffer on every edge.
    for (size_t k = 1; k < count; ++k) {
        const std::pair<double, RankedVertex> moving = keyed[k];
        size_t at = k;
        for (; at > 0 && moving.first < keyed[at - 1].first; --at) keyed[at] = keyed[at - 1];
        keyed[at] = moving;
    }
    for (size_t k = 0; k < count; ++k) nearest[k] = keyed[k].second;
}

void EdgeModel::resolved(uint32_t apex) {
    if (disagreement_.byDistance == kNoVertex) return;
    if (apex == disagreement_.byAngle) ++angleWins_;
    else if (apex == disagreement_.byDistance) ++distanceWins_;
    // Halving keeps the choice local: it follows the mesh's regions.
    if (angleWins_ + distanceWins_ > kOrderMemory) {
        angleWins_ /= 2;
        distanceWins_ /= 2;
    }
}

// The nearest candidates, when the forecast holds them, take the first ranks
// in the forecast's order; every other vertex is ranked by distance after
// them.
uint32_t EdgeModel::rankOf(uint32_t apex, const OpenEdge& edge) {
    for (size_t k = 0; k < forecast_.nearest.size(); ++k)
        if (forecast_.nearest[k].second == apex) return uint32_t(k + 1);
    return ranks_.rankOf(forecast_.prediction, apex, edge, forecast_.preferred, forecast_.nearest);
}

uint32_t EdgeModel::vertexOfRank(uint32_t rank, const OpenEdge& edge) {
    if (rank >= 1 && rank <= forecast_.nearest.size()) return forecast_.nearest[rank - 1].second;
    return ranks_.vertexOfRank(forecast_.prediction, rank, edge, forecast_.preferred, forecast_.nearest);
}

}  // namespace drm
