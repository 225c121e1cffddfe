// The vertex coder's local frame: an integer rotation that must
// give back every vector exactly, and must actually turn the normal onto
// the third axis (else it would code nothing better).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/tree/local_frame.h"

namespace drm {
namespace {

// Into the frame and back out, or (outward) out and back in: what a
// corrupt file makes the decoder take out of the frame must go back exactly.
void expectExactRoundTrip(const LocalFrame& frame, int64_t x, int64_t y, int64_t z, bool outward = false) {
    int64_t v[3] = {x, y, z};
    if (outward) {
        frame.fromFrame(v);
        frame.toFrame(v);
    } else {
        frame.toFrame(v);
        frame.fromFrame(v);
    }
    EXPECT_EQ(v[0], x);
    EXPECT_EQ(v[1], y);
    EXPECT_EQ(v[2], z);
}

// The normal, rotated, lies along the third axis to within the rounding
// of the shears (a few units on vectors of length 2^20), its length kept.
void expectNormalOntoThirdAxis(int64_t nx, int64_t ny, int64_t nz) {
    SCOPED_TRACE(std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz));
    const LocalFrame frame(nx, ny, nz);
    const double length = std::sqrt(double(nx) * nx + double(ny) * ny + double(nz) * nz);
    const double scale = double(1 << 20) / length;
    int64_t v[3] = {int64_t(std::llround(nx * scale)), int64_t(std::llround(ny * scale)), int64_t(std::llround(nz * scale))};
    frame.toFrame(v);
    EXPECT_LE(std::abs(v[0]), 64);
    EXPECT_LE(std::abs(v[1]), 64);
    EXPECT_NEAR(double(v[2]), double(1 << 20), 64.0);
}

TEST(LocalFrame, EveryVectorComesBackExactly) {
    std::mt19937_64 random(7);
    std::uniform_int_distribution<int64_t> normal(-(int64_t(1) << 46), int64_t(1) << 46);
    std::uniform_int_distribution<int64_t> small(-40, 40);
    std::uniform_int_distribution<int64_t> residual(-(int64_t(1) << 22), int64_t(1) << 22);
    for (int f = 0; f < 2000; ++f) {
        // Random normals, and ones near the axes and the half-turn cases.
        const bool nearAxes = f % 2 == 1;
        const LocalFrame frame = nearAxes ? LocalFrame(small(random), small(random), small(random))
                                          : LocalFrame(normal(random), normal(random), normal(random));
        for (int k = 0; k < 50; ++k) expectExactRoundTrip(frame, residual(random), residual(random), residual(random));
        for (int k = 0; k < 20; ++k)
            expectExactRoundTrip(frame, residual(random) * 2, residual(random) * 2, residual(random) * 2, true);
        for (int64_t x = -2; x <= 2; ++x)
            for (int64_t y = -2; y <= 2; ++y)
                for (int64_t z = -2; z <= 2; ++z) expectExactRoundTrip(frame, x, y, z);
    }
}

TEST(LocalFrame, TurnsTheNormalOntoTheThirdAxis) {
    for (int64_t nx : {-5, -1, 0, 1, 3})
        for (int64_t ny : {-4, 0, 1, 7})
            for (int64_t nz : {-9, -1, 0, 2, 6}) {
                if (nx == 0 && ny == 0 && nz == 0) continue;
                expectNormalOntoThirdAxis(nx, ny, nz);
            }
    expectNormalOntoThirdAxis(int64_t(1) << 45, -(int64_t(1) << 44), 12345);  // scaled down to 20 bits first
    expectNormalOntoThirdAxis(-1000000, -1, -1);                             // nearly a half turn
}

TEST(LocalFrame, AxisNormalsAndNoNormalLeaveTheGridAlone) {
    // A normal up the third axis, or none at all: the identity, so
    // residuals keep their zero components.
    for (const LocalFrame& frame : {LocalFrame(), LocalFrame(0, 0, 5), LocalFrame(0, 0, 0)}) {
        int64_t v[3] = {17, 0, -3};
        frame.toFrame(v);
        EXPECT_EQ(v[0], 17);
        EXPECT_EQ(v[1], 0);
        EXPECT_EQ(v[2], -3);
    }
    // Down the third axis: a half turn in the (z, x) plane, exact.
    int64_t down[3] = {17, 0, -3};
    LocalFrame(0, 0, -5).toFrame(down);
    EXPECT_EQ(down[0], -17);
    EXPECT_EQ(down[1], 0);
    EXPECT_EQ(down[2], 3);
    // Along the first axis: an exact quarter turn, x onto z (the normal
    // becomes the third axis) and z onto -x.
    int64_t v[3] = {0, 4, 11};
    LocalFrame(9, 0, 0).toFrame(v);
    EXPECT_EQ(v[0], -11);
    EXPECT_EQ(v[1], 4);
    EXPECT_EQ(v[2], 0);
    int64_t w[3] = {7, 0, 0};
    LocalFrame(9, 0, 0).toFrame(w);
    EXPECT_EQ(w[0], 0);
    EXPECT_EQ(w[2], 7);
}

// The frame turned about its normal: the tangent part of the
// direction it is given then lies along the positive first axis, the normal
// stays the third axis, and every vector still comes back exactly.
TEST(LocalFrame, TurnsAboutTheNormalOntoAGivenDirection) {
    std::mt19937_64 random(11);
    std::uniform_int_distribution<int64_t> coordinate(-(int64_t(1) << 30), int64_t(1) << 30);
    std::uniform_int_distribution<int64_t> small(-40, 40);
    std::uniform_int_distribution<int64_t> residual(-(int64_t(1) << 22), int64_t(1) << 22);
    for (int f = 0; f < 500; ++f) {
        const bool tiny = f % 2 == 1;  // short directions are scaled up to 20 bits first
        const auto pick = [&] { return tiny ? small(random) : coordinate(random); };
        const double n[3] = {double(pick()), double(pick()), double(pick())};
        const double d[3] = {double(pick()), double(pick()), double(pick())};
        LocalFrame frame{int64_t(n[0]), int64_t(n[1]), int64_t(n[2])};
        frame.alignFirstAxis(int64_t(d[0]), int64_t(d[1]), int64_t(d[2]));
        for (int k = 0; k < 20; ++k) expectExactRoundTrip(frame, residual(random), residual(random), residual(random));
        for (int k = 0; k < 10; ++k) expectExactRoundTrip(frame, residual(random), residual(random), residual(random), true);
        // d's part in the tangent plane, at 2^20, turned: along +x.
        const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (nn == 0) continue;
        const double along = (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / nn;
        const double t[3] = {d[0] - along * n[0], d[1] - along * n[1], d[2] - along * n[2]};
        const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        const double dLength = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (length <= 0.05 * dLength) continue;  // nearly along the normal (or zero): any turn will do
        int64_t v[3];
        for (int a = 0; a < 3; ++a) v[a] = int64_t(std::llround(t[a] * double(1 << 20) / length));
        frame.toFrame(v);
        SCOPED_TRACE(f);
        // The normal's and the direction's 20-bit roundings and the shears'
        // 16-bit slopes tilt the frame by a few units at this length.
        EXPECT_NEAR(double(v[0]), double(1 << 20), 64.0);
        EXPECT_LE(std::abs(v[1]), 96);
        EXPECT_LE(std::abs(v[2]), 96);
    }
    // No normal: the identity, whatever the direction.
    LocalFrame none;
    none.alignFirstAxis(3, -5, 7);
    int64_t v[3] = {17, 0, -3};
    none.toFrame(v);
    EXPECT_EQ(v[0], 17);
    EXPECT_EQ(v[1], 0);
    EXPECT_EQ(v[2], -3);
    // A normal up the third axis and a direction along -y: a quarter turn
    // about z (shears of slope -1 and 1), exact: -y onto +x.
    LocalFrame up(0, 0, 5);
    up.alignFirstAxis(0, -9, 4);
    int64_t w[3] = {0, -6, 2};
    up.toFrame(w);
    EXPECT_EQ(w[0], 6);
    EXPECT_EQ(w[1], 0);
    EXPECT_EQ(w[2], 2);
}

TEST(LocalFrame, IntegerSquareRootIsExact) {
    for (uint64_t r : {uint64_t(0), uint64_t(1), uint64_t(2), uint64_t(3037000499), uint64_t(1) << 31}) {
        EXPECT_EQ(integerSqrt(r * r), r);
        if (r > 0) EXPECT_EQ(integerSqrt(r * r - 1), r - 1);
        EXPECT_EQ(integerSqrt(r * r + 1), r == 0 ? 1u : r);
    }
}

}  // namespace
}  // namespace drm
