// exact_math.h: the vector arithmetic of the predictions and the one
// fixed-point distance every search is decided by, against their
// definitions (integer arithmetic where the answer is an integer).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "exact_math.h"

namespace drm {
namespace {

TEST(ExactMath, VectorArithmetic) {
    const Vec3 a{1, 2, 3}, b{-4, 0.5, 8};
    const Vec3 s = a + b, d = a - b, m = a * -2;
    EXPECT_EQ(s.x, -3);
    EXPECT_EQ(s.y, 2.5);
    EXPECT_EQ(s.z, 11);
    EXPECT_EQ(d.x, 5);
    EXPECT_EQ(d.y, 1.5);
    EXPECT_EQ(d.z, -5);
    EXPECT_EQ(m.x, -2);
    EXPECT_EQ(m.z, -6);
    EXPECT_EQ(dot(a, b), -4 + 1 + 24);
    EXPECT_EQ(norm2(a), 14);
    EXPECT_EQ(norm(Vec3{3, 4, 12}), 13);
    EXPECT_EQ(norm(Vec3{}), 0);
}

TEST(ExactMath, RejectFromLeavesTheOrthogonalPart) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> any(-100, 100);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 v{any(rng), any(rng), any(rng)}, e{any(rng), any(rng), any(rng)};
        const Vec3 r = rejectFrom(v, e);
        // Orthogonal to e, up to rounding of the magnitudes involved.
        EXPECT_NEAR(dot(r, e), 0, 1e-9 * norm(v) * norm(e));
        // v = r + (a multiple of e): v - r is parallel to e.
        const Vec3 along = v - r;
        const Vec3 cross{along.y * e.z - along.z * e.y, along.z * e.x - along.x * e.z, along.x * e.y - along.y * e.x};
        EXPECT_NEAR(norm(cross), 0, 1e-9 * norm(v) * norm(e));
    }
    // Exact cases: a vector along an axis rejected from another axis, and
    // from itself; a zero direction leaves v alone.
    const Vec3 r = rejectFrom(Vec3{2, 5, 0}, Vec3{0, 3, 0});
    EXPECT_EQ(r.x, 2);
    EXPECT_EQ(r.y, 0);
    EXPECT_EQ(r.z, 0);
    const Vec3 self = rejectFrom(Vec3{1, 2, 2}, Vec3{1, 2, 2});
    EXPECT_EQ(norm2(self), 0);
    const Vec3 same = rejectFrom(Vec3{1, 2, 3}, Vec3{});
    EXPECT_EQ(same.x, 1);
    EXPECT_EQ(same.y, 2);
    EXPECT_EQ(same.z, 3);
}

TEST(ExactMath, FixedDistanceIsTheSquaredDistanceInSubUnits) {
    EXPECT_EQ(kSubUnits, int64_t(1) << kSubUnitBits);
    const int32_t point[3] = {1, -2, 3};
    // The point itself, in fixed point, is at distance 0.
    EXPECT_EQ(fixedDistance2(point, FixedPoint{kSubUnits, -2 * kSubUnits, 3 * kSubUnits}), 0);
    // Half a step off on one axis: (kSubUnits / 2)^2.
    EXPECT_EQ(fixedDistance2(point, FixedPoint{kSubUnits + kSubUnits / 2, -2 * kSubUnits, 3 * kSubUnits}),
              (kSubUnits / 2) * (kSubUnits / 2));
    std::mt19937 rng(4);
    const int32_t top = (1 << 21) - 1;
    std::uniform_int_distribution<int32_t> coordinate(0, top);
    std::uniform_int_distribution<int64_t> fixed(-int64_t(top) * kSubUnits, 2 * int64_t(top) * kSubUnits);
    for (int i = 0; i < 1000; ++i) {
        const int32_t q[3] = {coordinate(rng), coordinate(rng), coordinate(rng)};
        const FixedPoint p{fixed(rng) / 2, fixed(rng) / 2, fixed(rng) / 2};
        int64_t expected = 0;
        for (int k = 0; k < 3; ++k) {
            const int64_t c = k == 0 ? p.x : k == 1 ? p.y : p.z;
            const int64_t diff = int64_t(q[k]) * kSubUnits - c;
            expected += diff * diff;
        }
        ASSERT_EQ(fixedDistance2(q, p), expected);
    }
    // Grid points a whole grid apart stay exact in 64 bits.
    const int32_t corner[3] = {top, top, top};
    EXPECT_EQ(fixedDistance2(corner, FixedPoint{}), 3 * (int64_t(top) * kSubUnits) * (int64_t(top) * kSubUnits));
}

}  // namespace
}  // namespace drm
