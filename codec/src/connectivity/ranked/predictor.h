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

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "exact_math.h"
#include "connectivity/admissibility.h"
#include "connectivity/seam_side.h"
#include "spatial/spatial_index.h"
#include "connectivity/traversal.h"

namespace drm {

// The base predictors alone, from the edge (a, b) and the opposite vertex o
// of the rebuilt triangle (a, b, o). Grid units.
Vec3 parallelogramApex(Vec3 a, Vec3 b, Vec3 o);
Vec3 midpointApex(Vec3 a, Vec3 b, Vec3 o);
Vec3 baseApex(Predictor kind, Vec3 a, Vec3 b, Vec3 o);

struct PredictorTuning {
    // The slab ahead of the edge that the size correction searches extends
    // this many edge lengths beyond each end of the edge: apexes of right
    // and obtuse triangles sit just outside the edge's own span. 0.75 is
    // the best with all levers on (docs/tuning.md).
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
    // ahead (not when the edge or the prediction's height is zero).
    bool searchedBall() const { return searchedBall_; }
    // Then calls visit(v, point) for present vertices in that ball,
    // admissible or not (point: its grid x, y, z), until the index next
    // changes (a culled vertex removed): every one, unless bound() says
    // some need not be. The listed vertices come first (most balls are
    // listed whole), then the runs kept beyond them: the one nearest p,
    // then the others in turn, each passed over if its nearest point lies
    // farther from p than bound() (a squared fixed-point distance, asked
    // before each run) says the caller needs. A wide ball (searched
    // through the index's hierarchy) is searched there again, as the index
    // stands, nearest boxes first, passing over those beyond bound().
    template <class Visit, class Bound>
    void forEachInBall(const FixedPoint& p, Bound bound, Visit visit) const;
    // Which of the last predict()'s balls held the first vertex ahead (0:
    // the first; 1 to 3: one of the wider ones), or -1 if none did or none
    // was searched. The boundary flag's context.
    int firstAheadAttempt() const { return firstAheadAttempt_; }
    // Two connectivity parts (connectivity_parts.h): on the
    // seam's side, where the first ball holds no vertex ahead, the wider
    // balls are not searched and the prediction stays as it is. Across the
    // seam they find no vertex the part may take, or a far one, at the cost
    // of balls of up to 8 times the first's radius (bunny's decoding in two
    // parts takes about 4 % fewer instructions so: docs/tuning.md).
    // The seam's side is `side`'s (EdgeModel's seam classes), tested on
    // the prediction before the size step (the same point when the rule
    // stops it), with or without boundary flags; `side` must outlive the
    // predictor's use (null: every ball is searched).
    void searchFirstBallOnlyOn(const SeamSide* side) { firstBallOnly_ = side; }

private:
    // A run of vertices the index handed over: their coordinates where the
    // index keeps them, and a box around them.
    struct Run {
        const uint32_t* ids;
        const int32_t* points;
        const int32_t* box;  // lowest x, y, z, then highest
        size_t count;
    };
    Vec3 bendOntoSurface(Vec3 prediction, Vec3 a, Vec3 b, const OpenEdge& edge);
    Vec3 scaleToFirstVertexAhead(Vec3 prediction, Vec3 a, Vec3 b, const OpenEdge& edge);
    // The slab ahead of an edge: its midpoint, the edge (b - a), the unit
    // direction ahead, the edge's length, how far along the edge the slab
    // reaches either side of the midpoint, and the unit edge (for bounds
    // over boxes; a vertex's place along the edge is dot(x, e) / edgeLength).
    struct Slab {
        Vec3 mid, e, ahead;
        double edgeLength, halfWidth;
        Vec3 along;
    };
    struct FirstAhead {
        double height = std::numeric_limits<double>::infinity();
        uint32_t vertex = kNoIndex;
    };
    void gather(const uint32_t* ids, const int32_t* points, size_t count);
    void offerAhead(const Slab& slab, uint32_t v, const int32_t* point, bool inBall, const OpenEdge& edge,
                    FirstAhead& best) const;
    FirstAhead firstAheadInBall(const Slab& slab, const OpenEdge& edge) const;
    FirstAhead firstAheadByRuns(const Slab& slab, const OpenEdge& edge) const;
    FirstAhead firstAheadInOrder(const Slab& slab, const OpenEdge& edge) const;
    // A bound below the height of any vertex of box in the slab, or
    // +infinity if none of them can be in it.
    static double lowestAhead(const Slab& slab, const int32_t* box);

    Predictor kind_;
    bool curvature_;
    const std::vector<int32_t>& grid_;
    const SpatialIndex& candidates_;
    const Admissibility& usable_;
    PredictorTuning tuning_;
    std::vector<uint32_t> nearby_;  // scratch, reused by every query
    bool searchedBall_ = false;
    int firstAheadAttempt_ = -1;
    const SeamSide* firstBallOnly_ = nullptr;  // searchFirstBallOnlyOn's
    // The last search's ball: its vertices in the runs the index handed
    // over first, listed (the first inBallCount_ entries of inBall_; the
    // rest is room), until the runs held more than kListUpToPoints
    // vertices; the later runs as they are (runs_), searched run by run,
    // passing over runs that cannot hold an answer. Most balls are listed
    // whole (runs_ empty). The limit trades scans (listing is cheapest) for
    // CAD meshes' wide balls (docs/tuning.md).
    struct BallVertex {
        uint32_t id;
        const int32_t* point;
    };
    std::vector<BallVertex> inBall_;
    size_t inBallCount_ = 0;
    std::vector<Run> runs_;
    static constexpr size_t kListUpToPoints = 64;
    Vec3 ballCentre_;
    double ballRadius_ = 0, ballRadius2_ = 0;
    // The last ball was searched through the index's hierarchy
    // (SpatialIndex::forEachNearInOrder), and nothing of it is listed.
    bool wideBall_ = false;
    // Balls wider than this go to the hierarchy (SpatialIndex::
    // wideBallRadius; -1 until asked), once more than kWideBallsBefore of
    // them were searched: the index builds its hierarchy on first use, which
    // a mesh with a handful of wide balls (a scan: bunny has 2) would not
    // repay.
    double wideBallRadius_ = -1;
    uint64_t wideBallsSearched_ = 0;
    static constexpr uint64_t kWideBallsBefore = 64;
    // Scratch: runs by how near they may come (a height or a distance).
    mutable std::vector<std::pair<double, uint32_t>> byHeight_;
    mutable std::vector<std::pair<int64_t, uint32_t>> byDistance_;
};

// The squared fixed-point distance from p to the nearest point of box
// (grid units: lowest x, y, z, then highest), exactly.
inline int64_t boxDistance2(const FixedPoint& p, const int32_t* box) {
    int64_t d2 = 0;
    for (int k = 0; k < 3; ++k) {
        const int64_t c = k == 0 ? p.x : k == 1 ? p.y : p.z;
        const int64_t lo = int64_t(box[k]) * kSubUnits, hi = int64_t(box[3 + k]) * kSubUnits;
        const int64_t gap = std::max<int64_t>(lo - c, 0) + std::max<int64_t>(c - hi, 0);
        d2 += gap * gap;
    }
    return d2;
}

template <class Visit, class Bound>
void ApexPredictor::forEachInBall(const FixedPoint& p, Bound bound, Visit visit) const {
    if (wideBall_) {
        // The index's hierarchy again, nearest boxes first, passing over
        // those beyond the bound.
        candidates_.forEachNearInOrder(
            ballCentre_, ballRadius_, [&](const int32_t* box) { return double(boxDistance2(p, box)); },
            // Rounding to double is monotonic, so a box passed over lies
            // beyond the bound in integers too.
            [&] { return double(bound()); },
            [&](const uint32_t* ids, const int32_t* at, size_t count, const int32_t*) {
                for (size_t i = 0; i < count; ++i, at += 3) {
                    const Vec3 x = Vec3{double(at[0]), double(at[1]), double(at[2])} - ballCentre_;
                    if (norm2(x) <= ballRadius2_) visit(ids[i], at);
                }
            });
        return;
    }
    for (size_t i = 0; i < inBallCount_; ++i) visit(inBall_[i].id, inBall_[i].point);
    if (runs_.empty()) return;
    // Each run's nearest possible point, exactly (the box's gap to p per
    // axis, in fixed point). The nearest run first, since it sets the bound
    // soonest; then the others in turn, each passed over if it lies beyond
    // the bound by then (sorting them all costs more than it spares).
    byDistance_.clear();
    size_t nearest = 0;
    for (uint32_t r = 0; r < runs_.size(); ++r) {
        const int64_t d2 = boxDistance2(p, runs_[r].box);
        if (d2 < (byDistance_.empty() ? INT64_MAX : byDistance_[nearest].first)) nearest = byDistance_.size();
        byDistance_.emplace_back(d2, r);
    }
    if (!byDistance_.empty()) std::swap(byDistance_[0], byDistance_[nearest]);
    for (const std::pair<int64_t, uint32_t>& near : byDistance_) {
        if (near.first > bound()) continue;  // no vertex of this run can enter
        const Run& run = runs_[near.second];
        const int32_t* at = run.points;
        for (size_t i = 0; i < run.count; ++i, at += 3) {
            const Vec3 x = Vec3{double(at[0]), double(at[1]), double(at[2])} - ballCentre_;
            if (norm2(x) <= ballRadius2_) visit(run.ids[i], at);
        }
    }
}

}  // namespace drm

#endif  // DRM_PREDICTOR_H
