// FLANN's kd-tree (Muja and Lowe; Debian's libflann-dev, used header-only)
// as a SpatialIndex: KDTreeSingleIndex, whose search with eps = 0 and
// unlimited checks visits every leaf its float bounds cannot rule out.
//
// FLANN computes in float, the codec ranks in exact integers, so FLANN's
// answer is only a nomination. For a k-nearest query that came back full,
// every vertex it did not return lies, in FLANN's float arithmetic, at
// least as far as its k-th (a leaf rejects only what is no nearer than the
// k-th so far, a branch is pruned only when its float box distance exceeds
// it). Float rounding of those distances, of the box distances summed down
// the tree and of the coordinates themselves is bounded:
//   true distance of a vertex not returned >= sqrt(F_k (1 - kRelativeMargin))
//                                           - (query rounding + point rounding),
// with kRelativeMargin far above the few hundred float roundings a search
// can accumulate (2^-24 each). Candidates are then ranked exactly; once
// `count` accepted ones lie strictly below that bound, no vertex outside
// could come before them, ties included, and the answer is the grid's. If
// they do not, k doubles; a query that comes back with fewer than k
// vertices has returned every present vertex.
#include "spatial/spatial_index.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>
#include <flann/util/matrix.h>
#include <flann/util/result_set.h>

namespace drm {
namespace {

constexpr double kRelativeMargin = 1.0 / 1024;
// Leaves of 8 points: the fastest of 4, 8, 10 and 16 on bunny (docs/tuning.md).
constexpr int kLeafSize = 8;
// The first k of a nearest search: the answer and a few more, since some
// of the nearest are usually not admissible.
constexpr size_t kExtraCandidates = 4;
// FLANN's result sets: a sorted list (insertion costs k) for a few, a heap
// beyond (far ranks on sliver-rich meshes ask for hundreds).
constexpr size_t kSortedListUpTo = 32;

using Tree = flann::KDTreeSingleIndex<flann::L2_3D<float>>;

// Collects every vertex FLANN finds within a float radius.
class WithinRadius final : public flann::ResultSet<float> {
public:
    WithinRadius(float radius2, std::vector<uint32_t>& out) : radius2_(radius2), out_(out) {}
    bool full() const override { return true; }
    void addPoint(float dist, size_t index) override {
        if (dist < radius2_) out_.push_back(uint32_t(index));
    }
    float worstDist() const override { return radius2_; }

private:
    float radius2_;
    std::vector<uint32_t>& out_;
};

class FlannIndex final : public SpatialIndex {
public:
    explicit FlannIndex(const std::vector<int32_t>& grid);

    const char* name() const override { return "flann"; }
    void remove(uint32_t v) override;
    size_t presentCount() const override { return present_.size(); }
    void collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const override;
    void forEachNear(Vec3 q, double radius, PointRunVisitor visit) const override {
        collectNear(q, radius, near_);
        if (near_.empty()) return;
        nearPoints_.resize(3 * near_.size());
        int32_t* box = nearBox_;
        for (int k = 0; k < 3; ++k) {
            box[k] = INT32_MAX;
            box[3 + k] = INT32_MIN;
        }
        for (size_t i = 0; i < near_.size(); ++i)
            for (size_t k = 0; k < 3; ++k) {
                const int32_t c = grid_[3 * size_t(near_[i]) + k];
                nearPoints_[3 * i + k] = c;
                box[k] = std::min(box[k], c);
                box[3 + k] = std::max(box[3 + k], c);
            }
        visit(near_.data(), nearPoints_.data(), near_.size(), box);
    }
    void nearest(const FixedPoint& p, size_t count, VertexFilter accept, std::vector<RankedVertex>& out) const override;
    void nearestOfEach(size_t count, std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                       int threads) const override;

private:
    // The float query for fixed-point p (relative to the origin), and how far
    // it lies from p, in grid units.
    double floatQuery(const FixedPoint& p, float q[3]) const;
    // Squared fixed-point distance below which every vertex not returned
    // lies farther: from F_k, FLANN's float distance of the last vertex
    // returned, and the query's rounding error.
    double certifiedBound(float lastDistance, double queryError) const;
    // Ranks `found` (vertex ids) exactly and keeps the first `count`
    // accepted strictly below bound; true when there were `count`.
    // FLANN's k nearest of q into found_ and foundDistance_, nearest first.
    template <class Result>
    size_t search(const float q[3], size_t k, const flann::SearchParams& params) const {
        Result result(k);
        tree_->findNeighbors(result, q, params);
        const size_t got = result.size();
        found_.resize(got);
        foundDistance_.resize(got);
        result.copy(found_.data(), foundDistance_.data(), got, true);
        return got;
    }
    bool settle(const FixedPoint& p, const size_t* found, size_t got, double bound, size_t count,
                VertexFilter accept, std::vector<RankedVertex>& out) const;

    const std::vector<int32_t>& grid_;
    int64_t origin_ = 0;          // the smallest coordinate; FLANN sees coordinates relative to it
    std::vector<float> points_;   // x, y, z per vertex, relative to origin_
    double pointError_ = 0;       // largest distance between a vertex and its float point (grid units)
    std::unique_ptr<Tree> tree_;
    std::vector<uint32_t> present_, presentSlot_;  // present vertices, for searches that take them all
    mutable std::vector<size_t> found_;
    mutable std::vector<float> foundDistance_;
    mutable std::vector<RankedVertex> ranked_;
    mutable std::vector<uint32_t> near_;  // forEachNear's run
    mutable int32_t nearBox_[6];          // and the box around it
    mutable std::vector<int32_t> nearPoints_;
};

FlannIndex::FlannIndex(const std::vector<int32_t>& grid) : grid_(grid) {
    const size_t n = grid.size() / 3;
    present_.resize(n);
    presentSlot_.resize(n);
    for (size_t v = 0; v < n; ++v) present_[v] = presentSlot_[v] = uint32_t(v);
    if (n == 0) return;
    origin_ = *std::min_element(grid.begin(), grid.end());
    points_.resize(3 * n);
    double axisError = 0;
    for (size_t i = 0; i < 3 * n; ++i) {
        const double exact = double(int64_t(grid[i]) - origin_);
        points_[i] = float(exact);
        axisError = std::max(axisError, std::fabs(double(points_[i]) - exact));
    }
    pointError_ = axisError * std::sqrt(3.0) * (1 + 1e-9);  // 0 on real grids (coordinates below 2^24)
    tree_.reset(new Tree(flann::Matrix<float>(points_.data(), n, 3), flann::KDTreeSingleIndexParams(kLeafSize)));
    tree_->buildIndex();
}

void FlannIndex::remove(uint32_t v) {
    if (v >= presentSlot_.size() || presentSlot_[v] == kNotPresent) return;
    tree_->removePoint(v);
    const uint32_t at = presentSlot_[v], moved = present_.back();
    present_[at] = moved;
    presentSlot_[moved] = at;
    present_.pop_back();
    presentSlot_[v] = kNotPresent;
}

double FlannIndex::floatQuery(const FixedPoint& p, float q[3]) const {
    const int64_t at[3] = {p.x - origin_ * kSubUnits, p.y - origin_ * kSubUnits, p.z - origin_ * kSubUnits};
    double error2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double exact = double(at[k]) / double(kSubUnits);  // exact: |at| < 2^53
        q[k] = float(exact);
        const double e = double(q[k]) - exact;
        error2 += e * e;
    }
    return std::sqrt(error2) * (1 + 1e-9);
}

double FlannIndex::certifiedBound(float lastDistance, double queryError) const {
    const double reach = std::sqrt(double(lastDistance) * (1 - kRelativeMargin)) - queryError - pointError_;
    if (!(reach > 0)) return 0;
    const double fixedReach = reach * double(kSubUnits);
    return fixedReach * fixedReach * (1 - 1e-9);  // below it, double rounding of the comparison cannot matter
}

bool FlannIndex::settle(const FixedPoint& p, const size_t* found, size_t got, double bound, size_t count,
                        VertexFilter accept, std::vector<RankedVertex>& out) const {
    ranked_.clear();
    for (size_t i = 0; i < got; ++i) ranked_.emplace_back(fixedDistance2(grid_, p, uint32_t(found[i])), uint32_t(found[i]));
    std::sort(ranked_.begin(), ranked_.end());
    out.clear();
    for (const RankedVertex& c : ranked_) {
        if (!(double(c.first) < bound)) return false;
        if (accept(c.second)) {
            out.push_back(c);
            if (out.size() == count) return true;
        }
    }
    return false;
}

void FlannIndex::nearest(const FixedPoint& p, size_t count, VertexFilter accept, std::vector<RankedVertex>& out) const {
    out.clear();
    if (count == 0 || present_.empty()) return;
    float q[3];
    const double queryError = floatQuery(p, q);
    const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
    for (size_t k = std::min(present_.size(), std::max(2 * count, count + kExtraCandidates));;
         k = std::min(present_.size(), 2 * k)) {
        const size_t got = k <= kSortedListUpTo ? search<flann::KNNSimpleResultSet<float>>(q, k, params)
                                                : search<flann::KNNResultSet2<float>>(q, k, params);
        // Fewer than k, or every present vertex: nothing was left out.
        const bool all = got < k || got == present_.size();
        const double bound = all ? std::numeric_limits<double>::infinity()
                                 : certifiedBound(foundDistance_[got - 1], queryError);
        if (settle(p, found_.data(), got, bound, count, accept, out) || all) return;
    }
}

void FlannIndex::collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const {
    out.clear();
    if (present_.empty()) return;
    const double at[3] = {q.x - double(origin_), q.y - double(origin_), q.z - double(origin_)};
    float fq[3];
    double error2 = 0;
    for (int k = 0; k < 3; ++k) {
        fq[k] = float(at[k]);
        const double e = double(fq[k]) - at[k];
        error2 += e * e;
    }
    // One unit beyond the ball, as the grid does, then the roundings.
    const double reach = (radius + 1.0 + std::sqrt(error2) + pointError_) * (1 + kRelativeMargin);
    if (!(reach < double(int64_t(1) << 27)) || !std::isfinite(at[0] + at[1] + at[2])) {
        out.insert(out.end(), present_.begin(), present_.end());  // also NaN: let the callers' tests decide
        return;
    }
    WithinRadius result(float(reach * reach), out);
    tree_->findNeighbors(result, fq, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0.0f, false));
}

// FLANN's batch search over every vertex, spread over `threads` (OpenMP),
// then each answer certified as above; the few that are not are asked
// again one by one with a growing k.
void FlannIndex::nearestOfEach(size_t count, std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                               int threads) const {
    const size_t n = grid_.size() / 3;
    neighbours.assign(n * count, kNoVertex);
    if (distance2) distance2->assign(n * count, 0);
    if (n == 0 || count == 0 || present_.empty()) return;
    const size_t k = std::min(present_.size(), count + 1 + kExtraCandidates);  // + 1: the vertex itself
    std::vector<size_t> indexData(n * k, size_t(-1));
    std::vector<float> distanceData(n * k, 0);
    flann::Matrix<size_t> indices(indexData.data(), n, k);
    flann::Matrix<float> distances(distanceData.data(), n, k);
    flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
    params.cores = std::max(1, threads);
    tree_->knnSearch(flann::Matrix<float>(const_cast<float*>(points_.data()), n, 3), indices, distances, k, params);
    std::vector<RankedVertex> found;
    for (size_t v = 0; v < n; ++v) {
        const size_t* row = indices[v];
        const size_t got = size_t(std::find(row, row + k, size_t(-1)) - row);
        const bool all = got < k || got == present_.size();
        const FixedPoint p = fixedPointOf(grid_, uint32_t(v));
        auto other = [v](uint32_t w) { return w != v; };
        // The query is the vertex's own float point: its rounding is pointError_.
        const double bound =
            all ? std::numeric_limits<double>::infinity() : certifiedBound(distances[v][got - 1], pointError_);
        if (!settle(p, row, got, bound, count, other, found) && !all) nearest(p, count, other, found);
        for (size_t j = 0; j < found.size(); ++j) {
            neighbours[v * count + j] = found[j].second;
            if (distance2) (*distance2)[v * count + j] = found[j].first;
        }
    }
}

}  // namespace

std::unique_ptr<SpatialIndex> makeFlannIndex(const std::vector<int32_t>& grid) {
    return std::unique_ptr<SpatialIndex>(new FlannIndex(grid));
}

}  // namespace drm
