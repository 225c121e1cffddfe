// common.h's helpers against their definitions: bitLength is the least n
// with m < 2^n, integerSqrt the floor of the square root exactly (also
// where the double's guess is off), grid points add, subtract and measure
// exact squared distances at the grid's widest extent, and the union-find
// gives the sets of a plain relabelling, joinToLower keeping each set's
// least member as its root.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "common.h"

namespace drm {
namespace {

TEST(Common, NoIndexIsNoValidIndex) {
    EXPECT_EQ(kNoIndex, UINT32_MAX);
    EXPECT_EQ(kNoVertex, kNoIndex);
    EXPECT_EQ(kNotPresent, kNoIndex);
}

TEST(Common, BitLengthIsTheLeastNWithMBelowTwoToTheN) {
    EXPECT_EQ(bitLength(0), 0);
    EXPECT_EQ(bitLength(1), 1);
    EXPECT_EQ(bitLength(5), 3);
    for (int n = 1; n < 64; ++n) {
        const uint64_t power = uint64_t(1) << n;
        EXPECT_EQ(bitLength(power - 1), n) << n;
        EXPECT_EQ(bitLength(power), n + 1) << n;
    }
    EXPECT_EQ(bitLength(UINT64_MAX), 64);
}

TEST(Common, IntegerSqrtIsTheFloorExactly) {
    auto check = [](uint64_t v) {
        const uint64_t r = integerSqrt(v);
        ASSERT_LE(r * r, v) << v;
        ASSERT_GT((r + 1) * (r + 1), v) << v;
    };
    for (uint64_t v = 0; v < 100000; ++v) check(v);
    // Around squares of large roots, where a double cannot hold v exactly.
    for (uint64_t r : {uint64_t(94906265), uint64_t(1) << 30, (uint64_t(1) << 31) - 1, (uint64_t(1) << 31) + 12345}) {
        for (int64_t d = -3; d <= 3; ++d) check(r * r + uint64_t(d));
        EXPECT_EQ(integerSqrt(r * r), r);
        EXPECT_EQ(integerSqrt(r * r - 1), r - 1);
    }
    std::mt19937_64 rng(1);
    for (int i = 0; i < 100000; ++i) check(rng() >> 2);  // below 2^62
}

TEST(Common, GridPointsAddSubtractAndMeasureExactly) {
    const GridPoint a{1, -2, 3}, b{10, 20, -30};
    const GridPoint s = a + b, d = b - a;
    EXPECT_EQ(s.x, 11);
    EXPECT_EQ(s.y, 18);
    EXPECT_EQ(s.z, -27);
    EXPECT_EQ(d.x, 9);
    EXPECT_EQ(d.y, 22);
    EXPECT_EQ(d.z, -33);
    EXPECT_EQ(distance2(a, b), 9 * 9 + 22 * 22 + 33 * 33);
    EXPECT_EQ(distance2(b, a), distance2(a, b));
    EXPECT_EQ(distance2(a, a), 0);
    // The far corners of the 21-bit grid: 3 (2^21 - 1)^2, past 32 bits.
    const int32_t top = (1 << 21) - 1;
    EXPECT_EQ(distance2(GridPoint{0, 0, 0}, GridPoint{top, top, top}), 3 * int64_t(top) * top);
    const std::vector<int32_t> grid = {0, 0, 0, 4, 5, 6, -7, 8, -9};
    const GridPoint p = gridPointOf(grid, 2);
    EXPECT_EQ(p.x, -7);
    EXPECT_EQ(p.y, 8);
    EXPECT_EQ(p.z, -9);
}

TEST(Common, UnionFindGivesTheSetsOfAPlainRelabelling) {
    std::mt19937 rng(2);
    for (int trial = 0; trial < 20; ++trial) {
        const uint32_t n = 1 + rng() % 200;
        UnionFind sets(n), lowest(n);
        std::vector<uint32_t> label(n);
        for (uint32_t v = 0; v < n; ++v) label[v] = v;
        for (int j = 0; j < int(n); ++j) {
            const uint32_t a = rng() % n, b = rng() % n;
            const bool separate = label[a] != label[b];
            EXPECT_EQ(sets.join(a, b), separate);
            lowest.joinToLower(a, b);
            if (separate) {
                const uint32_t from = label[a], to = label[b];
                for (uint32_t& l : label)
                    if (l == from) l = to;
            }
        }
        for (uint32_t v = 0; v < n; ++v) {
            for (uint32_t w = 0; w < n; ++w) ASSERT_EQ(sets.root(v) == sets.root(w), label[v] == label[w]);
            // joinToLower: the root is the least member of v's set.
            uint32_t least = v;
            for (uint32_t w = 0; w < n; ++w)
                if (label[w] == label[v] && w < least) least = w;
            ASSERT_EQ(lowest.root(v), least);
        }
    }
}

TEST(Common, JoinPutsTheFirstSetUnderTheSecondsRoot) {
    UnionFind sets(4);
    EXPECT_TRUE(sets.join(0, 1));
    EXPECT_EQ(sets.root(0), 1u);
    EXPECT_TRUE(sets.join(2, 0));
    EXPECT_EQ(sets.root(2), 1u);
    EXPECT_FALSE(sets.join(1, 2));
    EXPECT_EQ(sets.root(3), 3u);
}

}  // namespace
}  // namespace drm
