#include "predictor.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "quantize.h"
#include "spatial_index.h"

namespace drm {

Vec3 parallelogramApex(Vec3 a, Vec3 b, Vec3 o) { return a + b - o; }

Vec3 midpointApex(Vec3 a, Vec3 b, Vec3 o) {
    const Vec3 e = b - a;
    const double edgeLength2 = norm2(e);
    const Vec3 mid = (a + b) * 0.5;
    const Vec3 away = rejectFrom(mid - o, e);  // in the triangle's plane, away from o
    const double awayLength = norm(away);
    if (edgeLength2 == 0 || awayLength == 0) return mid;  // degenerate triangle: no direction
    // Equilateral height ahead of the edge...
    const double height = 0.8660254037844386 * std::sqrt(edgeLength2);
    Vec3 apex = mid + away * (height / awayLength);
    // ...shifted slightly along the edge the way the rebuilt triangle leans,
    // so that on quad-like grids the two equidistant vertices do not tie
    // (the paper's skew bias; 0.05 of the opposite vertex's offset measured
    // best, method notes).
    const double lean = dot(mid - o, e) / edgeLength2;
    apex = apex + e * (0.05 * lean);
    return apex;
}

Vec3 baseApex(Predictor kind, Vec3 a, Vec3 b, Vec3 o) {
    return kind == Predictor::Parallelogram ? parallelogramApex(a, b, o) : midpointApex(a, b, o);
}

ApexPredictor::ApexPredictor(Predictor kind, bool curvature, const std::vector<int32_t>& grid,
                             const SpatialIndex& candidates, const Admissibility& admissible, PredictorTuning tuning)
    : kind_(kind), curvature_(curvature), grid_(grid), candidates_(candidates), usable_(admissible),
      tuning_(tuning) {}

Vec3 ApexPredictor::predict(const OpenEdge& edge) {
    searchedBall_ = false;
    firstAheadAttempt_ = -1;
    const Vec3 a = gridPoint(grid_, edge.vi), b = gridPoint(grid_, edge.vj);
    Vec3 p = baseApex(kind_, a, b, gridPoint(grid_, edge.opposite));
    if (norm2(b - a) == 0) return p;  // coincident ends: no edge frame to correct in
    if (curvature_) p = bendOntoSurface(p, a, b, edge);
    return scaleToFirstVertexAhead(p, a, b, edge);
}

// Figure 4: rotate p about the edge onto the plane through the edge and the
// centroid c of the nearest candidates; of the two rotations that reach the
// plane, the smaller one.
Vec3 ApexPredictor::bendOntoSurface(Vec3 p, Vec3 a, Vec3 b, const OpenEdge& edge) {
    const Vec3 e = b - a, mid = (a + b) * 0.5;
    const double radius = tuning_.curvatureRadius * norm(e);
    candidates_.collectNear(p, radius, nearby_);
    std::vector<std::pair<double, uint32_t>> byDistance;
    byDistance.reserve(nearby_.size());
    for (uint32_t v : nearby_) {
        if (!usable_(v, edge)) continue;
        const double d2 = norm2(gridPoint(grid_, v) - p);
        if (d2 <= radius * radius) byDistance.emplace_back(d2, v);
    }
    if (byDistance.empty()) return p;
    const size_t keep = std::min(byDistance.size(), size_t(tuning_.curvatureNeighbours));
    std::partial_sort(byDistance.begin(), byDistance.begin() + keep, byDistance.end());
    Vec3 centroid;
    for (size_t i = 0; i < keep; ++i) centroid = centroid + gridPoint(grid_, byDistance[i].second);
    centroid = centroid * (1.0 / double(keep));

    const Vec3 toward = rejectFrom(centroid - mid, e);
    const Vec3 offset = rejectFrom(p - mid, e);
    const double towardLength = norm(toward), offsetLength = norm(offset);
    if (towardLength == 0 || offsetLength == 0) return p;
    const double side = dot(offset, toward) < 0 ? -1.0 : 1.0;
    const Vec3 along = (p - mid) - offset;
    return mid + along + toward * (side * offsetLength / towardLength);
}

// Figure 5: among the candidates in the slab ahead of the edge (bounded by
// two planes perpendicular to the edge, widened beyond its ends), the one
// nearest the edge along the prediction direction sets the height of the
// prediction. The search grows outwards until it finds one or gives up.
Vec3 ApexPredictor::scaleToFirstVertexAhead(Vec3 p, Vec3 a, Vec3 b, const OpenEdge& edge) {
    const Vec3 e = b - a, mid = (a + b) * 0.5;
    const double edgeLength = norm(e);
    const Vec3 offset = rejectFrom(p - mid, e);
    const double height = norm(offset);
    if (height == 0) return p;
    const Vec3 ahead = offset * (1.0 / height);
    const double halfSlab = edgeLength * (0.5 + tuning_.slabWidening);

    double radius = 2.0 * std::max(height, edgeLength);
    searchedBall_ = true;
    for (int attempt = 0; attempt < 4; ++attempt, radius *= 2.0) {
        // The box of cells around the ball holds a few dozen vertices, and
        // most of them lie outside the ball, behind the edge or beside the
        // slab, and which it is is a coin toss to a branch predictor. So
        // the ball is gathered first without a branch (every vertex is
        // written to the list, and kept there if inside), from the index's
        // runs where they lie; then the slab test, also without a branch,
        // over the whole ball at once.
        inBallCount_ = 0;
        const double radius2 = radius * radius;
        candidates_.forEachNear(mid, radius, [&](const uint32_t* ids, const int32_t* at, size_t count) {
            if (inBall_.size() < inBallCount_ + count) inBall_.resize(2 * (inBallCount_ + count));
            BallVertex* out = inBall_.data() + inBallCount_;
            size_t kept = 0;
            for (size_t i = 0; i < count; ++i, at += 3) {
                const Vec3 x = Vec3{double(at[0]), double(at[1]), double(at[2])} - mid;
                out[kept] = {ids[i], at};
                kept += norm2(x) <= radius2;
            }
            inBallCount_ += kept;
        });
        // The best so far: the smallest height, then the smallest index.
        // The one branch is taken by a vertex in the slab nearer than the
        // best so far, seldom once one is found; only then is it asked
        // whether the vertex is admissible (edge look-ups).
        double firstHeight = std::numeric_limits<double>::infinity();
        uint32_t first = kNoIndex;
        for (size_t i = 0; i < inBallCount_; ++i) {
            const int32_t* q = inBall_[i].point;
            const Vec3 x = Vec3{double(q[0]), double(q[1]), double(q[2])} - mid;
            const uint32_t v = inBall_[i].id;
            const double h = dot(x, ahead);
            const double along = dot(x, e) / edgeLength;
            const bool inSlab = (h > 0) & !(along > halfSlab) & !(along < -halfSlab);
            if (inSlab & ((h < firstHeight) | ((h == firstHeight) & (v < first))) && usable_(v, edge)) {
                firstHeight = h;
                first = v;
            }
        }
        if (first != kNoIndex) {
            firstAheadAttempt_ = attempt;
            return mid + (p - mid) * (firstHeight / height);
        }
    }
    return p;
}

}  // namespace drm
