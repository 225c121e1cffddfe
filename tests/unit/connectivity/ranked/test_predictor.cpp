// The base predictors and the two corrections on configurations whose
// answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <random>
#include <set>

#include "spatial/morton.h"
#include "connectivity/ranked/predictor.h"
#include "connectivity/ranked/rank_search.h"
#include "connectivity/traversal.h"
#include "spatial/spatial_index.h"

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


// Long edges among dense points make balls of hundreds of vertices, which
// the predictor searches run by run, passing over runs that cannot hold the
// answer, and (most of these balls are many cells wide: past the first 64,
// on the grids) through the grid's hierarchy of cells, passing over groups
// of cells. The answers must be those of every vertex looked at: the first
// vertex ahead (the scaled prediction, exactly) and, for the rank's nearest
// candidates, every vertex of the ball within the bound asked for. Checked
// against a search over every present vertex, on grids of several cell
// sizes and on FLANN's index, with a third of the vertices removed.
void expectFullBallsAsEveryVertexSays(const std::vector<int32_t>& grid,
                                      const std::function<OpenEdge(std::mt19937&)>& makeEdge) {
    std::mt19937 rng(11);
    const uint32_t n = uint32_t(grid.size() / 3);
    std::vector<bool> removed(n, false);
    for (uint32_t v = 0; v < n; ++v) removed[v] = rng() % 3 == 0;
    auto point = [&](uint32_t v) { return Vec3{double(grid[3 * v]), double(grid[3 * v + 1]), double(grid[3 * v + 2])}; };
    struct Made {
        const char* name;
        std::unique_ptr<SpatialIndex> index;
    };
    std::vector<Made> indexes;
    indexes.push_back({"grid", makeGridIndex(grid)});
    indexes.push_back({"grid, cells of 2", makeGridIndex(grid, 1)});
    indexes.push_back({"grid, cells of 32", makeGridIndex(grid, 5)});
    indexes.push_back({"flann", makeFlannIndex(grid)});
    for (Made& made : indexes) {
        SCOPED_TRACE(made.name);
        SpatialIndex& index = *made.index;
        Traversal traversal(n, 1, &index);
        for (uint32_t v = 0; v < n; ++v)
            if (removed[v]) index.remove(v);
        Admissibility admissible(traversal, false);
        ApexPredictor predictor(Predictor::Midpoint, false, grid, index, admissible);
        size_t fullBalls = 0;
        for (int q = 0; q < 300; ++q) {
            const OpenEdge edge = makeEdge(rng);
            if (edge.vi == edge.vj || edge.vi == edge.opposite || edge.vj == edge.opposite) continue;
            const Vec3 a = point(edge.vi), b = point(edge.vj), mid = (a + b) * 0.5, e = b - a;
            const Vec3 p = midpointApex(a, b, point(edge.opposite));
            const Vec3 offset = rejectFrom(p - mid, e);
            const double height = norm(offset), edgeLength = norm(e);
            if (height == 0) continue;
            // The search of every vertex: the balls in turn, the smallest
            // height in the slab, then the smallest index.
            const Vec3 ahead = offset * (1.0 / height);
            const double halfSlab = edgeLength * (0.5 + PredictorTuning().slabWidening);
            double radius = 2.0 * std::max(height, edgeLength);
            Vec3 expected = p;
            std::vector<uint32_t> ball;
            for (int attempt = 0; attempt < 4; ++attempt, radius *= 2.0) {
                ball.clear();
                double best = std::numeric_limits<double>::infinity();
                uint32_t first = kNoIndex;
                for (uint32_t v = 0; v < n; ++v) {
                    if (removed[v]) continue;
                    const Vec3 x = point(v) - mid;
                    if (!(norm2(x) <= radius * radius)) continue;
                    ball.push_back(v);
                    const double h = dot(x, ahead), along = dot(x, e) / edgeLength;
                    if (h > 0 && !(along > halfSlab) && !(along < -halfSlab) && admissible(v, edge) &&
                        (h < best || (h == best && v < first))) {
                        best = h;
                        first = v;
                    }
                }
                if (first != kNoIndex) {
                    expected = mid + (p - mid) * (best / height);
                    break;
                }
            }
            fullBalls += ball.size() > 64 ? 1 : 0;
            const Vec3 got = predictor.predict(edge);
            ASSERT_EQ(got.x, expected.x) << "query " << q;
            ASSERT_EQ(got.y, expected.y) << "query " << q;
            ASSERT_EQ(got.z, expected.z) << "query " << q;
            // Every vertex of the ball within the bound, and only vertices
            // of the ball: bounds at the distances of the nearest few, and
            // none. (A run is passed over only if its box lies beyond the
            // bound; at a bound equal to a vertex's distance, that vertex
            // is often its run's nearest point.)
            const FixedPoint fp = snapPrediction(got, 12);
            std::vector<int64_t> byDistance;
            for (uint32_t v : ball) byDistance.push_back(fixedDistance2(grid, fp, v));
            std::sort(byDistance.begin(), byDistance.end());
            byDistance.resize(std::min<size_t>(byDistance.size(), 8));
            byDistance.push_back(INT64_MAX);
            for (const int64_t bound : byDistance) {
                std::set<uint32_t> visited;
                predictor.forEachInBall(fp, [&] { return bound; }, [&](uint32_t v, const int32_t* xyz) {
                    ASSERT_TRUE(std::binary_search(ball.begin(), ball.end(), v)) << "vertex " << v << " is not in the ball";
                    ASSERT_EQ(xyz[0], grid[3 * v]);
                    visited.insert(v);
                });
                for (uint32_t v : ball)
                    if (fixedDistance2(grid, fp, v) <= bound)
                        ASSERT_TRUE(visited.count(v)) << "vertex " << v << " passed over, bound " << bound;
                if (bound == INT64_MAX) ASSERT_EQ(visited.size(), ball.size());
            }
        }
        EXPECT_GT(fullBalls, 100u) << "too few balls over the listing limit: the searches of full balls went untested";
    }
}

// 3,000 points in a thick slab, edges between any two.
TEST(Predictor, FullBallsGiveWhatASearchOfEveryVertexGives) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int32_t> at(0, 160);
    std::vector<int32_t> grid;
    for (int v = 0; v < 3000; ++v) grid.insert(grid.end(), {at(rng), at(rng), at(rng) / 8});
    const uint32_t n = uint32_t(grid.size() / 3);
    expectFullBallsAsEveryVertexSays(grid, [n](std::mt19937& r) {
        return OpenEdge{uint32_t(r() % n), uint32_t(r() % n), uint32_t(r() % n)};
    });
}

// A lattice, edges along x with the rebuilt triangle on the side of larger
// y: whole rows of vertices ahead lie at one height, so the first vertex
// ahead is decided by its index among equals, in whichever run it lies.
TEST(Predictor, FullBallsBreakTiesOfHeightByIndex) {
    constexpr int32_t kSide = 41, kLayers = 3;
    std::vector<int32_t> grid;
    for (int32_t x = 0; x < kSide; ++x)
        for (int32_t y = 0; y < kSide; ++y)
            for (int32_t z = 0; z < kLayers; ++z) grid.insert(grid.end(), {x, y, z});
    auto at = [](int32_t x, int32_t y, int32_t z) { return uint32_t((x * kSide + y) * kLayers + z); };
    expectFullBallsAsEveryVertexSays(grid, [&](std::mt19937& r) {
        const int32_t length = 4 + int32_t(r() % 12), x = int32_t(r() % uint32_t(kSide - length));
        const int32_t y = 2 + int32_t(r() % uint32_t(kSide - 6)), z = int32_t(r() % kLayers);
        return OpenEdge{at(x, y, z), at(x + length, y, z), at(x + length / 2 + int32_t(r() % 2), y + 3, z)};
    });
}

// Two parts: on a part's seam side the size step searches its first ball
// only. Edge 0-1 along x at y = 40, its rebuilt triangle behind (y = 43);
// the one vertex ahead, 3, lies 20 units away, past the first ball (radius
// 2 max(h, L) = 8) and the second (16): found in the third without the rule.
struct FarAhead {
    std::vector<int32_t> grid = {0, 40, 0, 4, 40, 0, 2, 43, 0, 2, 20, 0};
    std::unique_ptr<SpatialIndex> index = makeGridIndex(grid);
    Traversal traversal{4, 3, index.get()};
    Admissibility admissible{traversal, false};
    OpenEdge edge{0, 1, 2};
    Vec3 unscaled = midpointApex({0, 40, 0}, {4, 40, 0}, {2, 43, 0});
};

TEST(Predictor, SeamSideStopsAtTheFirstBallInPartOne) {
    FarAhead mesh;
    ApexPredictor everyBall(Predictor::Midpoint, false, mesh.grid, *mesh.index, mesh.admissible);
    EXPECT_NEAR(everyBall.predict(mesh.edge).y, 20.0, 1e-9);
    EXPECT_EQ(everyBall.firstAheadAttempt(), 2);
    // Part 1 with the seam at vertex 0: the edge's two ends are past it.
    SeamSide fromZero;
    fromZero.seam = 0;
    ApexPredictor seamSide(Predictor::Midpoint, false, mesh.grid, *mesh.index, mesh.admissible);
    seamSide.searchFirstBallOnlyOn(&fromZero);
    expectNear(seamSide.predict(mesh.edge), mesh.unscaled);
    EXPECT_EQ(seamSide.firstAheadAttempt(), -1);
    EXPECT_TRUE(seamSide.searchedBall());
    // Seam at vertex 1: end 0 lies before it, so the edge is not on the seam's side.
    SeamSide fromOne;
    fromOne.seam = 1;
    ApexPredictor before(Predictor::Midpoint, false, mesh.grid, *mesh.index, mesh.admissible);
    before.searchFirstBallOnlyOn(&fromOne);
    EXPECT_NEAR(before.predict(mesh.edge).y, 20.0, 1e-9);
    EXPECT_EQ(before.firstAheadAttempt(), 2);
}

TEST(Predictor, SeamSideStopsAtTheFirstBallInPartTwo) {
    FarAhead mesh;
    // The prediction's grid point, as EdgeModel snaps it for the seam classes.
    const FixedPoint snapped = snapPrediction(mesh.unscaled, 12);
    const uint64_t key = mortonKey(uint64_t(snapped.x >> kSubUnitBits), uint64_t(snapped.y >> kSubUnitBits),
                                   uint64_t(snapped.z >> kSubUnitBits));
    SeamSide pastIt;  // part 2 begins past the prediction: it lies in part 1's region
    pastIt.secondPart = true;
    pastIt.firstPartBelow = key + 1;
    pastIt.bits = 12;
    ApexPredictor inPartOne(Predictor::Midpoint, false, mesh.grid, *mesh.index, mesh.admissible);
    inPartOne.searchFirstBallOnlyOn(&pastIt);
    expectNear(inPartOne.predict(mesh.edge), mesh.unscaled);
    EXPECT_EQ(inPartOne.firstAheadAttempt(), -1);
    SeamSide atIt = pastIt;  // part 2 begins at it
    atIt.firstPartBelow = key;
    ApexPredictor inPartTwo(Predictor::Midpoint, false, mesh.grid, *mesh.index, mesh.admissible);
    inPartTwo.searchFirstBallOnlyOn(&atIt);
    EXPECT_NEAR(inPartTwo.predict(mesh.edge).y, 20.0, 1e-9);
    EXPECT_EQ(inPartTwo.firstAheadAttempt(), 2);
}

}  // namespace
}  // namespace drm
