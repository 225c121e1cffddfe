// Quantization onto the cubic grid (mesh/quantize.h): makeGrid takes the
// bounding box's low corner as origin and splits the largest extent into
// 2^bits - 1 steps; quantize rounds every coordinate to the nearest grid
// point within [0, 2^bits - 1]; dequantize gives back origin + q * step as
// floats, within half a step of the input, and names the first vertex
// that would leave float's range; gridProblem is the one test of a grid a
// file could hold; bad positions and bit counts are refused by name.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/quantize.h"

namespace drm {
namespace {

template <class F>
std::string refusal(F f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput) << e.what();
        return e.what();
    }
    return "";
}

TEST(Quantize, TheGridSpansTheLargestExtentInCubicSteps) {
    const std::vector<float> positions = {-1, 2, 10, 3, 2.5f, 10, 0, 3, 11};
    const Grid g = makeGrid(positions, 12);
    EXPECT_EQ(g.bits, 12);
    EXPECT_EQ(g.origin[0], -1);
    EXPECT_EQ(g.origin[1], 2);
    EXPECT_EQ(g.origin[2], 10);
    EXPECT_DOUBLE_EQ(g.step, 4.0 / 4095);  // x spans 4, y 1, z 1
    EXPECT_EQ(gridMax(12), 4095);
    EXPECT_EQ(gridMax(1), 1);
    EXPECT_EQ(gridMax(21), (1 << 21) - 1);
    const std::vector<int32_t> q = quantize(positions, g);
    EXPECT_EQ(q[0], 0);
    EXPECT_EQ(q[3], 4095);        // the far end of the largest extent
    EXPECT_EQ(q[7], 1024);        // y = 3: 1023.75 rounds to 1024
    EXPECT_EQ(q[2], 0);
    EXPECT_EQ(q[8], 1024);        // z = 11: 1023.75 rounds to 1024
    // A single point: a step of 1, every coordinate 0.
    const Grid point = makeGrid({5, 6, 7, 5, 6, 7}, 8);
    EXPECT_EQ(point.step, 1.0);
    EXPECT_EQ(quantize({5, 6, 7, 5, 6, 7}, point), (std::vector<int32_t>(6, 0)));
}

TEST(Quantize, EveryPointComesBackWithinHalfAStep) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> any(-1000, 1000);
    for (int bits : {1, 4, 12, 16, 21}) {
        std::vector<float> positions(3000);
        for (float& x : positions) x = any(rng);
        const Grid g = makeGrid(positions, bits);
        const std::vector<int32_t> q = quantize(positions, g);
        std::vector<float> back;
        size_t bad = 12345;
        ASSERT_TRUE(dequantize(q, g, back, &bad));
        EXPECT_EQ(bad, 12345u);  // untouched when nothing fails
        ASSERT_EQ(back.size(), positions.size());
        for (size_t i = 0; i < q.size(); ++i) {
            ASSERT_GE(q[i], 0);
            ASSERT_LE(q[i], gridMax(bits));
            ASSERT_EQ(back[i], float(g.origin[i % 3] + double(q[i]) * g.step));
            // Half a step, plus the float rounding of both ends.
            ASSERT_LE(std::fabs(double(back[i]) - positions[i]), g.step / 2 + 1e-3) << bits << " bits";
        }
    }
}

TEST(Quantize, AGridAtTheEdgeOfFloatStaysFinite) {
    // A box as wide as float's range: every grid point decodes to a finite
    // float (the nearest one past FLT_MAX is taken one step lower).
    const std::vector<float> positions = {-FLT_MAX, -FLT_MAX, 0, FLT_MAX, FLT_MAX * 0.999999f, 1};
    for (int bits : {2, 12, 21}) {
        const Grid g = makeGrid(positions, bits);
        std::vector<float> back;
        ASSERT_TRUE(dequantize(quantize(positions, g), g, back, nullptr)) << bits;
        for (float x : back) EXPECT_TRUE(std::isfinite(x));
    }
    // A grid point past float's range is named by its vertex.
    Grid g;
    g.bits = 12;
    g.origin[0] = g.origin[1] = g.origin[2] = 0;
    g.step = double(FLT_MAX) / 1000;
    std::vector<float> back;
    size_t bad = 0;
    EXPECT_FALSE(dequantize({1, 1, 1, 2, 2, 2, 1, 2000, 1}, g, back, &bad));
    EXPECT_EQ(bad, 2u);
}

TEST(Quantize, BadPositionsAndBitsAreRefusedByName) {
    EXPECT_EQ(refusal([] { makeGrid({0, 0, 0}, 0); }), "quantization bits must be between 1 and 21, not 0");
    EXPECT_EQ(refusal([] { makeGrid({0, 0, 0}, 22); }), "quantization bits must be between 1 and 21, not 22");
    EXPECT_EQ(refusal([] { makeGrid({}, 12); }), "empty mesh: there are no vertices to encode");
    EXPECT_EQ(refusal([] { makeGrid({0, 0}, 12); }), "the position array does not hold whole xyz triples");
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(refusal([&] { makeGrid({0, 0, 0, 1, nan, 1}, 12); }), "vertex 1 has a non-finite coordinate (NaN)");
    EXPECT_EQ(refusal([&] { makeGrid({0, 0, 0, 1, 1, 1, 2, 2, -inf}, 12); }),
              "vertex 2 has a non-finite coordinate (infinity)");
    Grid g;
    EXPECT_EQ(refusal([&] { quantize({0, 0, 0, inf, 0, 0}, g); }), "vertex 1 has a non-finite coordinate");
}

TEST(Quantize, GridProblemNamesWhatAFileCannotHold) {
    Grid g;
    EXPECT_EQ(gridProblem(g), "");
    g.bits = 22;
    EXPECT_EQ(gridProblem(g), "quantization bits 22 out of range 1..21");
    g = Grid();
    g.origin[1] = 1e39;  // finite as a double, not as a float
    EXPECT_EQ(gridProblem(g), "the bounding box origin is not a finite float");
    g = Grid();
    g.origin[2] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(gridProblem(g), "the bounding box origin is not a finite float");
    for (double step : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
        g = Grid();
        g.step = step;
        EXPECT_EQ(gridProblem(g), "the grid step is not a positive number") << step;
    }
    // Every grid makeGrid makes passes.
    EXPECT_EQ(gridProblem(makeGrid({-3, 4, 5, 7, 8, 9e30f}, 21)), "");
}

TEST(Quantize, GridPointReadsThreeCoordinates) {
    const std::vector<int32_t> q = {1, 2, 3, -4, 5, 2000000};
    const Vec3 p = gridPoint(q, 1);
    EXPECT_EQ(p.x, -4);
    EXPECT_EQ(p.y, 5);
    EXPECT_EQ(p.z, 2000000);
}

}  // namespace
}  // namespace drm
