#include "spatial/spatial_index.h"

#include <algorithm>
#include <limits>
#include <memory>

#include "spatial/all_nearest.h"
#include "spatial/candidate_set.h"

namespace drm {

// The grid is faster for the traversal's searches, each of which looks at a
// few dozen vertices around one point while vertices are culled
// (docs/tuning.md).
constexpr NeighbourIndex kTraversalDefault = NeighbourIndex::Grid;
// The grid is faster for the geometry tree's k-nearest graph too: its
// search by cells (all_nearest.h) answers every vertex at once.
constexpr NeighbourIndex kNeighbourGraphDefault = NeighbourIndex::Grid;

NeighbourIndex resolveIndex(NeighbourIndex choice, IndexRole role) {
    if (choice != NeighbourIndex::Auto) return choice;
    return role == IndexRole::Traversal ? kTraversalDefault : kNeighbourGraphDefault;
}

size_t SpatialIndex::nthNearest(const FixedPoint& p, size_t count, VertexFilter accept, RankedVertex& out) const {
    std::vector<RankedVertex> list;
    nearest(p, count, accept, list);
    if (count > 0 && list.size() == count) out = list.back();
    return list.size();
}

void SpatialIndex::forEachNearInOrder(Vec3 q, double radius, BoxBound lowest, KeyLimit limit,
                                      PointRunVisitor visit) const {
    forEachNear(q, radius, [&](const uint32_t* ids, const int32_t* points, size_t count, const int32_t* box) {
        const double key = lowest(box);  // +infinity: never
        if (key < std::numeric_limits<double>::infinity() && key <= limit()) visit(ids, points, count, box);
    });
}

namespace {

// The grid of cells. Nearest searches walk rings of cells outwards until
// nothing outside them can come nearer (exact on the integer grid).
class GridIndex final : public SpatialIndex {
public:
    GridIndex(const std::vector<int32_t>& grid, int cellShift) : grid_(grid), cellShift_(cellShift) {}

    const char* name() const override { return "grid"; }
    void remove(uint32_t v) override { cells().remove(v); }
    size_t presentCount() const override { return cells_ ? cells_->presentCount() : grid_.size() / 3; }
    void collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const override {
        cells().collectNear(q, radius, out);
    }
    void forEachNear(Vec3 q, double radius, PointRunVisitor visit) const override {
        cells().forEachNear(q, radius, visit);
    }
    void forEachNearInOrder(Vec3 q, double radius, BoxBound lowest, KeyLimit limit,
                            PointRunVisitor visit) const override {
        cells().forEachNearInOrder(q, radius, lowest, limit, visit);
    }
    double wideBallRadius() const override { return cells().wideBallRadius(); }
    void nearest(const FixedPoint& p, size_t count, VertexFilter accept, std::vector<RankedVertex>& out) const override;
    size_t nthNearest(const FixedPoint& p, size_t count, VertexFilter accept, RankedVertex& out) const override;
    void nearestOfEach(size_t count, std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                       int threads) const override;

private:
    static constexpr size_t kFewNearest = 8;  // kept in a sorted list; more are sorted at the end
    void manyNearest(const FixedPoint& p, size_t count, VertexFilter accept, std::vector<RankedVertex>& out) const;

    const std::vector<int32_t>& grid_;
    // The cells, made when first asked for: the 8-nearest graph asks only
    // for the few points its own search by cells leaves uncertain, once
    // that search has freed its tables, so the two sets of tables (the
    // cells' about twice the search's) never stand side by side.
    const VertexIndex& cells() const { return built(); }
    VertexIndex& cells() { return built(); }
    VertexIndex& built() const {
        if (!cells_) cells_.reset(new VertexIndex(grid_, cellShift_));
        return *cells_;
    }
    const int cellShift_;
    mutable std::unique_ptr<VertexIndex> cells_;
    mutable std::vector<uint32_t> scratch_;
    mutable std::vector<RankedVertex> candidates_, accepted_;
};

void GridIndex::nearest(const FixedPoint& p, size_t count, VertexFilter accept, std::vector<RankedVertex>& out) const {
    out.clear();
    if (count == 0) return;
    if (count > kFewNearest) return manyNearest(p, count, accept, out);
    cells().nearestFew(
        p, count, [&](uint32_t v) { return fixedDistance2(grid_, p, v); }, accept, out, scratch_);
}

// Every vertex at once by cells (all_nearest.h), then the vertices that
// pass leaves uncertain one by one: the same answers as a search per
// vertex, in about two thirds of its instructions.
void GridIndex::nearestOfEach(size_t count, std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                              int threads) const {
    const size_t n = grid_.size() / 3;
    neighbours.assign(n * count, kNoVertex);
    if (distance2) distance2->assign(n * count, 0);
    std::vector<uint32_t> uncertain;
    if (presentCount() == n) {
        uncertain = nearestOfEachByCells(grid_, count, -1, neighbours, distance2, threads);
        if (distance2)
            for (int64_t& d2 : *distance2) d2 *= kSubUnits * kSubUnits;  // to fixed point, as nearest() gives them
    } else {
        uncertain.resize(n);
        for (size_t v = 0; v < n; ++v) uncertain[v] = uint32_t(v);
    }
    std::vector<RankedVertex> found;
    for (const uint32_t v : uncertain) {
        nearest(fixedPointOf(grid_, v), count, [v](uint32_t w) { return w != v; }, found);
        for (size_t j = 0; j < found.size(); ++j) {
            neighbours[v * count + j] = found[j].second;
            if (distance2) (*distance2)[v * count + j] = found[j].first;
        }
    }
}

// For long lists (over kFewNearest; the decoder's far ranks take one vertex
// from nthNearest instead; the encoder's neighbour graph asks for 16 on
// meshes of up to 32,768 vertices, here for the points the cells left
// uncertain):
// everything in the rings, sorted, then acceptance in rank order. Sorting
// is what costs, so it waits until the rings hold `count` vertices at all,
// and after a failed attempt until they have doubled.
void GridIndex::manyNearest(const FixedPoint& p, size_t count, VertexFilter accept,
                            std::vector<RankedVertex>& out) const {
    candidates_.clear();
    auto collect = [&](const uint32_t* first, size_t n) {
        for (size_t i = 0; i < n; ++i) candidates_.emplace_back(fixedDistance2(grid_, p, first[i]), first[i]);
    };
    auto collectCell = [&](const uint32_t* first, const int32_t*, size_t n, const int32_t*) { collect(first, n); };
    auto settle = [&](int64_t clear) {  // true once `count` accepted vertices are nearer than clear
        std::sort(candidates_.begin(), candidates_.end());
        out.clear();
        for (const RankedVertex& c : candidates_) {
            if (c.first >= clear) return false;
            if (accept(c.second)) {
                out.push_back(c);
                if (out.size() == count) return true;
            }
        }
        return false;
    };
    size_t settleFrom = count;
    uint64_t cellsVisited = 0;
    const VertexIndex& index = cells();
    for (int ring = index.firstRing(p);; ++ring) {
        cellsVisited += VertexIndex::ringCellCount(ring);
        if (cellsVisited > index.cellBudget()) {
            candidates_.clear();
            scratch_.clear();
            index.collectAll(scratch_);
            collect(scratch_.data(), scratch_.size());
            settle(INT64_MAX);
            return;
        }
        index.forEachCellOfRing(p, ring, INT64_MAX, collectCell);
        if (index.ringsCoverGrid(p, ring)) {
            settle(INT64_MAX);
            return;
        }
        if (candidates_.size() < settleFrom) continue;
        if (settle(index.clearance2(p, ring))) return;
        settleFrom = 2 * candidates_.size();
    }
}

// For a far rank: the rings as manyNearest walks them, but nothing is
// sorted. Of the vertices nearer than the rings' clearance (no other can be
// settled yet), the nearest are taken a chunk at a time (a selection,
// std::nth_element: as many as the accepted ones still wanted and a quarter
// more), and each vertex of the chunk is asked whether it is accepted. Every
// chunk lies beyond the one before, so once `count` are accepted, the
// answer is the one among the last chunk's accepted that makes up the
// count, selected again. A vertex is asked once: a settling that fails has
// asked every vertex nearer than its clearance, and keeps those accepted.
// (Sorting the rings would take most of the decoding time of a mesh with
// many far ranks, such as the CAD mesh crank.)
size_t GridIndex::nthNearest(const FixedPoint& p, size_t count, VertexFilter accept, RankedVertex& out) const {
    if (count <= kFewNearest) {  // the list of a few, in the index's own scratch
        nearest(p, count, accept, candidates_);
        if (candidates_.size() == count) out = candidates_.back();
        return candidates_.size();
    }
    candidates_.clear();
    accepted_.clear();
    auto collect = [&](const uint32_t* first, size_t n) {
        for (size_t i = 0; i < n; ++i) candidates_.emplace_back(fixedDistance2(grid_, p, first[i]), first[i]);
    };
    auto collectCell = [&](const uint32_t* first, const int32_t*, size_t n, const int32_t*) { collect(first, n); };
    auto settle = [&](int64_t clear) {  // true once `count` accepted vertices are nearer than clear
        const auto nearer = std::partition(candidates_.begin(), candidates_.end(),
                                           [clear](const RankedVertex& c) { return c.first >= clear; });
        for (auto first = nearer; first != candidates_.end();) {
            const size_t wanted = count - accepted_.size(), chunk = wanted + wanted / 4 + 16;
            const auto chunkEnd = size_t(candidates_.end() - first) > chunk ? first + ptrdiff_t(chunk) : candidates_.end();
            if (chunkEnd != candidates_.end()) std::nth_element(first, chunkEnd, candidates_.end());
            const size_t before = accepted_.size();
            for (; first != chunkEnd; ++first)
                if (accept(first->second)) accepted_.push_back(*first);
            if (accepted_.size() >= count) {
                std::nth_element(accepted_.begin() + ptrdiff_t(before), accepted_.begin() + ptrdiff_t(count - 1),
                                 accepted_.end());
                out = accepted_[count - 1];
                return true;
            }
        }
        candidates_.erase(nearer, candidates_.end());
        return false;
    };
    const VertexIndex& index = cells();
    uint64_t cellsVisited = 0;
    for (int ring = index.firstRing(p);; ++ring) {
        cellsVisited += VertexIndex::ringCellCount(ring);
        if (cellsVisited > index.cellBudget()) {  // far from everything left: look at everything
            candidates_.clear();
            accepted_.clear();
            scratch_.clear();
            index.collectAll(scratch_);
            collect(scratch_.data(), scratch_.size());
            return settle(INT64_MAX) ? count : accepted_.size();
        }
        index.forEachCellOfRing(p, ring, INT64_MAX, collectCell);
        if (index.ringsCoverGrid(p, ring)) return settle(INT64_MAX) ? count : accepted_.size();
        if (accepted_.size() + candidates_.size() < count) continue;
        if (settle(index.clearance2(p, ring))) return count;
    }
}

}  // namespace

std::unique_ptr<SpatialIndex> makeGridIndex(const std::vector<int32_t>& grid, int cellShift) {
    static_assert(VertexIndex::kChooseCellSize == -1, "makeGridIndex's default");
    return std::unique_ptr<SpatialIndex>(new GridIndex(grid, cellShift));
}

std::unique_ptr<SpatialIndex> makeSpatialIndex(const std::vector<int32_t>& grid, NeighbourIndex choice,
                                               IndexRole role) {
    return resolveIndex(choice, role) == NeighbourIndex::Flann ? makeFlannIndex(grid) : makeGridIndex(grid);
}

}  // namespace drm
