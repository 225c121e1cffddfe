// The vertex coder's local frame (format 3): an integer rotation that must
// give back every vector exactly, and must actually turn the normal onto
// the third axis (else it would code nothing better).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "local_frame.h"

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

TEST(LocalFrame, IntegerSquareRootIsExact) {
    for (uint64_t r : {uint64_t(0), uint64_t(1), uint64_t(2), uint64_t(3037000499), uint64_t(1) << 31}) {
        EXPECT_EQ(integerSqrt(r * r), r);
        if (r > 0) EXPECT_EQ(integerSqrt(r * r - 1), r - 1);
        EXPECT_EQ(integerSqrt(r * r + 1), r == 0 ? 1u : r);
    }
}

}  // namespace
}  // namespace drm
