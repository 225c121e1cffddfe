#include "connectivity/ranked/predictor.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "mesh/quantize.h"
#include "connectivity/ranked/rank_search.h"
#include "spatial/spatial_index.h"

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
    const Slab slab{mid, e, offset * (1.0 / height), edgeLength, edgeLength * (0.5 + tuning_.slabWidening),
                    {e.x / edgeLength, e.y / edgeLength, e.z / edgeLength}};

    double radius = 2.0 * std::max(height, edgeLength);
    searchedBall_ = true;
    if (wideBallRadius_ < 0) wideBallRadius_ = candidates_.wideBallRadius();
    for (int attempt = 0; attempt < 4; ++attempt, radius *= 2.0) {
        // A ball many cells across is searched through the index's
        // hierarchy (firstAheadInOrder), once enough of them were. Any
        // other: the index hands over its runs of vertices around the ball
        // (cells of the grid, each in a box), the first listed (their
        // vertices in the ball), those past kListUpToPoints vertices kept
        // as runs. The rank's nearest candidates come from the same ball
        // (forEachInBall).
        runs_.clear();
        ballCentre_ = mid;
        ballRadius_ = radius;
        ballRadius2_ = radius * radius;
        inBallCount_ = 0;
        wideBall_ = radius > wideBallRadius_ && ++wideBallsSearched_ > kWideBallsBefore;
        FirstAhead found;
        if (wideBall_) {
            found = firstAheadInOrder(slab, edge);
        } else {
            size_t points = 0;
            candidates_.forEachNear(mid, radius, [&](const uint32_t* ids, const int32_t* at, size_t count, const int32_t* box) {
                points += count;
                if (points <= kListUpToPoints) gather(ids, at, count);
                else runs_.push_back({ids, at, box, count});
            });
            found = runs_.empty() ? firstAheadInBall(slab, edge) : firstAheadByRuns(slab, edge);
        }
        if (found.vertex != kNoIndex) {
            firstAheadAttempt_ = attempt;
            return mid + (p - mid) * (found.height / height);
        }
        if (attempt == 0 && firstBallOnly_ && firstBallOnly_->contains(edge, snapPrediction(p, firstBallOnly_->bits)))
            return p;  // the seam's side: the first ball only
    }
    return p;
}

// The ball's vertices, listed: the box of cells around the ball holds a few
// dozen vertices, and most of them lie outside the ball, behind the edge or
// beside the slab, and which it is is a coin toss to a branch predictor. So
// the ball is gathered first without a branch (every vertex is written to
// the list, and kept there if inside), then the slab test, also without a
// branch, over the whole ball at once (firstAheadInBall).
void ApexPredictor::gather(const uint32_t* ids, const int32_t* at, size_t count) {
    if (inBall_.size() < inBallCount_ + count) inBall_.resize(2 * (inBallCount_ + count));
    BallVertex* out = inBall_.data() + inBallCount_;
    size_t kept = 0;
    for (size_t i = 0; i < count; ++i, at += 3) {
        const Vec3 x = Vec3{double(at[0]), double(at[1]), double(at[2])} - ballCentre_;
        out[kept] = {ids[i], at};
        kept += norm2(x) <= ballRadius2_;
    }
    inBallCount_ += kept;
}

// Whether v at grid point q is in the slab ahead, and better than the best
// so far: the smallest height, then the smallest index. The one branch is
// taken by a vertex nearer than the best so far, seldom once one is found;
// only then is it asked whether the vertex is admissible (edge look-ups).
inline void ApexPredictor::offerAhead(const Slab& slab, uint32_t v, const int32_t* q, bool inBall,
                                      const OpenEdge& edge, FirstAhead& best) const {
    const Vec3 x = Vec3{double(q[0]), double(q[1]), double(q[2])} - slab.mid;
    const double h = dot(x, slab.ahead);
    const double along = dot(x, slab.e) / slab.edgeLength;
    const bool inSlab = (h > 0) & !(along > slab.halfWidth) & !(along < -slab.halfWidth);
    if (inBall & inSlab & ((h < best.height) | ((h == best.height) & (v < best.vertex))) && usable_(v, edge)) {
        best.height = h;
        best.vertex = v;
    }
}

ApexPredictor::FirstAhead ApexPredictor::firstAheadInBall(const Slab& slab, const OpenEdge& edge) const {
    FirstAhead best;
    for (size_t i = 0; i < inBallCount_; ++i) offerAhead(slab, inBall_[i].id, inBall_[i].point, true, edge, best);
    return best;
}

// A bound below the height of the vertices of a box that can be in the
// slab: the heights of the box's corners, less a margin far above the
// rounding of either side (coordinates below 2^26, so errors below 1e-6
// units), or +infinity for a box behind the edge or beside the slab. No
// vertex that could be first is passed over by it, and which one is first
// is decided vertex by vertex, as in the ball.
double ApexPredictor::lowestAhead(const Slab& slab, const int32_t* box) {
    constexpr double kMargin = 1e-3;
    const double centre[3] = {slab.mid.x, slab.mid.y, slab.mid.z}, towards[3] = {slab.ahead.x, slab.ahead.y, slab.ahead.z},
                 along[3] = {slab.along.x, slab.along.y, slab.along.z};
    double hLo = 0, hHi = 0, alongLo = 0, alongHi = 0;
    for (int k = 0; k < 3; ++k) {
        const double lo = double(box[k]) - centre[k], hi = double(box[3 + k]) - centre[k];
        hLo += std::min(lo * towards[k], hi * towards[k]);
        hHi += std::max(lo * towards[k], hi * towards[k]);
        alongLo += std::min(lo * along[k], hi * along[k]);
        alongHi += std::max(lo * along[k], hi * along[k]);
    }
    if (hHi + kMargin <= 0 || alongLo - kMargin > slab.halfWidth || alongHi + kMargin < -slab.halfWidth)
        return std::numeric_limits<double>::infinity();
    return hLo - kMargin;
}

// The same vertex from the runs as they are, for balls too full to list
// (on CAD meshes long edges make balls of thousands of vertices, of which a
// few cells matter): the runs listed before the ball was found too full,
// then the others. A run whose box holds no vertex ahead (lowestAhead) or
// lies above the best height found so far is passed over: the lowest box
// is looked at first, then the others in turn, each passed over if it lies
// above the best by then (sorting them all costs more than it spares).
ApexPredictor::FirstAhead ApexPredictor::firstAheadByRuns(const Slab& slab, const OpenEdge& edge) const {
    FirstAhead best = firstAheadInBall(slab, edge);  // the runs listed before the ball was found too full
    byHeight_.clear();
    size_t lowest = 0;
    for (uint32_t r = 0; r < runs_.size(); ++r) {
        const double low = lowestAhead(slab, runs_[r].box);
        if (low == std::numeric_limits<double>::infinity()) continue;
        if (byHeight_.empty() || low < byHeight_[lowest].first) lowest = byHeight_.size();
        byHeight_.emplace_back(low, r);
    }
    if (!byHeight_.empty()) std::swap(byHeight_[0], byHeight_[lowest]);
    for (const std::pair<double, uint32_t>& low : byHeight_) {
        if (low.first > best.height) continue;  // the run lies above the best
        const Run& run = runs_[low.second];
        const int32_t* q = run.points;
        for (size_t i = 0; i < run.count; ++i, q += 3) {
            const Vec3 x = Vec3{double(q[0]), double(q[1]), double(q[2])} - ballCentre_;
            offerAhead(slab, run.ids[i], q, norm2(x) <= ballRadius2_, edge, best);
        }
    }
    return best;
}

// The same vertex through the index's hierarchy (wide balls): groups of
// cells behind the edge, beside the slab or above the best so far are
// passed over whole, the lowest opened first.
ApexPredictor::FirstAhead ApexPredictor::firstAheadInOrder(const Slab& slab, const OpenEdge& edge) const {
    FirstAhead best;
    candidates_.forEachNearInOrder(
        ballCentre_, ballRadius_, [&](const int32_t* box) { return lowestAhead(slab, box); }, [&] { return best.height; },
        [&](const uint32_t* ids, const int32_t* q, size_t count, const int32_t*) {
            for (size_t i = 0; i < count; ++i, q += 3) {
                const Vec3 x = Vec3{double(q[0]), double(q[1]), double(q[2])} - ballCentre_;
                offerAhead(slab, ids[i], q, norm2(x) <= ballRadius2_, edge, best);
            }
        });
    return best;
}

}  // namespace drm
