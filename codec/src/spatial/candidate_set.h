// The candidate set: the quantized vertices bucketed into a uniform grid of
// cubic cells, from which culled vertices are removed as the traversal
// closes their fans (the paper's vertex culling).
//
// Every question is answered from the integer grid coordinates, so searches
// need no tolerance. Only occupied cells are stored (a surface occupies a
// vanishing share of a dense cell array), found through a hash table of
// occupied columns; the cell size is chosen from the data so that an occupied cell
// holds a few vertices: the searches around an edge then look at a few
// dozen vertices.
//
// Searches return candidates only: admissibility and the exact order are
// decided by the callers (rank_search, predictor), which is also why the
// cell size can never change a decoded mesh, only the speed.
#ifndef DRM_CANDIDATE_SET_H
#define DRM_CANDIDATE_SET_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "common.h"
#include "exact_math.h"

namespace drm {

class VertexIndex {
public:
    // grid: x, y, z per vertex, spanning less than 2^26 on each axis (real
    // grids: [0, 2^21)), so squared fixed-point distances fit in int64. Cells are
    // 2^cellShift units wide; by default the size suits the data (tests
    // force others: no answer may depend on it).
    static constexpr int kChooseCellSize = -1;
    explicit VertexIndex(const std::vector<int32_t>& grid, int cellShift = kChooseCellSize);

    // Takes v out of every later search. Removing a vertex twice is a no-op.
    void remove(uint32_t v);
    size_t presentCount() const { return present_.size(); }

    // Calls visit(ids, points, count, box) with runs of present vertices
    // (points: their x, y, z, 3 per vertex; box: the lowest and highest x,
    // y, z of the vertices their cell was built with, grid units; all valid
    // until the next remove()) that hold
    // every present vertex whose distance from q is at most radius (grid
    // units), plus possibly some farther ones: callers apply their own exact
    // test.
    template <class Visit>
    void forEachNear(Vec3 q, double radius, Visit visit) const;
    // The same vertices, appended to out (cleared first).
    void collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const;
    // The same vertices, cell by cell, for a caller after the best vertex
    // by some key (SpatialIndex::forEachNearInOrder): the hierarchy's nodes
    // depth first, of two children the one with the lower bound first, the
    // cells of a leaf in Morton order; a node or cell is passed over whole
    // if lowest(box) lies above limit() when it comes to be opened. `box`
    // may be a node's, valid during the call only. Not reentrant (one
    // stack). For balls many cells across (wideBallRadius), where visiting
    // every cell of the box around the ball is most of the cost: on CAD
    // meshes a long edge's ball holds thousands of vertices, of which a
    // few cells matter.
    template <class Lowest, class Limit, class Visit>
    void forEachNearInOrder(Vec3 q, double radius, Lowest lowest, Limit limit, Visit visit) const;
    double wideBallRadius() const { return double(kWideBallCells * cellWidth_); }

    // Rings of cells around a fixed-point location, for exact nearest
    // searches: ring r holds the cells at Chebyshev cell distance r from the
    // cell of p. Every present vertex outside rings 0..r lies at a squared
    // fixed-point distance of at least clearance2(p, r) from p.
    int firstRing(const FixedPoint& p) const;  // rings before it hold no cell of the grid
    // Cells in ring r; once the rings visited add up to more than the
    // budget, scanning every present vertex (collectAll) is cheaper.
    static uint64_t ringCellCount(int ring);
    uint64_t cellBudget() const;
    // Calls visit(first, points, count, box) with the present vertices of
    // each cell of the ring (points: their x, y, z, 3 per vertex, stored
    // with them so that distances need no look-up elsewhere; box: as
    // forEachNear gives it) that has a point within squared fixed-point
    // distance bound2 of p (cells farther away cannot hold anything nearer).
    template <class Visit>
    void forEachCellOfRing(const FixedPoint& p, int ring, int64_t bound2, Visit visit) const;
    int64_t clearance2(const FixedPoint& p, int ring) const;
    bool ringsCoverGrid(const FixedPoint& p, int ring) const;  // rings 0..ring hold every cell
    void collectAll(std::vector<uint32_t>& out) const;         // appends every present vertex

    int cellShift() const { return shift_; }

    // The `count` present vertices nearest p that accept(v) takes, as
    // (distance2(v), v) pairs in increasing order, exactly (ties by index):
    // rings of cells outwards until nothing outside them can come nearer.
    // distance2(v) is v's squared fixed-point distance from p; accept is
    // asked only of vertices that would enter the answer. Meant for a few
    // (each entry is an insertion into a sorted list).
    template <class Distance, class Accept>
    void nearestFew(const FixedPoint& p, size_t count, Distance distance2, Accept accept,
                    std::vector<std::pair<int64_t, uint32_t>>& out, std::vector<uint32_t>& scratch) const;

private:
    struct CellCoord {
        int64_t x, y, z;
    };
    // Cells are counted from the smallest coordinate of the grid.
    FixedPoint relative(const FixedPoint& p) const {
        return {p.x - origin_ * kSubUnits, p.y - origin_ * kSubUnits, p.z - origin_ * kSubUnits};
    }
    CellCoord cellOfPoint(const FixedPoint& p) const;  // p relative to the origin
    // Fixed-point distance from p to the nearest point of cell `cell`
    // along one axis (p relative to the origin).
    int64_t gap(int64_t p, int64_t cell) const {
        const int64_t lo = cell * cellWidth_ * kSubUnits, hi = lo + (cellWidth_ - 1) * kSubUnits;
        return std::max<int64_t>(lo - p, 0) + std::max<int64_t>(p - hi, 0);  // lo <= hi: one at most; no branch
    }
    // Fixed-point distance from p to [lo, hi] (grid units) along one axis.
    static int64_t boxGap(int64_t p, int32_t lo, int32_t hi) {
        const int64_t l = int64_t(lo) * kSubUnits, h = int64_t(hi) * kSubUnits;
        return std::max<int64_t>(l - p, 0) + std::max<int64_t>(p - h, 0);  // as gap
    }
    // Calls visit(ids, points, count, box) for the cells (x, y, z), z0 <= z
    // <= z1 (or only z0 and z1 when capsOnly), within bound2 of p (relative
    // to the origin); box as cellBoxes_ holds it.
    template <class Visit>
    void forEachCellOfColumn(const FixedPoint& p, int64_t x, int64_t y, int64_t z0, int64_t z1, bool capsOnly,
                             int64_t bound2, Visit& visit) const {
        const uint32_t column = findColumn(x, y);
        if (column == kNoColumn) return;
        const int64_t gx = gap(p.x, x), gy = gap(p.y, y), xy2 = gx * gx + gy * gy;
        if (xy2 > bound2) return;
        for (uint32_t c = columnCells_[column], end = columnCells_[column + 1]; c < end; ++c) {
            const int64_t z = cellZ_[c];
            if (z > z1) break;
            if (z < z0 || (capsOnly && z != z0 && z != z1) || cellPresent_[c] == 0) continue;
            // The cell's own box first (cheap), then the box of the
            // vertices it was built with: a surface fills a thin slice of
            // a cell, so this one passes a third fewer cells around a ball.
            const int64_t gz = gap(p.z, z);
            if (xy2 + gz * gz > bound2) continue;
            const int32_t* box = cellBoxes_.data() + 6 * size_t(c);
            const int64_t o = origin_ * kSubUnits;  // the boxes are in grid units, not from the origin
            const int64_t bx = boxGap(p.x + o, box[0], box[3]), by = boxGap(p.y + o, box[1], box[4]),
                          bz = boxGap(p.z + o, box[2], box[5]);
            if (bx * bx + by * by + bz * bz <= bound2)
                visit(slots_.data() + cellStart_[c], slotPoints_.data() + 3 * size_t(cellStart_[c]),
                      size_t(cellPresent_[c]), box);
        }
    }

    // Balls more than this many cells in radius are searched faster
    // through the hierarchy (wideBallRadius; the caller decides): the
    // fewest instructions decoding the CAD mesh cycloidal (docs/tuning.md).
    static constexpr int64_t kWideBallCells = 6;
    // forEachNearInOrder's hierarchy: a binary tree of boxes over the cells
    // taken in Morton order of their coordinates (hierarchyCells_), halved
    // down to kLeafCells cells or fewer, in preorder (a node's first child
    // follows it), each node with the count of present vertices under it,
    // so that culled regions are passed over whole. Made when first asked
    // for (only meshes with long edges ask), then kept up to date by
    // remove(). Leaves of 8 cells: fewer instructions than 2, 4 or 16
    // decoding cycloidal (docs/tuning.md).
    static constexpr size_t kLeafCells = 8;
    struct Node {
        int32_t box[6];       // as cellBoxes_, around every cell under the node
        uint32_t present;     // present vertices under the node
        uint32_t secondChild; // a leaf: kNoIndex (the first child follows the node)
        uint32_t cellsBegin;  // a leaf's cells: hierarchyCells_[cellsBegin, cellsEnd)
        uint32_t cellsEnd;
        uint32_t parent;      // kNoIndex at the root
    };
    void buildHierarchy() const;
    uint32_t buildNode(size_t begin, size_t end, uint32_t parent) const;
    mutable std::vector<Node> nodes_;
    mutable std::vector<uint32_t> hierarchyCells_, leafOfCell_;
    mutable std::vector<std::pair<uint32_t, double>> nodeStack_;

    int shift_ = 0;         // a cell is 2^shift grid units wide
    int64_t cellWidth_ = 1;
    int64_t origin_ = 0;    // the smallest coordinate
    int64_t lastCell_ = -1; // cells per axis - 1
    // Occupied columns (x, y), found through an open-addressing table of
    // their numbers; column i's cells are columnCells_[i] ..
    // columnCells_[i + 1] - 1, by increasing z. Only occupied columns are
    // stored, so the cells can be as fine as the vertices ask whatever the
    // extent of the box.
    static constexpr uint32_t kNoColumn = kNoIndex;
    static uint64_t columnKey(int64_t x, int64_t y) { return (uint64_t(x) << 32) | uint64_t(y); }
    uint32_t findColumn(int64_t x, int64_t y) const {  // kNoColumn if empty or outside
        if (x < 0 || y < 0 || x > lastCell_ || y > lastCell_) return kNoColumn;
        if (!denseColumns_.empty()) return denseColumns_[size_t(x * (lastCell_ + 1) + y)];
        return findHashedColumn(x, y);
    }
    uint32_t findHashedColumn(int64_t x, int64_t y) const;
    size_t findColumnSlot(uint64_t key) const;
    std::vector<uint32_t> columnTable_;
    std::vector<uint32_t> denseColumns_;  // column of (x, y) at x * (lastCell_ + 1) + y, when the box allows
    int columnBits_ = 0;
    std::vector<uint64_t> columnKeys_;
    std::vector<uint32_t> columnCells_;
    std::vector<int32_t> cellZ_;
    // The vertices of cell c are slots_[cellStart_[c] ..
    // cellStart_[c] + cellPresent_[c]): present ones first.
    std::vector<uint32_t> cellStart_, cellPresent_;
    // Per cell, the smallest and largest x, y, z of its vertices (grid
    // units), from all of them: removals leave it larger than it need be,
    // never smaller.
    std::vector<int32_t> cellBoxes_;
    std::vector<uint32_t> slots_, slotOf_, cellOfVertex_;
    std::vector<int32_t> slotPoints_;  // x, y, z of slots_[i] at 3 i: the cells' vertices are read in order
    // Every present vertex, for searches that would visit more cells than
    // there are vertices left.
    std::vector<uint32_t> present_, presentSlot_;
};

template <class Visit>
void VertexIndex::forEachCellOfRing(const FixedPoint& p, int ring, int64_t bound2, Visit visit) const {
    if (present_.empty()) return;
    const FixedPoint local = relative(p);
    const CellCoord c = cellOfPoint(local);
    const int64_t r = ring;
    const int64_t x0 = std::max<int64_t>(c.x - r, 0), x1 = std::min(c.x + r, lastCell_);
    const int64_t y0 = std::max<int64_t>(c.y - r, 0), y1 = std::min(c.y + r, lastCell_);
    for (int64_t x = x0; x <= x1; ++x)
        for (int64_t y = y0; y <= y1; ++y) {
            // Columns on the ring's sides hold all its z; inner ones only
            // the two caps.
            const bool side = x == c.x - r || x == c.x + r || y == c.y - r || y == c.y + r;
            forEachCellOfColumn(local, x, y, c.z - r, c.z + r, !side, bound2, visit);
        }
}

template <class Visit>
void VertexIndex::forEachNear(Vec3 q, double radius, Visit visit) const {
    if (present_.empty()) return;
    auto everything = [&] {
        for (size_t c = 0; c < cellStart_.size(); ++c)
            if (cellPresent_[c] != 0)
                visit(slots_.data() + cellStart_[c], slotPoints_.data() + 3 * size_t(cellStart_[c]),
                      size_t(cellPresent_[c]), cellBoxes_.data() + 6 * c);
    };
    // A box of cells around the ball, one unit wider than it so that float
    // rounding of q and radius cannot drop a vertex on its surface.
    const double reach = radius + 1.0;
    const double top = double(lastCell_ + 1) * double(int64_t(1) << shift_);
    if (!(reach < top) || reach > double(int64_t(1) << 26)) return everything();  // also NaN; squares stay in int64
    int64_t lo[3], hi[3];
    const double center[3] = {q.x - double(origin_), q.y - double(origin_), q.z - double(origin_)};
    int64_t boxCells = 1;
    for (int k = 0; k < 3; ++k) {
        const double a = std::max(center[k] - reach, -1.0), b = std::min(center[k] + reach, top);
        if (!(a <= b)) return;  // the ball misses the grid
        lo[k] = std::max<int64_t>(int64_t(std::floor(a)), 0) >> shift_;
        hi[k] = std::min<int64_t>(int64_t(std::floor(b)) >> shift_, lastCell_);
        if (lo[k] > hi[k]) return;
        boxCells *= hi[k] - lo[k] + 1;
    }
    if (uint64_t(boxCells) > 2 * present_.size() + 64) return everything();
    // The box's corner cells may miss the ball: the cells are tested against
    // it in fixed point, the centre rounded and the radius padded by the
    // unit already added (so rounding cannot drop a vertex).
    const FixedPoint p{int64_t(std::floor(center[0] * kSubUnits + 0.5)), int64_t(std::floor(center[1] * kSubUnits + 0.5)),
                       int64_t(std::floor(center[2] * kSubUnits + 0.5))};  // relative to the origin, as cells are
    const int64_t bound = int64_t(std::ceil(reach * kSubUnits)) + 1;
    for (int64_t x = lo[0]; x <= hi[0]; ++x)
        for (int64_t y = lo[1]; y <= hi[1]; ++y) forEachCellOfColumn(p, x, y, lo[2], hi[2], false, bound * bound, visit);
}

template <class Lowest, class Limit, class Visit>
void VertexIndex::forEachNearInOrder(Vec3 q, double radius, Lowest lowest, Limit limit, Visit visit) const {
    if (present_.empty()) return;
    if (nodes_.empty()) buildHierarchy();
    // As forEachNear: one unit wider than the ball, so that float rounding
    // of q and radius cannot drop a vertex on its surface, and boxes tested
    // in fixed point (integer maxima compile without a branch; the maxima
    // of doubles take one that a branch predictor misses one time in six).
    if (!(q.x == q.x && q.y == q.y && q.z == q.z) || radius < 0) return;  // NaN: the ball misses the grid
    const double reach = radius + 1.0;
    const bool everywhere = !(reach < double(int64_t(1) << 26));  // also NaN
    // The centre relative to the grid's smallest coordinate, brought within
    // 2^28 of it along each axis (the grid spans less than 2^26: every box
    // then lies no farther from it, so more is visited and nothing missed).
    auto fixed = [&](double c) {
        const double far = double(int64_t(1) << 28), local = std::min(std::max(c - double(origin_), -far), far);
        return int64_t(std::floor(local * kSubUnits + 0.5)) + origin_ * kSubUnits;
    };
    const FixedPoint p{fixed(q.x), fixed(q.y), fixed(q.z)};
    const int64_t padded = everywhere ? 0 : int64_t(std::ceil(reach * kSubUnits)) + 1, bound2 = padded * padded;
    // Gaps past the padding are all out of reach alike: capped there,
    // their squares (at most about 2^60 each) stay in int64.
    auto inReach = [&](const int32_t* box) {
        const int64_t gx = std::min(boxGap(p.x, box[0], box[3]), padded + 1),
                      gy = std::min(boxGap(p.y, box[1], box[4]), padded + 1),
                      gz = std::min(boxGap(p.z, box[2], box[5]), padded + 1);
        return everywhere || gx * gx + gy * gy + gz * gz <= bound2;
    };
    // Whether a box's bound lets it be opened (+infinity never does).
    constexpr double kNever = std::numeric_limits<double>::infinity();
    auto open = [&](double key) { return key < kNever && key <= limit(); };
    // A node's bound, or +infinity if it holds nothing in reach.
    auto bound = [&](const Node& node) { return node.present != 0 && inReach(node.box) ? lowest(node.box) : kNever; };
    std::vector<std::pair<uint32_t, double>>& stack = nodeStack_;
    stack.clear();
    stack.emplace_back(0, bound(nodes_[0]));
    while (!stack.empty()) {
        const uint32_t n = stack.back().first;
        const double key = stack.back().second;
        stack.pop_back();
        if (!open(key)) continue;
        const Node& node = nodes_[n];
        if (node.secondChild == kNoIndex) {
            for (uint32_t i = node.cellsBegin; i < node.cellsEnd; ++i) {
                const uint32_t c = hierarchyCells_[i];
                const int32_t* box = cellBoxes_.data() + 6 * size_t(c);
                if (cellPresent_[c] != 0 && inReach(box) && open(lowest(box)))
                    visit(slots_.data() + cellStart_[c], slotPoints_.data() + 3 * size_t(cellStart_[c]),
                          size_t(cellPresent_[c]), box);
            }
            continue;
        }
        // The child with the lower bound is opened first: pushed last.
        const double first = bound(nodes_[n + 1]), second = bound(nodes_[node.secondChild]);
        const bool secondFirst = second < first;
        const std::pair<uint32_t, double> later =
            secondFirst ? std::make_pair(n + 1, first) : std::make_pair(node.secondChild, second);
        const std::pair<uint32_t, double> sooner =
            secondFirst ? std::make_pair(node.secondChild, second) : std::make_pair(n + 1, first);
        if (open(later.second)) stack.push_back(later);
        if (open(sooner.second)) stack.push_back(sooner);
    }
}

template <class Distance, class Accept>
void VertexIndex::nearestFew(const FixedPoint& p, size_t count, Distance distance2, Accept accept,
                             std::vector<std::pair<int64_t, uint32_t>>& out, std::vector<uint32_t>& scratch) const {
    out.clear();
    if (count == 0) return;
    // Once there are `count`, cells and vertices farther than the last are
    // skipped.
    int64_t bound = INT64_MAX;
    auto consider = [&](const std::pair<int64_t, uint32_t>& c) {
        if (c.first > bound || (out.size() == count && !(c < out.back()))) return;
        if (!accept(c.second)) return;
        out.insert(std::upper_bound(out.begin(), out.end(), c), c);
        if (out.size() > count) out.pop_back();
        if (out.size() == count) bound = out.back().first;
    };
    auto visit = [&](const uint32_t* first, const int32_t* points, size_t n, const int32_t*) {
        for (size_t i = 0; i < n; ++i, points += 3) {
            const int64_t d2 = fixedDistance2(points, p);  // from the coordinates stored in the cell
            if (d2 > bound) continue;
            consider({d2, first[i]});
        }
    };
    auto visitIds = [&](const uint32_t* first, size_t n) {
        for (size_t i = 0; i < n; ++i) consider({distance2(first[i]), first[i]});
    };
    uint64_t cellsVisited = 0;
    for (int ring = firstRing(p);; ++ring) {
        cellsVisited += ringCellCount(ring);
        if (cellsVisited > cellBudget()) {  // far from everything left: look at everything
            out.clear();
            bound = INT64_MAX;
            scratch.clear();
            collectAll(scratch);
            visitIds(scratch.data(), scratch.size());
            return;
        }
        forEachCellOfRing(p, ring, bound, visit);
        if (ringsCoverGrid(p, ring)) return;
        if (out.size() == count && clearance2(p, ring) > bound) return;
    }
}

}  // namespace drm

#endif  // DRM_CANDIDATE_SET_H
