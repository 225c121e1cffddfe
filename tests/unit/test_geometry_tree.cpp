// The spanning-tree vertex coder on point sets that stress it: few grid
// positions and many coincident points (vertices with dozens of children, so
// the escaped child counts are exercised), every bit depth, single points.
#include <gtest/gtest.h>

#include <random>

#include "drm/drm.h"
#include "geometry_tree.h"

namespace drm {
namespace {

void expectRoundTrip(const std::vector<int32_t>& grid, int bits) {
    const GeometryEncoding encoded = encodeGeometryTree(grid, bits);
    const size_t n = grid.size() / 3;
    ASSERT_EQ(encoded.order.size(), n);
    const std::vector<int32_t> decoded = decodeGeometryTree(encoded.bytes.data(), encoded.bytes.size(), n, bits);
    for (size_t d = 0; d < n; ++d)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(decoded[3 * d + k], grid[3 * size_t(encoded.order[d]) + k]) << "vertex " << d;
    std::vector<int> seen(n, 0);
    for (uint32_t v : encoded.order) ++seen[v];
    for (int s : seen) EXPECT_EQ(s, 1);
}

TEST(GeometryTree, RandomPointsAtEveryBitDepth) {
    std::mt19937 rng(11);
    for (int bits : {1, 2, 3, 5, 8, 12, 16, 21}) {
        for (size_t n : {size_t(1), size_t(2), size_t(7), size_t(300), size_t(2000)}) {
            std::vector<int32_t> grid(3 * n);
            for (int32_t& c : grid) c = int32_t(rng() % (uint32_t(1) << bits));
            expectRoundTrip(grid, bits);
        }
    }
}

TEST(GeometryTree, ManyCoincidentPointsCodeDensely) {
    std::vector<int32_t> grid;
    for (int i = 0; i < 5000; ++i) grid.insert(grid.end(), {3, 1, 2});
    grid.insert(grid.end(), {0, 0, 0});
    expectRoundTrip(grid, 2);
    const GeometryEncoding encoded = encodeGeometryTree(grid, 2);
    EXPECT_LT(encoded.bytes.size(), 200u);  // thousands of vertices in a few bytes: the decoder must accept that
}

TEST(GeometryTree, RefusesCountsNoStreamCouldHold) {
    const std::vector<uint8_t> tiny = {0, 0, 0, 0};
    EXPECT_THROW(decodeGeometryTree(tiny.data(), tiny.size(), uint64_t(1) << 30, 12), Error);
}

}  // namespace
}  // namespace drm
