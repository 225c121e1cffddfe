// The base predictors and the two corrections on configurations whose
// answer is known.
#include <gtest/gtest.h>

#include "predictor.h"
#include "traversal.h"
#include "spatial_index.h"

namespace drm {
namespace {

void expectNear(Vec3 a, Vec3 b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Predictor, ParallelogramReflectsTheOppositeVertex) {
    expectNear(parallelogramApex({0, 0, 0}, {4, 0, 0}, {1, 3, 0}), {3, -3, 0});
}

TEST(Predictor, MidpointMakesAnEquilateralTriangleAhead) {
    // Opposite vertex straight above the midpoint: no lean, so no skew bias.
    const Vec3 p = midpointApex({0, 0, 0}, {2, 0, 0}, {1, 1, 0});
    expectNear(p, {1, -0.8660254037844386 * 2, 0});
}

TEST(Predictor, MidpointLeansWithTheRebuiltTriangle) {
    // The rebuilt triangle leans towards b (opposite vertex over x = 3 of
    // [0, 4]); the parallelogram apex lies over x = 1, and the midpoint
    // prediction is nudged that way, off the tie between two grid columns.
    const Vec3 p = midpointApex({0, 0, 0}, {4, 0, 0}, {3, 2, 0});
    EXPECT_LT(p.x, 2.0);
    EXPECT_GT(p.x, 1.9);
    EXPECT_LT(p.y, 0.0);
}

TEST(Predictor, DegenerateTrianglesStillPredict) {
    expectNear(midpointApex({1, 1, 1}, {1, 1, 1}, {5, 5, 5}), {1, 1, 1});  // coincident ends
    expectNear(midpointApex({0, 0, 0}, {2, 0, 0}, {5, 0, 0}), {1, 0, 0});  // opposite on the edge's line
}

// Vertices: edge 0-1 along x, opposite vertex 2 behind (y > 0); candidates ahead at y = -6.
struct Fan {
    std::vector<int32_t> grid = {0, 0, 0, 4, 0, 0, 2, 3, 0, 2, -6, 0, 30, -2, 0};
    std::unique_ptr<SpatialIndex> index = makeGridIndex(grid);
    Traversal traversal{5, 4, index.get()};
    Admissibility admissible{traversal, false};
    OpenEdge edge{0, 1, 2};
};

TEST(Predictor, SizeCorrectionScalesToTheFirstVertexAhead) {
    Fan fan;
    ApexPredictor predictor(Predictor::Midpoint, false, fan.grid, *fan.index, fan.admissible);
    const Vec3 p = predictor.predict(fan.edge);
    // Vertex 4 at y = -2 lies outside the slab (x = 30); vertex 3 at y = -6 is the first ahead.
    EXPECT_NEAR(p.y, -6.0, 1e-9);
}

TEST(Predictor, SizeCorrectionLeavesThePredictionAloneWithNothingAhead) {
    std::vector<int32_t> grid = {0, 0, 0, 4, 0, 0, 2, 3, 0};
    const std::unique_ptr<SpatialIndex> indexPtr = makeGridIndex(grid);
    SpatialIndex& index = *indexPtr;
    Traversal traversal(3, 1, &index);
    Admissibility admissible(traversal, false);
    ApexPredictor predictor(Predictor::Midpoint, false, grid, index, admissible);
    expectNear(predictor.predict({0, 1, 2}), midpointApex({0, 0, 0}, {4, 0, 0}, {2, 3, 0}));
}

TEST(Predictor, CurvatureBendsOntoThePlaneOfTheNearbyVertices) {
    // The rebuilt triangle lies in z = 0; the vertices ahead rise at 45 degrees
    // (z = -y): the prediction is rotated about the edge onto that slope.
    std::vector<int32_t> grid = {0, 0, 0, 4, 0, 0, 2, 3, 0};
    for (int x = 0; x <= 4; x += 2)
        for (int y = -2; y >= -6; y -= 2) grid.insert(grid.end(), {x, y, -y});
    const std::unique_ptr<SpatialIndex> indexPtr = makeGridIndex(grid);
    SpatialIndex& index = *indexPtr;
    Traversal traversal(grid.size() / 3, 4, &index);
    PredictorTuning noScaling;
    noScaling.slabWidening = -10;      // an empty slab: isolates the curvature step
    noScaling.curvatureNeighbours = 4;  // the four nearest all lie on the slope
    Admissibility admissible(traversal, false);
    ApexPredictor predictor(Predictor::Midpoint, true, grid, index, admissible, noScaling);
    const Vec3 p = predictor.predict({0, 1, 2});
    EXPECT_NEAR(p.z, -p.y, 1e-9);
    EXPECT_LT(p.y, 0.0);
    // Rotation keeps the distance from the edge.
    const Vec3 base = midpointApex({0, 0, 0}, {4, 0, 0}, {2, 3, 0});
    EXPECT_NEAR(p.y * p.y + p.z * p.z, base.y * base.y, 1e-9);
}

}  // namespace
}  // namespace drm
