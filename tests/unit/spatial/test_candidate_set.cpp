// The grid of cells behind every candidate search, against brute force:
// points on a surface (as meshes are), coincident points and a far outlier,
// vertices removed as the traversal culls them, queries near and far, and
// every cell size from one unit to the whole box giving the same answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "mesh/quantize.h"
#include "connectivity/ranked/rank_search.h"
#include "connectivity/traversal.h"
#include "spatial/spatial_index.h"
#include "spatial/candidate_set.h"

namespace drm {
namespace {

// A bumpy sphere on a 12-bit grid, some points doubled, one far corner point.
std::vector<int32_t> surfacePoints(std::mt19937& rng, size_t count) {
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::vector<int32_t> grid;
    for (size_t i = 0; i < count; ++i) {
        double x = gauss(rng), y = gauss(rng), z = gauss(rng);
        const double r = std::sqrt(x * x + y * y + z * z) + 1e-9;
        const double radius = 1200.0 * (1.0 + 0.1 * std::sin(7 * x / r));
        for (double c : {x, y, z}) grid.push_back(int32_t(std::lround(2048.0 + radius * c / r)));
        if (i % 17 == 0) grid.insert(grid.end(), grid.end() - 3, grid.end());  // a coincident twin
    }
    grid.insert(grid.end(), {4095, 4095, 4095});
    return grid;
}

// The nearest searches go through RankSearch, on the grid at each cell size
// and on FLANN's kd-tree (kFlann in place of a cell size).
constexpr int kFlann = -2;
std::unique_ptr<SpatialIndex> indexFor(const std::vector<int32_t>& grid, int shift) {
    return shift == kFlann ? makeFlannIndex(grid) : makeGridIndex(grid, shift);
}

int64_t squaredDistance(const std::vector<int32_t>& grid, uint32_t v, const FixedPoint& p) {
    const int64_t dx = int64_t(grid[3 * size_t(v)]) * kSubUnits - p.x;
    const int64_t dy = int64_t(grid[3 * size_t(v) + 1]) * kSubUnits - p.y;
    const int64_t dz = int64_t(grid[3 * size_t(v) + 2]) * kSubUnits - p.z;
    return dx * dx + dy * dy + dz * dz;
}

TEST(VertexIndex, CollectNearHoldsEveryVertexInTheBall) {
    std::mt19937 rng(99);
    const std::vector<int32_t> grid = surfacePoints(rng, 3000);
    const uint32_t n = uint32_t(grid.size() / 3);
    for (int shift : {VertexIndex::kChooseCellSize, 0, 3, 6, 9, 12}) {
        VertexIndex index(grid, shift);
        std::vector<uint8_t> removed(n, 0);
        std::uniform_real_distribution<double> at(-200.0, 4300.0), radii(0.0, 300.0);
        std::vector<uint32_t> found;
        for (int q = 0; q < 300; ++q) {
            if (q % 3 == 0)
                for (int k = 0; k < 20; ++k) {
                    const uint32_t v = uint32_t(rng() % n);
                    index.remove(v);
                    removed[v] = 1;
                }
            const Vec3 c{at(rng), at(rng), at(rng)};
            const double radius = q % 10 == 0 ? 5000.0 : radii(rng);
            index.collectNear(c, radius, found);
            const std::set<uint32_t> got(found.begin(), found.end());
            EXPECT_EQ(got.size(), found.size()) << "a vertex reported twice";
            for (uint32_t v = 0; v < n; ++v) {
                const Vec3 d{grid[3 * v] - c.x, grid[3 * v + 1] - c.y, grid[3 * v + 2] - c.z};
                if (removed[v]) EXPECT_EQ(got.count(v), 0u) << "removed vertex " << v;
                else if (norm2(d) <= radius * radius) EXPECT_EQ(got.count(v), 1u) << "missed vertex " << v;
            }
        }
        size_t left = 0;
        for (uint8_t r : removed) left += r ? 0 : 1;
        EXPECT_EQ(index.presentCount(), left);
    }
}

TEST(VertexIndex, NearestAgreesWithBruteForceAtEveryCellSize) {
    std::mt19937 rng(5);
    const std::vector<int32_t> grid = surfacePoints(rng, 2000);
    const uint32_t n = uint32_t(grid.size() / 3);
    std::vector<uint32_t> doomed(n);
    for (uint32_t v = 0; v < n; ++v) doomed[v] = v;
    std::shuffle(doomed.begin(), doomed.end(), rng);
    for (int shift : {VertexIndex::kChooseCellSize, 0, 4, 7, 12, kFlann}) {
        const std::unique_ptr<SpatialIndex> indexPtr = indexFor(grid, shift);
        SpatialIndex& index = *indexPtr;
        Traversal traversal(n, 4, nullptr);  // nothing culled: removal goes through the index alone
        Admissibility admissible(traversal, false);
        RankSearch search(grid, index, admissible);
        std::vector<uint8_t> removed(n, 0);
        std::mt19937 queries(77);  // the same queries at every cell size
        std::uniform_real_distribution<double> at(-9000.0, 13000.0);
        size_t next = 0;
        for (int q = 0; q < 400; ++q) {
            // Remove vertices until only a handful remain: searches must
            // also work when the rings around a point are empty.
            for (int k = 0; k < 5 && next + 3 < n; ++k) {
                index.remove(doomed[next]);
                removed[doomed[next++]] = 1;
            }
            const OpenEdge edge{uint32_t(queries() % n), uint32_t(queries() % n), 0};
            Vec3 c{at(queries), at(queries), at(queries)};
            if (q % 2) c = gridPoint(grid, doomed[n - 1 - queries() % 3]) + Vec3{0.5, -0.25, 0.0};
            const FixedPoint p = snapPrediction(c, 12);
            std::vector<RankedVertex> all;
            for (uint32_t v = 0; v < n; ++v)
                if (!removed[v] && v != edge.vi && v != edge.vj) all.emplace_back(squaredDistance(grid, v, p), v);
            std::sort(all.begin(), all.end());
            for (size_t count : {size_t(1), size_t(4), size_t(20)}) {
                const std::vector<RankedVertex>& got = search.nearest(p, count, edge);
                const std::vector<RankedVertex> want(all.begin(), all.begin() + std::min(count, all.size()));
                EXPECT_EQ(got, want) << "shift " << shift << " query " << q << " count " << count;
            }
        }
    }
}

// Ties everywhere: a small integer lattice, queries on lattice points and
// half-steps, so that vertices sit exactly at the distances where a search
// decides to stop; a far outlier stretches the box (cells must still follow
// the cluster); cell sizes from one unit to beyond the box.
TEST(VertexIndex, TiesAndAFarOutlierAtEveryCellSize) {
    std::vector<int32_t> grid;
    for (int x = 0; x < 9; ++x)
        for (int y = 0; y < 9; ++y)
            for (int z = 0; z < 3; ++z) grid.insert(grid.end(), {x * 2, y * 2, z * 2});
    grid.insert(grid.end(), {(1 << 21) - 1, (1 << 21) - 1, (1 << 21) - 1});
    const uint32_t n = uint32_t(grid.size() / 3);
    for (int shift : {VertexIndex::kChooseCellSize, 0, 1, 2, 3, 5, 22, 26, kFlann}) {
        const std::unique_ptr<SpatialIndex> indexPtr = indexFor(grid, shift);
        SpatialIndex& index = *indexPtr;
        Traversal traversal(n, 4, nullptr);
        Admissibility admissible(traversal, false);
        RankSearch search(grid, index, admissible);
        for (int qx = -1; qx <= 17; qx += 3)
            for (int qy = 0; qy <= 16; qy += 5)
                for (int qz = -2; qz <= 5; ++qz) {
                    const Vec3 c{qx * 0.5 + (qz & 1), qy * 1.0, qz * 1.0};
                    const FixedPoint p = snapPrediction(c, 21);
                    const OpenEdge edge{0, 1, 2};
                    std::vector<RankedVertex> all;
                    for (uint32_t v = 2; v < n; ++v) all.emplace_back(squaredDistance(grid, v, p), v);
                    std::sort(all.begin(), all.end());
                    for (size_t count : {size_t(1), size_t(3), size_t(8), size_t(30)}) {
                        const std::vector<RankedVertex> want(all.begin(), all.begin() + std::min(count, all.size()));
                        EXPECT_EQ(search.nearest(p, count, edge), want) << "shift " << shift << " count " << count;
                    }
                    std::vector<uint32_t> found;
                    index.collectNear(c, 3.0, found);
                    const std::set<uint32_t> got(found.begin(), found.end());
                    for (uint32_t v = 0; v < n; ++v)
                        if (norm2(gridPoint(grid, v) - c) <= 9.0) EXPECT_EQ(got.count(v), 1u) << "shift " << shift;
                }
    }
}

}  // namespace
}  // namespace drm
