#include "connectivity/ranked/edge_model.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "container/file_format.h"
#include "connectivity/ranked/gap_closing.h"
#include "mesh/quantize.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

// Confidence of the distance order: the ratio of the two nearest candidate
// distances (method notes). A clear winner (small ratio) makes rank 1 far
// likelier than a near tie does. Large meshes have codes enough to teach six
// buckets; small ones learn faster with three (docs/tuning.md). Ratios are
// compared on squared distances in 128 bits, exactly:
// r < t  <=>  d1 * 10000 < d2 * (100 t)^2.
constexpr int kMaxConfidenceBuckets = 6;
constexpr uint64_t kFineBucketsFromFaces = 4096;
// Gap-closing edges get two contexts of their own: the gap vertex is, or is
// not, also the nearest candidate.
constexpr int kGapContext = kMaxConfidenceBuckets;
constexpr int kDistanceContexts = kGapContext + 2;
// With angle order, every distance context comes twice: the angle order's
// first candidate is, or is not, also the nearest one.
constexpr int kDisagreementOffset = kDistanceContexts;
// The angle order sorts the four nearest candidates: the best count on the
// paper's models (docs/tuning.md).
constexpr size_t kAngleOrdered = 4;
// Edges ranked in the front order (front neighbours after rank 1) have a
// context set of their own: rank 2 is likelier there.
constexpr int kFrontOffset = 2 * kDistanceContexts;

// The front order's score forgets 1/256 of itself on each edge where the
// two orders would have cost different bits (a half-life of about 177 such
// edges): it follows a mesh's regions (octopus) without flapping on smooth
// meshes (docs/tuning.md). Forgetting only on those edges spares the front
// neighbours of the rank-1 ones, which a decoder never needs.
constexpr int kFrontMemoryShift = 8;

// log2(rank) in 1/16 bits, the fraction read linearly from the four bits
// after the leading one.
int64_t log2Sixteenths(uint32_t rank) {
    const int n = bitLength(rank) - 1;
    const uint64_t scaled = (uint64_t(rank) << 4) >> n;  // 16 .. 31
    return 16 * n + int64_t(scaled - 16);
}

// What a rank costs, roughly, in 1/16 bits: log2(rank), so rank 1 costs
// nothing and every doubling one bit. Fractions of a bit, not whole bit
// lengths, keep the score steady on small meshes.
int64_t rankCost(uint32_t rank) { return log2Sixteenths(rank); }

// The first of `count` limits with d1 * 10000 < d2 * limit, or count, in
// the integer type Wide.
template <class Wide>
int firstLimitAbove(Wide d1, Wide d2, const int* limits, int count) {
    int bucket = 0;
    while (bucket < count && !(d1 * 10000 < d2 * limits[bucket])) ++bucket;
    return bucket;
}

// Distances below 2^49 (the two nearest candidates within 2^20 grid steps
// of the prediction, as on nearly every edge) keep the products below 2^63
// (d1 <= d2, factors up to 10000 < 2^14), so 64 bits answer exactly as 128
// do; a WebAssembly build multiplies 128-bit integers through a call.
constexpr int64_t kConfidenceIn64Below = int64_t(1) << 49;

int confidenceBucket(const std::vector<RankedVertex>& nearest, bool fine) {
    static const int kFine[kMaxConfidenceBuckets - 1] = {400, 1600, 3600, 5625, 8100};  // 0.2 0.4 0.6 0.75 0.9
    static const int kCoarse[2] = {900, 5625};                                          // 0.3 0.75
    if (nearest.size() < 2) return 0;
    const int64_t d1 = nearest[0].first, d2 = nearest[1].first;
    const int* limits = fine ? kFine : kCoarse;
    const int count = fine ? kMaxConfidenceBuckets - 1 : 2;
    if (d2 < kConfidenceIn64Below) return firstLimitAbove<int64_t>(d1, d2, limits, count);
    return firstLimitAbove<__int128>(d1, d2, limits, count);
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

// The boundary flag's context class (0 .. 8; the two connectivity parts
// add the seam's, below): where the size step found the first vertex
// ahead of the edge (in its first ball, in a wider one, or nowhere: past
// an open border there is nothing ahead), and how many of the fans at the
// edge's ends already end on a coded boundary (0, 1 or 2: a border is
// coded edge after edge). On mountain, a terrain with one border, 634 of
// the 636 boundary edges have no vertex ahead, against 23 of its 50,561
// other edges.
int boundaryClass(int firstAheadAttempt, const FanEnds& ends) {
    const int ahead = firstAheadAttempt == 0 ? 0 : firstAheadAttempt > 0 ? 1 : 2;
    return 3 * ahead + int(ends.boundaryAtI) + int(ends.boundaryAtJ);
}
// The two connectivity parts (connectivity_parts.h): edges on the seam's
// side take classes of their own, by the fans' ends as above. Most of them
// are coded as boundary edges, the seam, in both parts (about 1.4 % of
// bunny's flags).
constexpr int kSeamBoundaryClass = 9;
static_assert(kSeamBoundaryClass + 3 == kBoundaryClasses, "three seam classes");

}  // namespace

EdgeModel::EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature,
                     const Levers& levers, uint64_t faceCount, const SpatialIndex& candidates,
                     const Traversal& traversal)
    : grid_(grid),
      bits_(bits),
      levers_(levers),
      fineBuckets_(faceCount >= kFineBucketsFromFaces),
      admissible_(traversal, levers.topologicalFilter),
      predictor_(predictor, curvature, grid, candidates, admissible_),
      ranks_(grid, candidates, admissible_),
      frontLever_(levers.frontNeighbours),
      boundaryLever_(levers.boundaryFlag) {
    seamSide_.bits = bits;
}


int EdgeModel::contextCount() const {
    if (!levers_.confidenceContext) return 1;
    return (frontLever_ ? 4 : 2) * kDistanceContexts;
}

const EdgeForecast& EdgeModel::forecast(const OpenEdge& edge) {
    forecastBoundary(edge);
    return forecastRank(edge);
}

const EdgeForecast& EdgeModel::forecastBoundary(const OpenEdge& edge) {
    EdgeForecast& f = forecast_;
    f.prediction = snapPrediction(predictor_.predict(edge), bits_);
    FanEnds& ends = forecastEnds_;
    ends = FanEnds();
    if (levers_.gapClosing || frontLever_ || boundaryLever_) ends = fanEnds(edge, admissible_.traversal());
    f.boundaryClass = boundaryLever_ ? boundaryClass(predictor_.firstAheadAttempt(), ends) : -1;
    if (boundaryLever_ && seamSide_.contains(edge, f.prediction))
        f.boundaryClass = kSeamBoundaryClass + int(ends.boundaryAtI) + int(ends.boundaryAtJ);
    f.preferred = kNoVertex;
    f.context = 0;
    f.nearest.clear();
    disagreement_ = Disagreement();  // only an edge where the orders disagree teaches resolved()
    return f;
}

const EdgeForecast& EdgeModel::forecastRank(const OpenEdge& edge) {
    EdgeForecast& f = forecast_;
    const FanEnds& ends = forecastEnds_;
    f.preferred = levers_.gapClosing ? gapClosingVertex(edge, ends, grid_, admissible_) : kNoVertex;
    if (f.preferred != kNoVertex) {
        if (levers_.confidenceContext) {
            const std::vector<RankedVertex>& first = nearestCandidates(f.prediction, 1, edge);
            f.context = kGapContext + (!first.empty() && first[0].second == f.preferred ? 0 : 1);
        }
        if (frontLever_) forecastFrontOrder(edge, ends);
        return f;
    }
    if (!levers_.confidenceContext && !levers_.angleOrder) {
        if (frontLever_) forecastFrontOrder(edge, ends);
        return f;
    }
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
    if (frontLever_) forecastFrontOrder(edge, ends);
    return f;
}

// Front neighbours. The plain order is the one above: the gap-closing
// vertex alone, or the nearest candidates (angle or distance order), or
// with neither lever the nearest candidate alone (listing it changes no
// rank). The front order puts the front neighbours that are not listed yet
// right after the plain order's first, nearer to the prediction first.
// Either way every other vertex follows by distance.
void EdgeModel::forecastFrontOrder(const OpenEdge& edge, const FanEnds& ends) {
    EdgeForecast& f = forecast_;
    edge_ = edge;
    lastRank_ = 0;
    // The plain order as a list in f.nearest (the same ranks).
    if (f.preferred != kNoVertex) {
        f.nearest.push_back({0, f.preferred});  // empty until now
        f.preferred = kNoVertex;
    } else if (f.nearest.empty()) {
        f.nearest = ranks_.nearest(f.prediction, 1, edge);  // the levers listed none, or the ball held none
    }
    ends_ = ends;
    extraCount_ = 0;
    extrasKnown_ = false;
    plainListed_ = uint32_t(f.nearest.size());
    // The plain order until the front order has lately served better.
    if (frontAdvantage_ <= 0) {
        useFront_ = false;
        return;  // the front neighbours are looked at only if the apex is not rank 1 (learnOrder)
    }
    findExtras();
    useFront_ = extraCount_ > 0;
    if (!useFront_) return;
    otherOrder_.clear();
    otherOrder_.push_back(f.nearest[0]);
    otherOrder_.insert(otherOrder_.end(), extra_, extra_ + extraCount_);
    otherOrder_.insert(otherOrder_.end(), f.nearest.begin() + 1, f.nearest.end());
    std::swap(f.nearest, otherOrder_);  // otherOrder_: the plain order, for learnOrder
    if (levers_.confidenceContext) f.context += kFrontOffset;
}

// The front neighbours that the plain order does not list, admissible,
// nearer to the prediction first.
void EdgeModel::findExtras() {
    extrasKnown_ = true;
    extraCount_ = 0;
    for (uint32_t v : {ends_.atI, ends_.atJ}) {
        if (v == kNoVertex || (extraCount_ == 1 && extra_[0].second == v)) continue;
        bool listed = false;
        for (const RankedVertex& l : forecast_.nearest) listed = listed || l.second == v;
        if (listed || !admissible_(v, edge_)) continue;
        const RankedVertex c{ranks_.distance2(forecast_.prediction, v), v};
        if (extraCount_ == 1 && c < extra_[0]) {
            extra_[1] = extra_[0];
            extra_[0] = c;
        } else {
            extra_[extraCount_] = c;
        }
        ++extraCount_;
    }
}

// Front neighbours: the apex's rank in the order not used, from the one
// used (no new search but in one case), and the score of the two orders.
void EdgeModel::learnOrder(uint32_t apex, const OpenEdge& edge) {
    const uint32_t used = lastRank_;
    lesson_ = {used, used, useFront_, plainListed_};
    // Rank 1 is the same vertex in both orders: nothing to learn.
    if (used <= 1) return;
    if (!extrasKnown_) findExtras();
    if (extraCount_ == 0) return;
    const std::vector<RankedVertex>& plainOrder = useFront_ ? otherOrder_ : forecast_.nearest;
    const uint32_t extras = uint32_t(extraCount_);
    uint32_t plain = 0, front = 0;
    uint32_t listedAt = 0;
    for (size_t k = 0; k < plainOrder.size() && listedAt == 0; ++k)
        if (plainOrder[k].second == apex) listedAt = uint32_t(k + 1);
    if (listedAt != 0) {
        plain = listedAt;
        front = listedAt == 1 ? 1 : listedAt + extras;
    } else if (apex == extra_[0].second || (extras == 2 && apex == extra_[1].second)) {
        front = apex == extra_[0].second ? 2 : 3;
        // Ranked in the plain order, the apex's rank is known; else it takes
        // a count of the vertices nearer than it.
        plain = useFront_ ? ranks_.rankOf(forecast_.prediction, apex, edge, kNoVertex, plainOrder) : used;
    } else {
        // Beyond both lists the two orders differ by the extra vertices
        // listed in one and counted by distance in the other.
        const RankedVertex a{ranks_.distance2(forecast_.prediction, apex), apex};
        uint32_t nearer = 0;
        for (size_t x = 0; x < extraCount_; ++x) nearer += extra_[x] < a ? 1 : 0;
        const uint32_t shift = extras - nearer;
        if (useFront_) {
            front = used;
            plain = used - shift;
        } else {
            plain = used;
            front = used + shift;
        }
    }
    lesson_ = {plain, front, useFront_, plainListed_};
    const int64_t gain = rankCost(plain) - rankCost(front);
    if (gain == 0) return;
    // Division rounds toward zero: the same on every machine, either sign.
    frontAdvantage_ += gain - frontAdvantage_ / (int64_t(1) << kFrontMemoryShift);
}

const std::vector<RankedVertex>& EdgeModel::nearestCandidates(const FixedPoint& p, size_t count, const OpenEdge& edge) {
    if (predictor_.searchedBall())
        return ranks_.nearestAmong(p, count, edge,
                                   [&](auto offer, auto bound) { predictor_.forEachInBall(p, bound, offer); });
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
    // std::stable_sort would ask for a temporary buffer on every edge.
    for (size_t k = 1; k < count; ++k) {
        const std::pair<double, RankedVertex> moving = keyed[k];
        size_t at = k;
        for (; at > 0 && moving.first < keyed[at - 1].first; --at) keyed[at] = keyed[at - 1];
        keyed[at] = moving;
    }
    for (size_t k = 0; k < count; ++k) nearest[k] = keyed[k].second;
}

void EdgeModel::resolved(uint32_t apex) {
    if (frontLever_) learnOrder(apex, edge_);
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
        if (forecast_.nearest[k].second == apex) return lastRank_ = uint32_t(k + 1);
    return lastRank_ = ranks_.rankOf(forecast_.prediction, apex, edge, forecast_.preferred, forecast_.nearest);
}

uint32_t EdgeModel::vertexOfRank(uint32_t rank, const OpenEdge& edge) {
    lastRank_ = rank;
    if (rank >= 1 && rank <= forecast_.nearest.size()) return forecast_.nearest[rank - 1].second;
    return ranks_.vertexOfRank(forecast_.prediction, rank, edge, forecast_.preferred, forecast_.nearest);
}

}  // namespace drm
