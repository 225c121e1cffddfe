// Everything encoder and decoder compute about one open edge before its rank
// is coded: the predicted apex, the gap-closing vertex, the coder context.
// Both sides call the same code, so they cannot drift apart; they differ only
// in turning apex -> rank (encoder) or rank -> apex (decoder).
#ifndef DRM_EDGE_MODEL_H
#define DRM_EDGE_MODEL_H

#include <vector>

#include "connectivity/admissibility.h"
#include "connectivity/ranked/gap_closing.h"
#include "drmcodec/drmcodec.h"
#include "connectivity/ranked/predictor.h"
#include "connectivity/ranked/rank_search.h"

namespace drm {

class SpatialIndex;

struct EdgeForecast {
    FixedPoint prediction;
    uint32_t preferred = kNoVertex;  // gap-closing vertex, rank 1 when present (with the front lever: listed first in `nearest` instead)
    int context = 0;                     // coder context, < EdgeModel::contextCount()
    int boundaryClass = -1;              // the boundary flag's context, or -1 without the lever
    std::vector<RankedVertex> nearest;   // the listed candidates, in rank order (confidence / angle / front levers)
};

class EdgeModel {
public:
    // faceCount sets how finely the coder contexts split (small meshes
    // cannot teach many contexts).
    EdgeModel(const std::vector<int32_t>& grid, int bits, Predictor predictor, bool curvature, const Levers& levers,
              uint64_t faceCount, const SpatialIndex& candidates, const Traversal& traversal);
    // The predictor points at this model's seam side: not copied.
    EdgeModel(const EdgeModel&) = delete;
    EdgeModel& operator=(const EdgeModel&) = delete;

    // How many coder contexts forecasts use (for the rank coder).
    int contextCount() const;
    // Whether forecasts carry a boundary class, so that the rank coder
    // codes a boundary flag before each rank (the boundary lever).
    bool boundaryFlags() const { return boundaryLever_; }

    // The whole forecast: forecastBoundary, then forecastRank.
    const EdgeForecast& forecast(const OpenEdge& edge);
    // Its first half, all a boundary flag needs: the prediction and the
    // boundary class (context 0, nothing listed). The second half, for the
    // same edge, adds the listed candidates and the context. With boundary
    // flags a boundary edge's rank 0 is the flag alone, and nothing the
    // second half works out outlives the edge, so coders skip it there:
    // past the seam of two parts the nearest admissible vertex can lie far
    // away (such searches would take about 5 % of igea's decoding).
    const EdgeForecast& forecastBoundary(const OpenEdge& edge);
    const EdgeForecast& forecastRank(const OpenEdge& edge);
    // Both use the forecast made last, for the same edge.
    uint32_t rankOf(uint32_t apex, const OpenEdge& edge);
    uint32_t vertexOfRank(uint32_t rank, const OpenEdge& edge);
    // Whether v may close edge (the encoder checks its true apex against the
    // rule the decoder will apply).
    bool admissible(uint32_t v, const OpenEdge& edge) const { return admissible_(v, edge); }
    // Two parts: this model ranks the first of two connectivity parts,
    // whose second part holds the faces over vertices from `first` on
    // (connectivity_parts.h). Before the first forecast.
    void setSeam(uint32_t first) {
        admissible_.setSeam(first);
        seamSide_.seam = first;
        predictor_.searchFirstBallOnlyOn(&seamSide_);
    }
    // Two parts: this model ranks the second part, whose first vertex has
    // Morton key `key`: an edge whose prediction lies at a grid point of
    // smaller key points into the first part's region, across the seam
    // (its boundary flag then has a class of its own). Before the first
    // forecast.
    void setFirstPartBelowKey(uint64_t key) {
        seamSide_.firstPartBelow = key;
        seamSide_.secondPart = true;
        predictor_.searchFirstBallOnlyOn(&seamSide_);
    }
    // Tells the model the apex of the last forecast edge, once known, so it
    // can learn which candidate order serves this mesh. After rankOf or
    // vertexOfRank of that edge (the rank they gave is part of the lesson).
    void resolved(uint32_t apex);

    // The front-neighbour lever: the ranks the apex of the last
    // resolved edge had in the order without front neighbours (`plain`) and
    // in the order with them (`front`), and whether that edge was ranked in
    // the front order. Equal when the edge had no front neighbour to add,
    // or when its apex had rank 1. plainListed: how many vertices the plain
    // order listed ahead of the distance order (for tests).
    struct OrderLesson {
        uint32_t plain = 0, front = 0;
        bool frontUsed = false;
        uint32_t plainListed = 0;
    };
    const OrderLesson& lastLesson() const { return lesson_; }

private:
    void orderByAngle(const OpenEdge& edge, std::vector<RankedVertex>& nearest) const;
    // The `count` admissible vertices nearest p: from the predictor's last
    // ball when it searched one, or from a search of their own.
    const std::vector<RankedVertex>& nearestCandidates(const FixedPoint& p, size_t count, const OpenEdge& edge);
    // Front neighbours: the front order's list for the forecast edge, and
    // which list ranks it; learnOrder keeps score after the apex is known.
    void forecastFrontOrder(const OpenEdge& edge, const FanEnds& ends);
    void learnOrder(uint32_t apex, const OpenEdge& edge);
    void findExtras();

    const std::vector<int32_t>& grid_;
    int bits_;
    Levers levers_;
    bool fineBuckets_;
    Admissibility admissible_;
    ApexPredictor predictor_;
    RankSearch ranks_;
    EdgeForecast forecast_;
    FanEnds forecastEnds_;  // forecastBoundary's, for forecastRank
    std::vector<RankedVertex> byAngle_;  // scratch: the nearest in angle order
    // Rank-1 disagreements between distance and angle order: who was right.
    struct Disagreement {
        uint32_t byDistance = kNoVertex, byAngle = kNoVertex;
    } disagreement_;
    uint32_t angleWins_ = 0, distanceWins_ = 0;

    // The front neighbours lever (Levers::frontNeighbours).
    bool frontLever_;
    // The boundary flag lever (Levers::boundaryFlag).
    bool boundaryLever_;
    // The two connectivity parts: the seam's side, for the boundary flag's
    // class and the size step; the predictor points at it.
    SeamSide seamSide_;
    // The forecast's list (nearest) holds the order used: the plain one,
    // or the front order (its first, extra_, the rest); otherOrder_ then
    // holds the plain one.
    RankedVertex extra_[2];                  // front neighbours not in the plain order, by distance
    size_t extraCount_ = 0;
    uint32_t plainListed_ = 0;
    bool extrasKnown_ = false;               // extra_ found for this edge (only when needed)
    FanEnds ends_;
    std::vector<RankedVertex> otherOrder_;
    bool useFront_ = false;                  // this edge is ranked in the front order
    OpenEdge edge_;                          // the forecast edge
    uint32_t lastRank_ = 0;                 // what rankOf / vertexOfRank gave for the forecast edge
    // Decayed sum of (plain order's cost - front order's cost) over the
    // edges where the two differ, in 1/16 bits: the front order ranks the
    // next edge while it is above zero.
    int64_t frontAdvantage_ = 0;
    OrderLesson lesson_;
};

}  // namespace drm

#endif  // DRM_EDGE_MODEL_H
