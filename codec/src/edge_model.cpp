#include "edge_model.h"

#include "gap_closing.h"

namespace drm {
namespace {

// Confidence of the distance order: the ratio of the two nearest candidate
// distances, bucketed at 0.3, 0.6 and 0.85 (method notes). A clear winner
// (small ratio) makes rank 1 far likelier than a near tie does. Compared on
// squared distances in 128 bits: r < t  <=>  100 * d1 < (100 t)^2 / 100 * d2.
int confidenceBucket(const std::vector<RankedVertex>& nearest) {
    if (nearest.size() < 2) return 0;
    const __int128 d1 = nearest[0].first, d2 = nearest[1].first;
    if (d1 * 10000 < d2 * 900) return 0;   // ratio < 0.30
    if (d1 * 10000 < d2 * 3600) return 1;  // ratio < 0.60
    if (d1 * 10000 < d2 * 7225) return 2;  // ratio < 0.85
    return 3;
}
constexpr int kGapContext = 4;

}  // namespace

EdgeModel::EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature,
                     const Levers& levers, const VertexIndex& candidates, const Traversal& traversal)
    : grid_(grid),
      bits_(bits),
      levers_(levers),
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
            forecast_.context = kGapContext;
        } else {
            forecast_.nearest = ranks_.nearest(forecast_.prediction, 2, edge);
            forecast_.context = confidenceBucket(forecast_.nearest);
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
