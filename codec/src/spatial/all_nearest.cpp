#include "spatial/all_nearest.h"

#include <algorithm>
#include <future>
#include <utility>

#include "concurrency.h"
#include "spatial/morton.h"
#include "spatial/morton_order.h"

namespace drm {
namespace {

constexpr int kCoordinateBits = 21;
// Below this many points a second thread costs more than it saves.
constexpr size_t kSplitFromPoints = 16384;

// The points in Morton order of their coordinates: a cell of any power-of-
// two width is then one run, whose key is the point keys >> 3 * shift.
struct SortedPoints {
    std::vector<uint64_t> key;
    std::vector<uint32_t> id;
    std::vector<int32_t> at;  // x, y, z per point, in this order
};

SortedPoints sortByMorton(const std::vector<int32_t>& grid) {
    const size_t n = grid.size() / 3;
    SortedPoints sorted;
    sorted.id = mortonOrder(grid);  // ties (coincident points) by index
    sorted.key.resize(n);
    sorted.at.resize(3 * n);
    for (size_t i = 0; i < n; ++i) {
        const int32_t* p = &grid[3 * size_t(sorted.id[i])];
        sorted.key[i] = mortonKeyOf(p);
        for (int c = 0; c < 3; ++c) sorted.at[3 * i + size_t(c)] = p[c];
    }
    return sorted;
}

int chooseShift(const SortedPoints& sorted, size_t k) {
    // Two neighbours in Morton order share a cell of width 2^s exactly when
    // their keys agree above bit 3s: one pass counts the cells at every width.
    const size_t n = sorted.key.size();
    size_t splitsFrom[kCoordinateBits + 1] = {};  // pairs first split at cell width 2^s
    for (size_t i = 1; i < n; ++i) {
        const uint64_t differ = sorted.key[i] ^ sorted.key[i - 1];
        if (differ == 0) continue;
        const int highest = 63 - __builtin_clzll(differ);
        ++splitsFrom[highest / 3];
    }
    // cells(s) = 1 + the pairs that split at width 2^s or wider.
    size_t cells = 1;
    for (int s = kCoordinateBits; s >= 0; --s) cells += splitsFrom[s];
    // Narrowest first: the first width whose cells hold k / 4 points (at
    // least 2) on average (on a surface the block around a cell then holds
    // about 4k points and a few per cent of the points stay uncertain; at
    // twice the width a block holds four times as many: docs/tuning.md).
    // Distinct positions, not points, count: a stack of coincident points
    // does not make a cell any fuller around the others.
    const size_t perCell = std::max<size_t>(2, k / 4), distinct = cells;
    for (int s = 0; s <= kCoordinateBits; ++s) {
        if (distinct >= perCell * cells) return s;
        cells -= splitsFrom[s];
    }
    return kCoordinateBits;
}

}  // namespace

std::vector<uint32_t> nearestOfEachByCells(const std::vector<int32_t>& grid, size_t k, int cellShift,
                                           std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                                           int threads) {
    const size_t n = grid.size() / 3;
    std::vector<uint32_t> uncertain;
    if (n == 0 || k == 0) return uncertain;
    for (int32_t c : grid)
        if (c < 0 || c >= int32_t(1) << kCoordinateBits) {
            uncertain.resize(n);
            for (size_t v = 0; v < n; ++v) uncertain[v] = uint32_t(v);
            return uncertain;
        }
    const SortedPoints sorted = sortByMorton(grid);
    const int shift = cellShift < 0 ? chooseShift(sorted, k) : std::min(cellShift, kCoordinateBits);
    const int keyShift = 3 * shift;
    auto cellKey = [&](size_t i) { return sorted.key[i] >> keyShift; };  // keyShift <= 63
    // The cells as runs of the sorted points, found by their coordinates
    // through an open-addressing table.
    std::vector<uint32_t> cellStart;
    for (size_t i = 0; i < n; ++i)
        if (i == 0 || cellKey(i) != cellKey(i - 1)) cellStart.push_back(uint32_t(i));
    const size_t cellCount = cellStart.size();
    cellStart.push_back(uint32_t(n));
    const int64_t lastCell = (int64_t(1) << kCoordinateBits >> shift) - 1;
    auto packed = [](int64_t x, int64_t y, int64_t z) { return uint64_t(x) << 42 | uint64_t(y) << 21 | uint64_t(z); };
    size_t tableSize = 16;
    int tableBits = 4;
    while (tableSize < 2 * cellCount) {
        tableSize *= 2;
        ++tableBits;
    }
    std::vector<uint64_t> tableKey(tableSize, ~uint64_t(0));
    std::vector<uint32_t> tableCell(tableSize, 0);
    // The product's top bits, which every bit of the key reaches (the
    // product's bits from 20 up alone never depend on x, the key's bits 42
    // and up: cells sharing y and z would collide and probing would take
    // much of the graph's time).
    auto slotOf = [&](uint64_t key) { return size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - tableBits)); };
    for (size_t c = 0; c < cellCount; ++c) {
        const int32_t* first = &sorted.at[3 * size_t(cellStart[c])];
        const uint64_t key = packed(first[0] >> shift, first[1] >> shift, first[2] >> shift);
        size_t slot = slotOf(key);
        while (tableKey[slot] != ~uint64_t(0)) slot = (slot + 1) & (tableSize - 1);
        tableKey[slot] = key;
        tableCell[slot] = uint32_t(c);
    }
    auto findCell = [&](uint64_t key) -> int64_t {
        for (size_t slot = slotOf(key);; slot = (slot + 1) & (tableSize - 1)) {
            if (tableKey[slot] == key) return tableCell[slot];
            if (tableKey[slot] == ~uint64_t(0)) return -1;
        }
    };

    // The block's cells as runs of the sorted points, read in place (copying
    // them out cost more than the distances). The point's own cell first:
    // its nearest are often there, and once found they keep more of the
    // rest out (a few per cent fewer insertions on igea).
    struct Run {
        uint32_t begin, end;
    };
    const int32_t* const coords = sorted.at.data();
    const uint32_t* const ids = sorted.id.data();
    constexpr uint64_t kFarther = ~uint64_t(0);
    // The 26 other cells' keys less the cell's own, in the order above
    // (modulo 2^64: a step down borrows from the fields above, which the
    // cell's own key pays back).
    uint64_t neighbourOffsets[26];
    size_t offsetCount = 0;
    for (int64_t dx = -1; dx <= 1; ++dx)
        for (int64_t dy = -1; dy <= 1; ++dy)
            for (int64_t dz = -1; dz <= 1; ++dz)
                if (dx != 0 || dy != 0 || dz != 0)
                    neighbourOffsets[offsetCount++] = uint64_t(dx) * (uint64_t(1) << 42) +
                                                      uint64_t(dy) * (uint64_t(1) << 21) + uint64_t(dz);
    // The cells [cellsBegin, cellsEnd): each point's row is its own, so two
    // threads may take two ranges.
    auto searchCells = [&](size_t cellsBegin, size_t cellsEnd, std::vector<uint32_t>& uncertainHere) {
        Run runs[27];
        // The k + 1 nearest so far, each as one sortable key (squared distance
        // above, index below, so that key order is (distance, index) order),
        // kept sorted by insertion: a block holds a few dozen points, most of
        // them farther than the running (k + 1)-th and dismissed by one compare.
        std::vector<uint64_t> slots(k + 1);
        uint64_t* const best = slots.data();
        for (size_t c = cellsBegin; c < cellsEnd; ++c) {
            const int32_t* first = &sorted.at[3 * size_t(cellStart[c])];
            const int64_t cell[3] = {first[0] >> shift, first[1] >> shift, first[2] >> shift};
            size_t runCount = 0;
            runs[runCount++] = {cellStart[c], cellStart[c + 1]};
            auto addCell = [&](uint64_t key) {
                const int64_t found = findCell(key);
                if (found >= 0) runs[runCount++] = {cellStart[size_t(found)], cellStart[size_t(found) + 1]};
            };
            if (cell[0] > 0 && cell[1] > 0 && cell[2] > 0 && cell[0] < lastCell && cell[1] < lastCell &&
                cell[2] < lastCell) {
                // Inside the grid (nearly every cell) no neighbour's field of
                // the packed key under- or overflows into the next: each is the
                // cell's key plus a fixed offset.
                const uint64_t key = packed(cell[0], cell[1], cell[2]);
                for (uint64_t offset : neighbourOffsets) addCell(key + offset);
            } else {
                for (int64_t dx = -1; dx <= 1; ++dx)
                    for (int64_t dy = -1; dy <= 1; ++dy)
                        for (int64_t dz = -1; dz <= 1; ++dz) {
                            if (dx == 0 && dy == 0 && dz == 0) continue;
                            const int64_t x = cell[0] + dx, y = cell[1] + dy, z = cell[2] + dz;
                            if (x < 0 || y < 0 || z < 0 || x > lastCell || y > lastCell || z > lastCell) continue;
                            addCell(packed(x, y, z));
                        }
            }
            const int64_t width = int64_t(1) << shift;
            for (uint32_t i = cellStart[c]; i < cellStart[c + 1]; ++i) {
                const int32_t* p = &sorted.at[3 * size_t(i)];
                const uint32_t self = sorted.id[i];
                // Anything outside the block is at least this far along some
                // axis: one step past the block's faces (none past the grid's).
                int64_t clearance = INT64_MAX;
                for (int a = 0; a < 3; ++a) {
                    if (cell[a] > 0) clearance = std::min(clearance, int64_t(p[a]) - (cell[a] - 1) * width + 1);
                    if (cell[a] < lastCell) clearance = std::min(clearance, (cell[a] + 2) * width - int64_t(p[a]));
                }
                // Only what lies nearer than that can be certain, and keys need
                // the distance below 2^31: a block point at 2^31 or more is left
                // out like one outside the block, and is as surely no nearer
                // than a (k + 1)-th found below the cutoff.
                const int64_t cutoff = clearance >= (int64_t(1) << 16) ? int64_t(1) << 31
                                                                       : std::min(clearance * clearance, int64_t(1) << 31);
                // Every candidate below the cutoff and the (k + 1)-th so far
                // enters; the list starts full of "farther than any" (keys stay
                // below 2^63). Where one enters is a coin toss to a branch
                // predictor, so the insertion has no branch: with the list
                // sorted, entry i becomes max(best[i - 1], min(best[i], key)).
                std::fill(best, best + k + 1, kFarther);
                int64_t bound = cutoff - 1;  // the farthest distance that can still enter
                const int64_t px = p[0], py = p[1], pz = p[2];
                for (size_t r = 0; r < runCount; ++r) {
                    const int32_t* q = coords + 3 * size_t(runs[r].begin);
                    const int32_t* const qEnd = coords + 3 * size_t(runs[r].end);
                    const uint32_t* qId = ids + runs[r].begin;
                    for (; q != qEnd; q += 3, ++qId) {
                        const int64_t ex = q[0] - px, ey = q[1] - py, ez = q[2] - pz;
                        const int64_t d2 = ex * ex + ey * ey + ez * ez;
                        if (d2 > bound) continue;
                        const uint64_t key = uint64_t(d2) << 32 | *qId;
                        if (key >= best[k]) continue;
                        for (size_t i = k; i > 0; --i) best[i] = std::max(best[i - 1], std::min(best[i], key));
                        best[0] = std::min(best[0], key);
                        bound = std::min(bound, int64_t(best[k] >> 32));
                    }
                }
                const size_t kept = size_t(std::find(best, best + k + 1, kFarther) - best);
                // The point itself is among them (distance 0), with k others.
                if (kept <= k) {
                    uncertainHere.push_back(self);
                    continue;
                }
                // The k nearest others: the first k + 1 without the point
                // itself, or the first k if k coincident points of lower
                // index push it out.
                std::remove(best, best + k + 1, uint64_t(self));
                for (size_t j = 0; j < k; ++j) neighbours[size_t(self) * k + j] = uint32_t(best[j]);
                if (distance2)
                    for (size_t j = 0; j < k; ++j) (*distance2)[size_t(self) * k + j] = int64_t(best[j] >> 32);
            }
        }
    };
    // Two threads take the cells holding the first and the second half of
    // the points (the answers are the same).
    if (threads >= 2 && n >= kSplitFromPoints) {
        const size_t middle = size_t(std::upper_bound(cellStart.begin(), cellStart.begin() + ptrdiff_t(cellCount),
                                                      uint32_t(n / 2)) - cellStart.begin());
        std::vector<uint32_t> secondHalf;
        std::future<void> second = startBeside([&] { searchCells(middle, cellCount, secondHalf); });
        searchCells(0, middle, uncertain);
        second.get();
        uncertain.insert(uncertain.end(), secondHalf.begin(), secondHalf.end());
    } else {
        searchCells(0, cellCount, uncertain);
    }
    std::sort(uncertain.begin(), uncertain.end());
    return uncertain;
}

}  // namespace drm
