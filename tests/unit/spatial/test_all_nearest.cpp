// nearestOfEachByCells (spatial/all_nearest.h), the batch search of every
// point's k nearest others by cells, against brute force on the exact
// integer definition (squared distance, ties by index): every point it
// certifies has exactly its nearest at every cell width, far points never
// wrong a certified one, and two threads give what one gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "spatial/all_nearest.h"
#include "spatial/spatial_index.h"
#include "tiny_ply.h"

namespace drm {
namespace {

// The batch search by cells, on its own: every point it certifies has
// exactly its k nearest others (ties by index), at every cell width, on a
// sampled surface with coincident points (stacks of up to 12, so that a
// point's own entry can fall out of the first k + 1) and far outliers;
// the points it leaves uncertain keep their rows untouched. At the width it
// picks itself, a scan's vertices leave few points uncertain (the speed it
// is for).
TEST(AllNearest, CertifiedPointsHaveExactlyTheirNearestAtEveryCellWidth) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    std::vector<int32_t> grid;
    for (int i = 0; i < 1500; ++i) {  // a sphere of radius 1000 around (2000, 2000, 2000)
        const double a = angle(rng), b = angle(rng) / 2;
        for (double c : {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)})
            grid.push_back(int32_t(std::lround(2000 + 1000 * c)));
        if (i % 50 == 0)
            for (int copy = 0; copy < 1 + i % 12; ++copy) grid.insert(grid.end(), grid.end() - 3, grid.end());
    }
    grid.insert(grid.end(), {0, 0, 0, 4095, 4095, 4095, 4095, 0, 17});
    const size_t n = grid.size() / 3;
    for (size_t k : {size_t(1), size_t(8)}) {
        std::vector<std::vector<RankedVertex>> expected(n);
        for (uint32_t v = 0; v < n; ++v) {
            for (uint32_t w = 0; w < n; ++w)
                if (w != v) expected[v].emplace_back(fixedDistance2(grid, fixedPointOf(grid, v), w) / (kSubUnits * kSubUnits), w);
            std::sort(expected[v].begin(), expected[v].end());
            expected[v].resize(k);
        }
        for (int shift : {-1, 0, 3, 5, 7, 9, 12, 21}) {
            SCOPED_TRACE("k " + std::to_string(k) + " cell shift " + std::to_string(shift));
            std::vector<uint32_t> neighbours(n * k, 12345);
            std::vector<int64_t> distance2(n * k, -1);
            const std::vector<uint32_t> uncertain = nearestOfEachByCells(grid, k, shift, neighbours, &distance2);
            ASSERT_TRUE(std::is_sorted(uncertain.begin(), uncertain.end()));
            for (uint32_t v = 0; v < n; ++v) {
                const bool certain = !std::binary_search(uncertain.begin(), uncertain.end(), v);
                for (size_t j = 0; j < k; ++j) {
                    if (certain) {
                        ASSERT_EQ(neighbours[v * k + j], expected[v][j].second) << "vertex " << v << " neighbour " << j;
                        ASSERT_EQ(distance2[v * k + j], expected[v][j].first);
                    } else {
                        ASSERT_EQ(neighbours[v * k + j], 12345u);
                        ASSERT_EQ(distance2[v * k + j], -1);
                    }
                }
            }
            if (shift == 21) EXPECT_TRUE(uncertain.empty());  // one cell: the whole grid is every point's block
        }
    }
    // On a scan's vertices, at the width it picks, the batch leaves a
    // minority of points to the one-by-one search (bunny-lres, 2,583
    // vertices at 12 bits: 20 %; on the corpus horse 5 %, igea 0.7 %).
    const drm::Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    float low = bunny.positions[0], high = bunny.positions[0];
    for (float c : bunny.positions) low = std::min(low, c), high = std::max(high, c);
    std::vector<int32_t> scan(bunny.positions.size());
    for (size_t i = 0; i < scan.size(); ++i) scan[i] = int32_t(std::lround((bunny.positions[i] - low) * 4095.0 / (high - low)));
    std::vector<uint32_t> scanNeighbours(scan.size() / 3 * 8);
    std::vector<int64_t> scanDistance2(scanNeighbours.size());
    const size_t left = nearestOfEachByCells(scan, 8, -1, scanNeighbours, &scanDistance2).size();
    EXPECT_LT(double(left), 0.25 * double(scan.size() / 3)) << left << " of " << scan.size() / 3;
    // Outside [0, 2^21) nothing is certified.
    std::vector<int32_t> negative = {-1, 0, 0, 5, 5, 5, 6, 6, 6};
    std::vector<uint32_t> neighbours(3, kNoVertex);
    std::vector<int64_t> distance2(3, 0);
    EXPECT_EQ(nearestOfEachByCells(negative, 1, -1, neighbours, &distance2).size(), 3u);
}

// Squared distances of 2^31 or more do not fit the batch's sort keys: such
// block points are left out like points outside the block, which still
// certifies a point whose k + 1 nearest (itself included) all lie nearer,
// and no point whose k-th does not. Two clusters at opposite corners of the
// 2^21 grid, a lone point between them, and one cell holding all of them.
TEST(AllNearest, FarBlockPointsNeverEnterAndNeverWrongACertifiedPoint) {
    const int32_t top = (1 << 21) - 1;
    std::vector<int32_t> grid;
    for (int i = 0; i < 12; ++i) grid.insert(grid.end(), {i % 3, i / 3, i % 2});
    for (int i = 0; i < 12; ++i) grid.insert(grid.end(), {top - i % 3, top - i / 3, top - i % 2});
    grid.insert(grid.end(), {top / 2, top / 2, top / 2});
    const size_t n = grid.size() / 3, k = 8;
    std::vector<uint32_t> neighbours(n * k, 12345);
    std::vector<int64_t> distance2(n * k, -1);
    const std::vector<uint32_t> uncertain = nearestOfEachByCells(grid, k, 21, neighbours, &distance2);
    EXPECT_EQ(uncertain, std::vector<uint32_t>{uint32_t(n - 1)});  // only the lone point's neighbours are all far
    for (uint32_t v = 0; v + 1 < n; ++v) {
        std::vector<RankedVertex> expected;
        for (uint32_t w = 0; w < n; ++w)
            if (w != v) expected.emplace_back(fixedDistance2(grid, fixedPointOf(grid, v), w) / (kSubUnits * kSubUnits), w);
        std::sort(expected.begin(), expected.end());
        for (size_t j = 0; j < k; ++j) {
            ASSERT_EQ(neighbours[v * k + j], expected[j].second) << "vertex " << v << " neighbour " << j;
            ASSERT_EQ(distance2[v * k + j], expected[j].first);
        }
    }
}

// Two threads split the cells between them (from kSplitFromPoints points
// on): every row and the uncertain list are what one thread gives. A sphere
// of 30,000 points with clusters of coincident copies (ties by index across
// the split) and a few far outliers (uncertain points on both sides).
TEST(AllNearest, TwoThreadsGiveWhatOneGives) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    std::vector<int32_t> grid;
    for (int i = 0; i < 30000; ++i) {
        const double a = angle(rng), b = angle(rng) / 2;
        for (double c : {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)})
            grid.push_back(int32_t(std::lround(40000 + 30000 * c)));
        if (i % 997 == 0)
            for (int copy = 0; copy < 9; ++copy) grid.insert(grid.end(), grid.end() - 3, grid.end());
    }
    grid.insert(grid.end(), {0, 0, 0, 90000, 3, 7, 5, 90000, 11});
    const size_t n = grid.size() / 3, k = 8;
    std::vector<uint32_t> oneNeighbours(n * k, 12345), twoNeighbours(n * k, 12345);
    std::vector<int64_t> oneDistance2(n * k, -1), twoDistance2(n * k, -1);
    const std::vector<uint32_t> oneUncertain = nearestOfEachByCells(grid, k, -1, oneNeighbours, &oneDistance2, 1);
    const std::vector<uint32_t> twoUncertain = nearestOfEachByCells(grid, k, -1, twoNeighbours, &twoDistance2, 2);
    EXPECT_FALSE(oneUncertain.empty());  // the outliers at least
    EXPECT_EQ(twoUncertain, oneUncertain);
    EXPECT_EQ(twoNeighbours, oneNeighbours);
    EXPECT_EQ(twoDistance2, oneDistance2);
    EXPECT_LT(double(oneUncertain.size()), 0.5 * double(n));  // most rows were filled, so compared
}

}  // namespace
}  // namespace drm
