// Everything encoder and decoder compute about one open edge before its rank
// is coded: the predicted apex, the gap-closing vertex, the coder context.
// Both sides call the same code, so they cannot drift apart; they differ only
// in turning apex -> rank (encoder) or rank -> apex (decoder).
#ifndef DRM_EDGE_MODEL_H
#define DRM_EDGE_MODEL_H

#include <vector>

#include "admissibility.h"
#include "drm/drm.h"
#include "predictor.h"
#include "rank_search.h"

namespace drm {

class SpatialIndex;

struct EdgeForecast {
    FixedPoint prediction;
    uint32_t preferred = kNoVertex;  // gap-closing vertex, rank 1 when present
    int context = 0;                     // coder context, < EdgeModel::contextCount()
    std::vector<RankedVertex> nearest;   // the nearest candidates, in rank order (confidence / angle levers)
};

class EdgeModel {
public:
    // faceCount sets how finely the coder contexts split (small meshes
    // cannot teach many contexts).
    // formatVersion: the file's (from 4 on, the nearest candidates come
    // from the predictor's ball; docs/format.md, "Format 4").
    EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature, const Levers& levers,
              uint64_t faceCount, const SpatialIndex& candidates, const Traversal& traversal,
              int formatVersion = kFileFormatVersion);

    // How many coder contexts forecasts use (for the rank coder).
    int contextCount() const;

    const EdgeForecast& forecast(const OpenEdge& edge);
    // Both use the forecast made last, for the same edge.
    uint32_t rankOf(uint32_t apex, const OpenEdge& edge);
    uint32_t vertexOfRank(uint32_t rank, const OpenEdge& edge);
    // Whether v may close edge (the encoder checks its true apex against the
    // rule the decoder will apply).
    bool admissible(uint32_t v, const OpenEdge& edge) const { return admissible_(v, edge); }
    // Tells the model the apex of the last forecast edge, once known, so it
    // can learn which candidate order serves this mesh.
    void resolved(uint32_t apex);

private:
    void orderByAngle(const OpenEdge& edge, std::vector<RankedVertex>& nearest) const;
    // The `count` admissible vertices nearest p: from the predictor's ball
    // (format 4), or from a search of their own.
    const std::vector<RankedVertex>& nearestCandidates(const FixedPoint& p, size_t count, const OpenEdge& edge);

    const std::vector<int32_t>& grid_;
    int bits_;
    Levers levers_;
    bool fineBuckets_;
    bool ballCandidates_;
    Admissibility admissible_;
    ApexPredictor predictor_;
    RankSearch ranks_;
    EdgeForecast forecast_;
    std::vector<RankedVertex> byAngle_;  // scratch: the nearest in angle order
    // Rank-1 disagreements between distance and angle order: who was right.
    struct Disagreement {
        uint32_t byDistance = kNoVertex, byAngle = kNoVertex;
    } disagreement_;
    uint32_t angleWins_ = 0, distanceWins_ = 0;
};

}  // namespace drm

#endif  // DRM_EDGE_MODEL_H
