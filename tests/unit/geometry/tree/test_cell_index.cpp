// The tree coder's cell index (geometry/tree/cell_index.h) against brute
// force: CellHeads keeps every key's head like a std::map through growth;
// DecodedCells::nearest gives the kNearest smallest squared distances
// among the vertices of the 2 x 2 x 2 block of cells around the point (its
// own cell and, on each axis, the neighbour on its nearer side), never the
// vertex itself and nothing off the grid; equally near vertices come own
// cell first, then each cell's latest first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "common.h"
#include "geometry/tree/cell_index.h"

namespace drm {
namespace {

TEST(CellHeads, AgreesWithAMapThroughGrowth) {
    std::mt19937_64 rng(10);
    CellHeads heads;
    std::map<uint64_t, uint32_t> expected;
    EXPECT_EQ(heads.get(5), kNoVertex);  // an empty table
    for (uint32_t i = 0; i < 20000; ++i) {
        // Keys on a few y, z rows with many x (cells along a line collide
        // in a poor hash), and keys anywhere in 63 bits.
        const uint64_t key = i % 2 ? (uint64_t(rng() % 300) << 42) | (rng() % 3) : rng() >> 1;
        uint32_t& head = heads.at(key);
        if (!expected.count(key)) EXPECT_EQ(head, kNoVertex);  // inserted as "none"
        head = i;
        expected[key] = i;
        if (i % 1000 == 0)
            for (const auto& e : expected) ASSERT_EQ(heads.get(e.first), e.second);
    }
    for (const auto& e : expected) ASSERT_EQ(heads.get(e.first), e.second);
    for (int i = 0; i < 1000; ++i) {
        const uint64_t key = rng() >> 1;
        if (!expected.count(key)) ASSERT_EQ(heads.get(key), kNoVertex);
    }
}

// The block of cells nearest() searches: per axis the own cell and the
// neighbour on the nearer side of `at` (below when at lies in the lower half
// of its cell).
bool inBlock(GridPoint p, GridPoint at, int cellBits) {
    const int32_t side = int32_t(1) << cellBits;
    const int32_t pc[3] = {p.x >> cellBits, p.y >> cellBits, p.z >> cellBits};
    const int32_t ac[3] = {at.x >> cellBits, at.y >> cellBits, at.z >> cellBits};
    const int32_t ao[3] = {at.x & (side - 1), at.y & (side - 1), at.z & (side - 1)};
    for (int a = 0; a < 3; ++a) {
        const int32_t neighbour = ao[a] < side / 2 ? ac[a] - 1 : ac[a] + 1;
        if (pc[a] != ac[a] && pc[a] != neighbour) return false;
    }
    return true;
}

TEST(DecodedCells, NearestAreTheNearestOfTheBlock) {
    std::mt19937 rng(11);
    for (int cellBits : {0, 2, 4, 6, 10}) {
        SCOPED_TRACE("cell bits " + std::to_string(cellBits));
        DecodedCells cells(cellBits);
        std::vector<GridPoint> points;
        std::uniform_int_distribution<int32_t> coordinate(0, 255);
        for (uint32_t v = 0; v < 1500; ++v) {
            GridPoint p{coordinate(rng), coordinate(rng), coordinate(rng) / 8};  // a slab: many near points
            if (v % 7 == 3) p = points[rng() % points.size()];                  // coincident points
            if (v % 13 == 5) p = GridPoint{p.x % 4, p.y % 4, 0};                // near the grid's low corner
            points.push_back(p);
            cells.insert(v, p);
            // Query every few insertions: at a decoded vertex (itself left
            // out) and at a point not decoded.
            if (v % 5 != 0) continue;
            for (int q = 0; q < 2; ++q) {
                const uint32_t self = q == 0 ? uint32_t(rng() % points.size()) : kNoVertex;
                const GridPoint at = q == 0 ? points[self] : GridPoint{coordinate(rng), coordinate(rng), coordinate(rng) / 8};
                std::vector<int64_t> brute;
                for (uint32_t w = 0; w < points.size(); ++w)
                    if (w != self && inBlock(points[w], at, cellBits)) brute.push_back(distance2(points[w], at));
                std::sort(brute.begin(), brute.end());
                if (brute.size() > size_t(kNearest)) brute.resize(kNearest);
                GridPoint near[kNearest];
                int64_t nearD2[kNearest];
                const int count = cells.nearest(self, at, near, nearD2);
                ASSERT_EQ(size_t(count), brute.size());
                for (int i = 0; i < count; ++i) {
                    ASSERT_EQ(nearD2[i], brute[size_t(i)]) << "entry " << i;
                    ASSERT_EQ(distance2(near[i], at), nearD2[i]);
                    ASSERT_TRUE(inBlock(near[i], at, cellBits));
                }
            }
        }
    }
}

bool same(GridPoint a, GridPoint b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

TEST(DecodedCells, TiesGoToTheOwnCellThenTheLatest) {
    // One cell of side 16: (7, 8, 8) then (9, 8, 8), both 1 from (8, 8, 8):
    // the latest comes first.
    DecodedCells one(4);
    one.insert(0, GridPoint{7, 8, 8});
    one.insert(1, GridPoint{9, 8, 8});
    GridPoint near[kNearest];
    int64_t d2[kNearest];
    ASSERT_EQ(one.nearest(kNoVertex, GridPoint{8, 8, 8}, near, d2), 2);
    EXPECT_TRUE(same(near[0], GridPoint{9, 8, 8}));
    EXPECT_TRUE(same(near[1], GridPoint{7, 8, 8}));
    // Across cells: from (15, 5, 5) the point 1 below lies in the own cell,
    // the point 1 above in the next; the own cell's comes first, whichever
    // was decoded last.
    for (bool ownLast : {false, true}) {
        DecodedCells two(4);
        const GridPoint own{14, 5, 5}, next{16, 5, 5};
        two.insert(0, ownLast ? next : own);
        two.insert(1, ownLast ? own : next);
        ASSERT_EQ(two.nearest(kNoVertex, GridPoint{15, 5, 5}, near, d2), 2);
        EXPECT_TRUE(same(near[0], own));
        EXPECT_TRUE(same(near[1], next));
        EXPECT_EQ(d2[0], 1);
        EXPECT_EQ(d2[1], 1);
    }
}

TEST(DecodedCells, VerticesInsertedOutOfOrderAreFound) {
    DecodedCells cells(3);
    cells.insert(5, GridPoint{1, 1, 1});
    cells.insert(2, GridPoint{2, 1, 1});
    cells.insert(9, GridPoint{1, 3, 1});
    GridPoint near[kNearest];
    int64_t d2[kNearest];
    ASSERT_EQ(cells.nearest(5, GridPoint{1, 1, 1}, near, d2), 2);  // vertex 5 itself left out
    EXPECT_TRUE(same(near[0], GridPoint{2, 1, 1}));
    EXPECT_EQ(d2[1], 4);
    EXPECT_EQ(cells.cellBits(), 3);
}

}  // namespace
}  // namespace drm
