// SeamSide (connectivity/seam_side.h), the one test of which edges lie on a
// part's seam side: in part 1, edges whose two ends are both at or past
// the split; in part 2, edges whose snapped prediction lies, on the grid,
// at a Morton key below part 2's first vertex (part 1's region), the
// prediction clamped to the grid first; and a whole mesh has no seam side.
#include <gtest/gtest.h>

#include <cstdint>

#include "connectivity/seam_side.h"
#include "spatial/morton.h"

namespace drm {
namespace {

// The fixed-point prediction at grid point (x, y, z), plus `sub` sixteenths.
FixedPoint at(int64_t x, int64_t y, int64_t z, int64_t sub = 0) {
    return {x * kSubUnits + sub, y * kSubUnits + sub, z * kSubUnits + sub};
}

TEST(SeamSide, AWholeMeshHasNone) {
    const SeamSide none;
    EXPECT_FALSE(none.contains(OpenEdge{0, 1, 2}, at(0, 0, 0)));
    EXPECT_FALSE(none.contains(OpenEdge{0xFFFFFFF0u, 0xFFFFFFF1u, 2}, at(5, 5, 5)));
}

TEST(SeamSide, PartOneEdgesWithBothEndsPastTheSplit) {
    SeamSide first;
    first.seam = 100;
    EXPECT_TRUE(first.contains(OpenEdge{100, 101, 3}, at(0, 0, 0)));
    EXPECT_TRUE(first.contains(OpenEdge{250, 100, 3}, at(0, 0, 0)));
    EXPECT_FALSE(first.contains(OpenEdge{99, 101, 3}, at(0, 0, 0)));
    EXPECT_FALSE(first.contains(OpenEdge{101, 99, 100}, at(0, 0, 0)));
    // Part 1 never asks the prediction.
    first.secondPart = true;
    first.bits = 4;
    first.firstPartBelow = ~uint64_t(0);
    EXPECT_FALSE(first.contains(OpenEdge{1, 2, 3}, at(0, 0, 0)));
}

TEST(SeamSide, PartTwoPredictionsBelowItsFirstKey) {
    SeamSide second;
    second.secondPart = true;
    second.bits = 4;  // grid points 0..15
    second.firstPartBelow = mortonKey(2, 2, 2);
    const OpenEdge edge{7, 8, 9};
    EXPECT_TRUE(second.contains(edge, at(1, 1, 1)));
    EXPECT_TRUE(second.contains(edge, at(0, 0, 3)));  // key 0b100100 = 36 < 56
    EXPECT_FALSE(second.contains(edge, at(2, 2, 2)));  // the key itself is part 2's
    EXPECT_FALSE(second.contains(edge, at(3, 3, 3)));
    EXPECT_FALSE(second.contains(edge, at(0, 0, 4)));  // key 256
    // Sixteenths below the next grid point still snap down to this one.
    EXPECT_TRUE(second.contains(edge, at(1, 1, 1, kSubUnits - 1)));
    EXPECT_FALSE(second.contains(edge, at(2, 2, 2, kSubUnits - 1)));
    // Outside the grid, each coordinate is clamped: below 0 to 0, past the
    // top to 15.
    EXPECT_TRUE(second.contains(edge, at(-5, -1, -1000)));
    EXPECT_FALSE(second.contains(edge, at(1, 1, 16)));
    EXPECT_FALSE(second.contains(edge, at(99, 99, 99)));
    second.firstPartBelow = mortonKey(15, 15, 15) + 1;  // everything lies below
    EXPECT_TRUE(second.contains(edge, at(1000, 1000, 1000)));
}

}  // namespace
}  // namespace drm
