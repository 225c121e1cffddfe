#include "spatial/candidate_set.h"

#include <algorithm>
#include <cmath>

#include "common.h"
#include "spatial/morton.h"

namespace drm {
namespace {

constexpr int kMaxShift = 26;  // coordinates span less than 2^26 (real grids: 2^21)

// Mean vertices per occupied cell the cell size aims at (the size steps by
// halving, so the occupancy lands within [target / 2, 2 target)). Around an
// edge the predictor looks about two edge lengths away, and the rank's
// nearest candidates come from that same ball: visiting fewer, fuller
// cells costs less than skipping vertices in finer ones (docs/tuning.md).
constexpr uint64_t kTargetOccupancy = 8;
// The occupancy is first counted on a coarse grid of at most 64 cells per
// axis (a 32 KB bitmap); surfaces keep about 4x fewer vertices per cell with
// each halving of the cell size, which sets the final size.
constexpr int kSurveyCellsPerAxisBits = 6;

int64_t floorShift(int64_t v, int s) { return v >= 0 ? v >> s : -((-v - 1) >> s) - 1; }

// The cell size: about kTargetOccupancy vertices per occupied cell. Only
// occupied columns and cells are stored, so a far outlier stretching the box
// costs nothing: the cells still follow the vertices.
int chooseCellShift(const std::vector<int32_t>& grid, int64_t origin, int64_t span) {
    const uint64_t n = grid.size() / 3;
    const int surveyShift = std::max(0, bitLength(uint64_t(span)) - kSurveyCellsPerAxisBits);
    const int64_t perAxis = (span >> surveyShift) + 1;  // <= 64
    std::vector<uint64_t> seen(size_t((perAxis * perAxis * perAxis + 63) / 64), 0);
    uint64_t occupied = 0;
    for (size_t v = 0; v < n; ++v) {
        const int64_t x = (grid[3 * v] - origin) >> surveyShift, y = (grid[3 * v + 1] - origin) >> surveyShift,
                      z = (grid[3 * v + 2] - origin) >> surveyShift;
        const uint64_t bit = uint64_t((x * perAxis + y) * perAxis + z);
        if (!(seen[bit / 64] >> (bit % 64) & 1)) {
            seen[bit / 64] |= uint64_t(1) << (bit % 64);
            ++occupied;
        }
    }
    // Estimated occupancy n / cells, kept within [target/2, 2 target):
    // finer cells while it stays above, coarser while it falls below.
    int shift = surveyShift;
    uint64_t cells = occupied;
    while (shift > 0 && 2 * n >= kTargetOccupancy * cells * 4 && cells * 4 <= n) {
        cells *= 4;
        --shift;
    }
    while (shift < kMaxShift && 2 * n < kTargetOccupancy * cells && cells > 1) {
        cells = (cells + 3) / 4;
        ++shift;
    }
    return shift;
}

}  // namespace

VertexIndex::VertexIndex(const std::vector<int32_t>& grid, int cellShift) {
    const size_t n = grid.size() / 3;
    if (n == 0) return;
    const auto bounds = std::minmax_element(grid.begin(), grid.end());
    origin_ = *bounds.first;
    const int64_t span = int64_t(*bounds.second) - origin_;
    shift_ = cellShift >= 0 ? std::min(cellShift, kMaxShift) : chooseCellShift(grid, origin_, span);
    cellWidth_ = int64_t(1) << shift_;
    lastCell_ = span >> shift_;

    // Columns (x, y) numbered as they are first met, through the hash
    // table; vertices by column (counting sort), then by z within each.
    auto cellOf = [&](int32_t coordinate) { return (int64_t(coordinate) - origin_) >> shift_; };
    columnBits_ = std::max(4, bitLength(2 * uint64_t(n) - 1));  // at least twice the columns: short probes
    columnTable_.assign(size_t(1) << columnBits_, kNoColumn);
    std::vector<uint32_t> columnOfVertex(n);
    std::vector<uint32_t> columnFirst(1, 0);  // vertex counts, then prefix sums
    for (size_t v = 0; v < n; ++v) {
        const uint64_t key = columnKey(cellOf(grid[3 * v]), cellOf(grid[3 * v + 1]));
        uint32_t& column = columnTable_[findColumnSlot(key)];
        if (column == kNoColumn) {
            column = uint32_t(columnKeys_.size());
            columnKeys_.push_back(key);
            columnFirst.push_back(0);
        }
        columnOfVertex[v] = column;
        ++columnFirst[column + 1];
    }
    for (size_t c = 1; c < columnFirst.size(); ++c) columnFirst[c] += columnFirst[c - 1];
    slots_.resize(n);
    {
        std::vector<uint32_t> fill(columnFirst.begin(), columnFirst.end() - 1);
        for (size_t v = 0; v < n; ++v) slots_[fill[columnOfVertex[v]]++] = uint32_t(v);
    }
    auto zCell = [&](uint32_t v) { return int32_t(cellOf(grid[3 * size_t(v) + 2])); };
    columnCells_.resize(columnKeys_.size() + 1);
    for (size_t column = 0; column + 1 < columnFirst.size(); ++column) {
        columnCells_[column] = uint32_t(cellZ_.size());
        const auto begin = slots_.begin() + columnFirst[column], end = slots_.begin() + columnFirst[column + 1];
        std::sort(begin, end, [&](uint32_t a, uint32_t b) { return zCell(a) != zCell(b) ? zCell(a) < zCell(b) : a < b; });
        for (auto it = begin; it != end; ++it)
            if (it == begin || zCell(*it) != zCell(*(it - 1))) {
                cellZ_.push_back(zCell(*it));
                cellStart_.push_back(uint32_t(it - slots_.begin()));
                cellPresent_.push_back(0);
            }
    }
    columnCells_.back() = uint32_t(cellZ_.size());
    // Where the box is not much larger than the surface in cells (no far
    // outlier), a dense table of columns answers without hashing: the
    // searches look up a column per (x, y) they visit, about 25 per query,
    // and a hashed look-up each is a visible share of the decoding time.
    const uint64_t perAxis = uint64_t(lastCell_) + 1;
    if (perAxis <= (uint64_t(1) << 16) && perAxis * perAxis <= 2 * uint64_t(n) + 4096) {
        denseColumns_.assign(size_t(perAxis * perAxis), kNoColumn);
        for (size_t column = 0; column < columnKeys_.size(); ++column) {
            const uint64_t key = columnKeys_[column];
            denseColumns_[size_t((key >> 32) * perAxis + (key & 0xFFFFFFFFu))] = uint32_t(column);
        }
        std::vector<uint32_t>().swap(columnTable_);
    }
    slotOf_.resize(n);
    cellOfVertex_.resize(n);
    cellBoxes_.resize(6 * cellStart_.size());
    for (size_t c = 0; c < cellStart_.size(); ++c) {
        const uint32_t end = c + 1 < cellStart_.size() ? cellStart_[c + 1] : uint32_t(n);
        cellPresent_[c] = end - cellStart_[c];
        int32_t* box = cellBoxes_.data() + 6 * c;
        for (int k = 0; k < 3; ++k) {
            box[k] = INT32_MAX;
            box[3 + k] = INT32_MIN;
        }
        for (uint32_t slot = cellStart_[c]; slot < end; ++slot) {
            slotOf_[slots_[slot]] = slot;
            cellOfVertex_[slots_[slot]] = uint32_t(c);
            for (int k = 0; k < 3; ++k) {
                const int32_t at = grid[3 * size_t(slots_[slot]) + size_t(k)];
                box[k] = std::min(box[k], at);
                box[3 + k] = std::max(box[3 + k], at);
            }
        }
    }
    slotPoints_.resize(3 * n);
    for (size_t slot = 0; slot < n; ++slot)
        for (int k = 0; k < 3; ++k) slotPoints_[3 * slot + size_t(k)] = grid[3 * size_t(slots_[slot]) + size_t(k)];
    present_.resize(n);
    presentSlot_.resize(n);
    for (size_t v = 0; v < n; ++v) present_[v] = presentSlot_[v] = uint32_t(v);
}

void VertexIndex::remove(uint32_t v) {
    if (v >= presentSlot_.size() || presentSlot_[v] == kNotPresent) return;
    // Swap v behind the present vertices of its cell...
    const uint32_t c = cellOfVertex_[v];
    const uint32_t last = cellStart_[c] + --cellPresent_[c];
    const uint32_t other = slots_[last];
    const uint32_t from = slotOf_[v];
    slots_[from] = other;
    slotOf_[other] = from;
    slots_[last] = v;
    slotOf_[v] = last;
    for (size_t k = 0; k < 3; ++k) std::swap(slotPoints_[3 * size_t(from) + k], slotPoints_[3 * size_t(last) + k]);
    // ...and out of the list of all present vertices.
    const uint32_t at = presentSlot_[v], moved = present_.back();
    present_[at] = moved;
    presentSlot_[moved] = at;
    present_.pop_back();
    presentSlot_[v] = kNotPresent;
    if (!nodes_.empty())
        for (uint32_t node = leafOfCell_[c]; node != kNoIndex; node = nodes_[node].parent) --nodes_[node].present;
}

void VertexIndex::buildHierarchy() const {
    // Each cell by its coordinates' Morton key (coordinates cut to 21
    // bits: only the order's locality depends on it), ties by cell.
    const int cut = std::max(0, bitLength(uint64_t(lastCell_)) - 21);
    std::vector<std::pair<uint64_t, uint32_t>> keyed(cellStart_.size());
    for (size_t column = 0; column + 1 < columnCells_.size(); ++column) {
        const uint64_t key = columnKeys_[column];
        const uint64_t x = (key >> 32) >> cut, y = (key & 0xFFFFFFFFu) >> cut;
        for (uint32_t c = columnCells_[column]; c < columnCells_[column + 1]; ++c)
            keyed[c] = {mortonKey(x, y, uint64_t(cellZ_[c]) >> cut), c};
    }
    std::sort(keyed.begin(), keyed.end());
    hierarchyCells_.resize(keyed.size());
    for (size_t i = 0; i < keyed.size(); ++i) hierarchyCells_[i] = keyed[i].second;
    // Halving leaves 4 to 8 cells a leaf (fewer only with fewer cells in all):
    // at most about half as many nodes as cells.
    nodes_.reserve(keyed.size() / 2 + 2);
    leafOfCell_.assign(keyed.size(), kNoIndex);
    buildNode(0, keyed.size(), kNoIndex);
}

uint32_t VertexIndex::buildNode(size_t begin, size_t end, uint32_t parent) const {
    const uint32_t self = uint32_t(nodes_.size());
    nodes_.push_back(Node());
    Node node;
    node.parent = parent;
    node.secondChild = kNoIndex;
    node.cellsBegin = uint32_t(begin);
    node.cellsEnd = uint32_t(end);
    if (end - begin <= kLeafCells) {
        for (int k = 0; k < 3; ++k) {
            node.box[k] = INT32_MAX;
            node.box[3 + k] = INT32_MIN;
        }
        node.present = 0;
        for (size_t i = begin; i < end; ++i) {
            const uint32_t c = hierarchyCells_[i];
            const int32_t* box = cellBoxes_.data() + 6 * size_t(c);
            for (int k = 0; k < 3; ++k) {
                node.box[k] = std::min(node.box[k], box[k]);
                node.box[3 + k] = std::max(node.box[3 + k], box[3 + k]);
            }
            node.present += cellPresent_[c];
            leafOfCell_[c] = self;
        }
    } else {
        const size_t middle = begin + (end - begin) / 2;
        const uint32_t first = buildNode(begin, middle, self);
        node.secondChild = buildNode(middle, end, self);
        const Node &a = nodes_[first], &b = nodes_[node.secondChild];
        for (int k = 0; k < 3; ++k) {
            node.box[k] = std::min(a.box[k], b.box[k]);
            node.box[3 + k] = std::max(a.box[3 + k], b.box[3 + k]);
        }
        node.present = a.present + b.present;
    }
    nodes_[self] = node;
    return self;
}

void VertexIndex::collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const {
    out.clear();
    forEachNear(q, radius, [&out](const uint32_t* ids, const int32_t*, size_t count, const int32_t*) {
        out.insert(out.end(), ids, ids + count);
    });
}

VertexIndex::CellCoord VertexIndex::cellOfPoint(const FixedPoint& p) const {  // p relative to the origin
    const int s = kSubUnitBits + shift_;
    return {floorShift(p.x, s), floorShift(p.y, s), floorShift(p.z, s)};
}

int VertexIndex::firstRing(const FixedPoint& p) const {
    const CellCoord c = cellOfPoint(relative(p));
    int64_t ring = 0;
    for (int64_t x : {c.x, c.y, c.z}) ring = std::max({ring, -x, x - lastCell_});
    return int(std::min<int64_t>(ring, int64_t(1) << 28));  // ringCellCount stays within 64 bits
}

uint64_t VertexIndex::ringCellCount(int ring) {
    return ring == 0 ? 1 : 24 * uint64_t(ring) * uint64_t(ring) + 2;
}

uint64_t VertexIndex::cellBudget() const { return 2 * uint64_t(present_.size()) + 64; }

uint32_t VertexIndex::findHashedColumn(int64_t x, int64_t y) const {
    if (columnTable_.empty()) return kNoColumn;
    return columnTable_[findColumnSlot(columnKey(x, y))];
}

size_t VertexIndex::findColumnSlot(uint64_t key) const {
    const size_t mask = columnTable_.size() - 1;
    size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - columnBits_));
    while (columnTable_[slot] != kNoColumn && columnKeys_[columnTable_[slot]] != key) slot = (slot + 1) & mask;
    return slot;
}

int64_t VertexIndex::clearance2(const FixedPoint& p, int ring) const {
    // A vertex outside the rings has, on some axis, a coordinate at most one
    // below the rings' lowest cell or at least the first cell above them.
    const FixedPoint local = relative(p);
    const CellCoord c = cellOfPoint(local);
    const int64_t width = int64_t(1) << shift_;
    int64_t gap = INT64_MAX;
    const int64_t at[3] = {local.x, local.y, local.z}, cell[3] = {c.x, c.y, c.z};
    for (int k = 0; k < 3; ++k) {
        const int64_t below = ((cell[k] - ring) * width - 1) * kSubUnits;
        const int64_t above = (cell[k] + ring + 1) * width * kSubUnits;
        gap = std::min({gap, at[k] - below, above - at[k]});
    }
    return gap * gap;
}

bool VertexIndex::ringsCoverGrid(const FixedPoint& p, int ring) const {
    const CellCoord c = cellOfPoint(relative(p));
    for (int64_t x : {c.x, c.y, c.z})
        if (x - ring > 0 || x + ring < lastCell_) return false;
    return true;
}

void VertexIndex::collectAll(std::vector<uint32_t>& out) const { out.insert(out.end(), present_.begin(), present_.end()); }

}  // namespace drm
