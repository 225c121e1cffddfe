#include "edge_model.h"

#include "gap_closing.h"

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
constexpr int kGapContext = kMaxConfidenceBuckets;  // and kGapContext + 1

}  // namespace

int EdgeModel::contextCount() const { return levers_.confidenceContext ? kGapContext + 2 : 1; }

EdgeModel::EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature,
                     const Levers& levers, uint64_t faceCount, const VertexIndex& candidates,
                     const Traversal& traversal)
    : grid_(grid),
      bits_(bits),
      levers_(levers),
      fineBuckets_(faceCount >= kFineBucketsFromFaces),
      admissible_(traversal, levers.topologicalFilter),
      predictor_(predictor, curvature, grid, candidates, admissible_),
      ranks_(grid, bits, candidates, admissible_) {}

const EdgeForecast& EdgeModel::forecast(const OpenEdge& edge) {
    forecast_.prediction = snapPrediction(predictor_.predict(edge), bits_);
    forecast_.preferred = levers_.gapClosing ? gapClosingVertex(edge, grid_, admissible_) : kNoPreference;
    forecast_.context = 0;
    forecast_.nearest.clear();
    if (levers_.confidenceContext) {
        if (forecast_.preferred != kNoPreference) {
            // Whether the gap vertex is also the nearest candidate says how
            // sure the gap closing is.
            const std::vector<RankedVertex>& first = ranks_.nearest(forecast_.prediction, 1, edge);
            forecast_.context = kGapContext + (!first.empty() && first[0].second == forecast_.preferred ? 0 : 1);
        } else {
            forecast_.nearest = ranks_.nearest(forecast_.prediction, 2, edge);
            forecast_.context = confidenceBucket(forecast_.nearest, fineBuckets_);
        }
    }
    return forecast_;
}

uint32_t EdgeModel::rankOf(uint32_t apex, const OpenEdge& edge) {
    // The two nearest are known already when the context needed them.
    for (size_t k = 0; k < forecast_.nearest.size(); ++k)
        if (forecast_.nearest[k].second == apex) return uint32_t(k + 1);
    return ranks_.rankOf(forecast_.prediction, apex, edge, forecast_.preferred);
}

uint32_t EdgeModel::vertexOfRank(uint32_t rank, const OpenEdge& edge) {
    if (rank >= 1 && rank <= forecast_.nearest.size()) return forecast_.nearest[rank - 1].second;
    return ranks_.vertexOfRank(forecast_.prediction, rank, edge, forecast_.preferred);
}

}  // namespace drm
