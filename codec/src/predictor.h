// Apex prediction (paper, Section 3.2): where the vertex closing the triangle
// across an open edge is expected to be.
//
// A base predictor (parallelogram or midpoint) uses the triangle already
// rebuilt on the edge; two corrections then use the whole vertex set, which
// both sides know before any connectivity is decoded: curvature (bend the
// prediction onto the plane through the edge and the centroid of the nearby
// vertices) and size (scale it to the first vertex ahead of the edge).
#ifndef DRM_PREDICTOR_H
#define DRM_PREDICTOR_H

#include <vector>

#include "drm/drm.h"
#include "exact_math.h"
#include "admissibility.h"
#include "traversal.h"

namespace drm {

class SpatialIndex;

// The base predictors alone, from the edge (a, b) and the opposite vertex o
// of the rebuilt triangle (a, b, o). Grid units.
Vec3 parallelogramApex(Vec3 a, Vec3 b, Vec3 o);
Vec3 midpointApex(Vec3 a, Vec3 b, Vec3 o);
Vec3 baseApex(Predictor kind, Vec3 a, Vec3 b, Vec3 o);

struct PredictorTuning {
    // The slab ahead of the edge that the size correction searches extends
    // this many edge lengths beyond each end of the edge: apexes of right
    // and obtuse triangles sit just outside the edge's own span. 0.75
    // measured best with all levers on (0.5 and 1.0 lose 2-7% on the paper's
    // irregular models; fandisk prefers 0.5 by 1%).
    double slabWidening = 0.75;
    // Curvature: at most this many vertices, within this many edge lengths.
    int curvatureNeighbours = 10;
    double curvatureRadius = 4.0;
};

class ApexPredictor {
public:
    ApexPredictor(Predictor kind, bool curvature, const std::vector<int32_t>& grid, const SpatialIndex& candidates,
                  const Admissibility& admissible, PredictorTuning tuning = PredictorTuning());

    // The predicted apex of the triangle across edge, in grid units.
    Vec3 predict(const OpenEdge& edge);

    // Whether the last predict() searched a ball for the first vertex
    // ahead (not when the edge or the prediction's height is zero), and
    // then calls visit(v, point) for every present vertex in that ball,
    // admissible or not (point: its grid x, y, z). Until the index next
    // changes (a culled vertex removed).
    bool searchedBall() const { return searchedBall_; }
    template <class Visit>
    void forEachInBall(Visit visit) const {
        for (size_t i = 0; i < inBallCount_; ++i) visit(inBall_[i].id, inBall_[i].point);
    }
    // Which of the last predict()'s balls held the first vertex ahead (0:
    // the first; 1 to 3: one of the wider ones), or -1 if none did or none
    // was searched. The boundary flag's context (format 10).
    int firstAheadAttempt() const { return firstAheadAttempt_; }

private:
    Vec3 bendOntoSurface(Vec3 prediction, Vec3 a, Vec3 b, const OpenEdge& edge);
    Vec3 scaleToFirstVertexAhead(Vec3 prediction, Vec3 a, Vec3 b, const OpenEdge& edge);

    Predictor kind_;
    bool curvature_;
    const std::vector<int32_t>& grid_;
    const SpatialIndex& candidates_;
    const Admissibility& usable_;
    PredictorTuning tuning_;
    std::vector<uint32_t> nearby_;  // scratch, reused by every query
    bool searchedBall_ = false;
    int firstAheadAttempt_ = -1;
    // The last search's vertices within its ball, their coordinates where
    // the index keeps them.
    struct BallVertex {
        uint32_t id;
        const int32_t* point;
    };
    std::vector<BallVertex> inBall_;  // the first inBallCount_ entries; the rest is room
    size_t inBallCount_ = 0;
};

}  // namespace drm

#endif  // DRM_PREDICTOR_H
