// The two spatial indexes (the grid, FLANN's kd-tree) against brute force
// on the exact integer definition: nearest vertices by (fixed-point squared
// distance, index) with a filter, as vertices are removed; every vertex's
// nearest others; the ball searches' superset. Clustered points with many
// exact ties, coincident points, a far outlier, and coordinates beyond
// float's 24 bits (FLANN's float distances then round even on the grid
// points), where only the certified bound keeps FLANN exact; the ordered
// search of a ball (the grid through its hierarchy of cells). The batch
// search all_nearest.h adds to the grid has its own file
// (test_all_nearest.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "spatial/spatial_index.h"

namespace drm {
namespace {

std::unique_ptr<SpatialIndex> makeIndex(const std::vector<int32_t>& grid, NeighbourIndex kind) {
    return kind == NeighbourIndex::Flann ? makeFlannIndex(grid) : makeGridIndex(grid);
}

// count points in [0, extent]^3, a third of them on a coarse lattice (ties),
// some doubled, one far outlier at the top corner.
std::vector<int32_t> cloud(std::mt19937& rng, size_t count, int32_t extent) {
    std::uniform_int_distribution<int32_t> any(0, extent), lattice(0, 6);
    std::vector<int32_t> grid;
    for (size_t i = 0; i < count; ++i) {
        if (i % 3 == 0) {
            for (int k = 0; k < 3; ++k) grid.push_back(lattice(rng) * (extent / 8));
        } else {
            for (int k = 0; k < 3; ++k) grid.push_back(any(rng) / 4);
        }
        if (i % 11 == 0) grid.insert(grid.end(), grid.end() - 3, grid.end());
    }
    grid.insert(grid.end(), {extent, extent, extent});
    return grid;
}

std::vector<RankedVertex> bruteNearest(const std::vector<int32_t>& grid, const std::vector<bool>& removed,
                                       const FixedPoint& p, size_t count, uint32_t skip) {
    std::vector<RankedVertex> all;
    for (uint32_t v = 0; v < grid.size() / 3; ++v)
        if (!removed[v] && v != skip && v % 5 != 1) all.emplace_back(fixedDistance2(grid, p, v), v);
    std::sort(all.begin(), all.end());
    if (all.size() > count) all.resize(count);
    return all;
}

class BothIndexes : public ::testing::TestWithParam<int32_t> {};

TEST_P(BothIndexes, NearestMatchesBruteForceAsVerticesAreRemoved) {
    const int32_t extent = GetParam();
    std::mt19937 rng{uint32_t(extent)};
    const std::vector<int32_t> grid = cloud(rng, 700, extent);
    const size_t n = grid.size() / 3;
    for (NeighbourIndex kind : {NeighbourIndex::Grid, NeighbourIndex::Flann}) {
        std::mt19937 local(99);
        const std::unique_ptr<SpatialIndex> index = makeIndex(grid, kind);
        SCOPED_TRACE(index->name());
        std::vector<bool> removed(n, false);
        std::uniform_int_distribution<int64_t> at(-int64_t(extent) * kSubUnits / 4, int64_t(extent) * kSubUnits * 5 / 4);
        std::vector<RankedVertex> found;
        for (int round = 0; round < 6; ++round) {
            for (int q = 0; q < 60; ++q) {
                FixedPoint p{at(local), at(local), at(local)};
                if (q % 3 == 0) p = fixedPointOf(grid, uint32_t(local() % n));  // on a vertex: ties
                const uint32_t skip = uint32_t(local() % n);
                for (size_t count : {size_t(1), size_t(2), size_t(4), size_t(8), size_t(9), size_t(40)}) {
                    index->nearest(p, count, [&](uint32_t v) { return v != skip && v % 5 != 1; }, found);
                    ASSERT_EQ(found, bruteNearest(grid, removed, p, count, skip)) << "round " << round << " count " << count;
                }
                // The far ranks' search: the last of that list alone, also
                // past every vertex there is (then how many there are).
                for (size_t count : {size_t(3), size_t(9), size_t(40), size_t(300), n}) {
                    const std::vector<RankedVertex> brute = bruteNearest(grid, removed, p, count, skip);
                    RankedVertex last{-1, kNoVertex};
                    const size_t got = index->nthNearest(p, count, [&](uint32_t v) { return v != skip && v % 5 != 1; }, last);
                    ASSERT_EQ(got, brute.size()) << "round " << round << " count " << count;
                    if (got == count) ASSERT_EQ(last, brute.back()) << "round " << round << " count " << count;
                    else ASSERT_EQ(last.second, kNoVertex) << "an answer where there is none";
                }
            }
            for (int r = 0; r < 100; ++r) {  // cull some, some twice
                const uint32_t v = uint32_t(local() % n);
                index->remove(v);
                removed[v] = true;
            }
            EXPECT_EQ(index->presentCount(), size_t(std::count(removed.begin(), removed.end(), false)));
        }
    }
}

TEST_P(BothIndexes, NearestOfEachIsEveryVertexsNearestOthers) {
    const int32_t extent = GetParam();
    std::mt19937 rng(uint32_t(extent) + 1);
    const std::vector<int32_t> grid = cloud(rng, 500, extent);
    const size_t n = grid.size() / 3, count = 8;
    const std::vector<bool> none(n, false);
    for (NeighbourIndex kind : {NeighbourIndex::Grid, NeighbourIndex::Flann}) {
        const std::unique_ptr<SpatialIndex> index = makeIndex(grid, kind);
        SCOPED_TRACE(index->name());
        std::vector<uint32_t> neighbours;
        std::vector<int64_t> distance2;
        index->nearestOfEach(count, neighbours, &distance2);
        ASSERT_EQ(neighbours.size(), n * count);
        for (uint32_t v = 0; v < n; ++v) {
            std::vector<RankedVertex> all;
            for (uint32_t w = 0; w < n; ++w)
                if (w != v) all.emplace_back(fixedDistance2(grid, fixedPointOf(grid, v), w), w);
            std::sort(all.begin(), all.end());
            for (size_t j = 0; j < count; ++j) {
                ASSERT_EQ(neighbours[v * count + j], all[j].second) << "vertex " << v << " neighbour " << j;
                ASSERT_EQ(distance2[v * count + j], all[j].first);
            }
        }
        // Without the distances (the geometry tree's graph), the same neighbours.
        std::vector<uint32_t> alone;
        index->nearestOfEach(count, alone, nullptr);
        EXPECT_EQ(alone, neighbours);
    }
}

TEST_P(BothIndexes, CollectNearHoldsEveryPresentVertexInTheBall) {
    const int32_t extent = GetParam();
    std::mt19937 rng(uint32_t(extent) + 2);
    const std::vector<int32_t> grid = cloud(rng, 600, extent);
    const size_t n = grid.size() / 3;
    for (NeighbourIndex kind : {NeighbourIndex::Grid, NeighbourIndex::Flann}) {
        const std::unique_ptr<SpatialIndex> index = makeIndex(grid, kind);
        SCOPED_TRACE(index->name());
        for (uint32_t v = 0; v < n; v += 3) index->remove(v);
        std::uniform_real_distribution<double> at(-0.2 * extent, 1.2 * extent), radius(0, 0.3 * extent);
        std::vector<uint32_t> near;
        for (int q = 0; q < 200; ++q) {
            const Vec3 c{at(rng), at(rng), at(rng)};
            const double r = q % 10 == 0 ? 0.0 : radius(rng);
            index->collectNear(c, r, near);
            const std::set<uint32_t> got(near.begin(), near.end());
            EXPECT_EQ(got.size(), near.size()) << "a vertex listed twice";
            for (uint32_t w = 0; w < n; ++w) {
                const Vec3 d{grid[3 * w] - c.x, grid[3 * w + 1] - c.y, grid[3 * w + 2] - c.z};
                if (w % 3 != 0 && norm2(d) <= r * r) ASSERT_TRUE(got.count(w)) << "vertex " << w << " query " << q;
                if (w % 3 == 0) ASSERT_FALSE(got.count(w)) << "removed vertex " << w;
            }
            // The same vertices with their coordinates, in runs.
            std::vector<uint32_t> visited;
            index->forEachNear(c, r, [&](const uint32_t* ids, const int32_t* points, size_t count, const int32_t* box) {
                for (size_t i = 0; i < count; ++i) {
                    visited.push_back(ids[i]);
                    for (size_t k = 0; k < 3; ++k) {
                        ASSERT_EQ(points[3 * i + k], grid[3 * size_t(ids[i]) + k]);
                        ASSERT_LE(box[k], points[3 * i + k]) << "a point below its run's box";
                        ASSERT_GE(box[3 + k], points[3 * i + k]) << "a point above its run's box";
                    }
                }
            });
            ASSERT_EQ(visited.size(), near.size());
            ASSERT_EQ(std::set<uint32_t>(visited.begin(), visited.end()), got);
        }
    }
}

// forEachNearInOrder as its two callers use it: the best vertex of the
// ball by a key the caller bounds over boxes, with a bound that tightens as
// it goes. Two keys: the lowest x (ties by index), the shape of the size
// step's lowest height ahead; and the squared fixed-point distance from a
// point off the centre, the nearest candidates'. Against brute force over
// the present vertices, the grid's hierarchy built early and brought up to
// date as more vertices are removed. Every vertex handed over must be
// present, and be handed over once.
TEST_P(BothIndexes, InOrderSearchFindsTheBestOfTheBall) {
    const int32_t extent = GetParam();
    std::mt19937 rng(uint32_t(extent) + 5);
    const std::vector<int32_t> grid = cloud(rng, 2000, extent);
    const size_t n = grid.size() / 3;
    constexpr double kNever = std::numeric_limits<double>::infinity();
    for (NeighbourIndex kind : {NeighbourIndex::Grid, NeighbourIndex::Flann}) {
        const std::unique_ptr<SpatialIndex> index = makeIndex(grid, kind);
        SCOPED_TRACE(index->name());
        std::vector<bool> removed(n, false);
        std::uniform_real_distribution<double> at(-0.2 * extent, 1.2 * extent), radius(0, 0.8 * extent);
        for (int round = 0; round < 4; ++round) {
            for (int q = 0; q < 60; ++q) {
                const Vec3 c{at(rng), at(rng), at(rng)};
                const double r = q % 10 == 0 ? 0.0 : radius(rng);
                auto inBall = [&](uint32_t v) {
                    const Vec3 d{grid[3 * v] - c.x, grid[3 * v + 1] - c.y, grid[3 * v + 2] - c.z};
                    return norm2(d) <= r * r;
                };
                // Lowest x among the ball's vertices with odd index.
                std::pair<double, uint32_t> expectedLow{kNever, kNoIndex}, gotLow{kNever, kNoIndex};
                for (uint32_t v = 0; v < n; ++v)
                    if (!removed[v] && v % 2 == 1 && inBall(v))
                        expectedLow = std::min(expectedLow, std::make_pair(double(grid[3 * v]), v));
                std::set<uint32_t> handed;
                index->forEachNearInOrder(
                    c, r, [](const int32_t* box) { return double(box[0]); }, [&] { return gotLow.first; },
                    [&](const uint32_t* ids, const int32_t* points, size_t count, const int32_t*) {
                        for (size_t i = 0; i < count; ++i) {
                            ASSERT_FALSE(removed[ids[i]]) << "removed vertex " << ids[i] << " handed over";
                            ASSERT_TRUE(handed.insert(ids[i]).second) << "vertex " << ids[i] << " handed over twice";
                            ASSERT_EQ(points[3 * i], grid[3 * size_t(ids[i])]);
                            if (ids[i] % 2 == 1 && inBall(ids[i]))
                                gotLow = std::min(gotLow, std::make_pair(double(points[3 * i]), ids[i]));
                        }
                    });
                ASSERT_EQ(gotLow, expectedLow) << "query " << q << " round " << round;
                // Nearest to a point a quarter of the radius off the centre.
                const Vec3 off{c.x + 0.25 * r, c.y, c.z};
                const FixedPoint p{int64_t(std::floor(off.x * kSubUnits + 0.5)), int64_t(std::floor(off.y * kSubUnits + 0.5)),
                                   int64_t(std::floor(off.z * kSubUnits + 0.5))};
                RankedVertex expectedNear{INT64_MAX, kNoIndex}, gotNear{INT64_MAX, kNoIndex};
                for (uint32_t v = 0; v < n; ++v)
                    if (!removed[v] && inBall(v)) expectedNear = std::min(expectedNear, {fixedDistance2(grid, p, v), v});
                index->forEachNearInOrder(
                    c, r,
                    [&](const int32_t* box) {
                        int64_t d2 = 0;
                        const int64_t pc[3] = {p.x, p.y, p.z};
                        for (int k = 0; k < 3; ++k) {
                            const int64_t gap = std::max<int64_t>(int64_t(box[k]) * kSubUnits - pc[k], 0) +
                                                std::max<int64_t>(pc[k] - int64_t(box[3 + k]) * kSubUnits, 0);
                            d2 += gap * gap;
                        }
                        return double(d2);
                    },
                    [&] { return double(gotNear.first); },
                    [&](const uint32_t* ids, const int32_t*, size_t count, const int32_t*) {
                        for (size_t i = 0; i < count; ++i)
                            if (inBall(ids[i])) gotNear = std::min(gotNear, {fixedDistance2(grid, p, ids[i]), ids[i]});
                    });
                ASSERT_EQ(gotNear, expectedNear) << "query " << q << " round " << round;
            }
            // An eighth of the vertices goes each round; the hierarchy keeps count.
            for (uint32_t v = uint32_t(round); v < n; v += 4)
                if (!removed[v] && (v / 4) % 2 == 0) {
                    index->remove(v);
                    removed[v] = true;
                }
        }
    }
}

// What is removed is passed over whole: once half the space is emptied,
// every box the search asks the caller about holds a present vertex (a
// hierarchy that did not keep count would open the emptied half), and once
// everything is gone nothing is asked or handed over. The grid at its own
// cell size, at cells one unit wide, and as one cell (the hierarchy a
// single leaf); its hierarchy built before the removals or after them.
TEST_P(BothIndexes, InOrderSearchPassesOverWhatIsRemoved) {
    const int32_t extent = GetParam();
    std::mt19937 rng(uint32_t(extent) + 6);
    const std::vector<int32_t> grid = cloud(rng, 1500, extent);
    const size_t n = grid.size() / 3;
    constexpr double kNever = std::numeric_limits<double>::infinity();
    struct Variant {
        NeighbourIndex kind;
        int cellShift;
        bool builtBefore;
    };
    for (const Variant& variant : {Variant{NeighbourIndex::Grid, -1, true}, Variant{NeighbourIndex::Grid, -1, false},
                                   Variant{NeighbourIndex::Grid, 0, true}, Variant{NeighbourIndex::Grid, 26, true},
                                   Variant{NeighbourIndex::Flann, -1, true}}) {
        const std::unique_ptr<SpatialIndex> index =
            variant.kind == NeighbourIndex::Flann ? makeFlannIndex(grid) : makeGridIndex(grid, variant.cellShift);
        SCOPED_TRACE(std::string(index->name()) + " cell shift " + std::to_string(variant.cellShift) +
                     (variant.builtBefore ? ", built before" : ", built after"));
        std::vector<bool> removed(n, false);
        const Vec3 middle{extent / 2.0, extent / 2.0, extent / 2.0};
        const double everywhere = 2.0 * extent;
        auto search = [&](const Vec3& c, double r, std::pair<double, uint32_t>& got, size_t& asked, size_t& handed) {
            got = {kNever, kNoIndex};
            asked = handed = 0;
            index->forEachNearInOrder(
                c, r,
                [&](const int32_t* box) {
                    ++asked;
                    bool holds = false;
                    for (uint32_t v = 0; v < n && !holds; ++v)
                        if (!removed[v]) {
                            const int32_t* at = &grid[3 * size_t(v)];
                            holds = at[0] >= box[0] && at[1] >= box[1] && at[2] >= box[2] && at[0] <= box[3] &&
                                    at[1] <= box[4] && at[2] <= box[5];
                        }
                    EXPECT_TRUE(holds) << "asked about a box with no present vertex";
                    return double(box[0]);
                },
                [&] { return got.first; },
                [&](const uint32_t* ids, const int32_t* points, size_t count, const int32_t*) {
                    for (size_t i = 0; i < count; ++i) {
                        ++handed;
                        EXPECT_FALSE(removed[ids[i]]) << "removed vertex " << ids[i] << " handed over";
                        got = std::min(got, std::make_pair(double(points[3 * i]), ids[i]));
                    }
                });
        };
        std::pair<double, uint32_t> got;
        size_t asked = 0, handed = 0;
        if (variant.builtBefore) search(middle, everywhere, got, asked, handed);
        // The lower half in x goes, and every third vertex besides.
        for (uint32_t v = 0; v < n; ++v)
            if (grid[3 * size_t(v)] < extent / 2 || v % 3 == 0) {
                index->remove(v);
                removed[v] = true;
            }
        std::uniform_real_distribution<double> at(0, extent), radius(0.1 * extent, 1.5 * extent);
        for (int q = 0; q < 8; ++q) {
            const Vec3 c = q == 0 ? middle : Vec3{at(rng), at(rng), at(rng)};
            const double r = q == 0 ? everywhere : radius(rng);
            std::pair<double, uint32_t> expected{kNever, kNoIndex};
            for (uint32_t v = 0; v < n; ++v) {
                const Vec3 d{grid[3 * v] - c.x, grid[3 * v + 1] - c.y, grid[3 * v + 2] - c.z};
                if (!removed[v] && norm2(d) <= r * r) expected = std::min(expected, std::make_pair(double(grid[3 * v]), v));
            }
            search(c, r, got, asked, handed);
            // The search hands over vertices beyond the ball too (callers
            // test): of those inside, it must have the best.
            if (expected.second != kNoIndex) {
                ASSERT_LE(got.first, expected.first) << "query " << q;
            }
            ASSERT_GE(got.first, double(extent / 2)) << "a vertex of the emptied half";
        }
        for (uint32_t v = 0; v < n; ++v) index->remove(v);
        std::fill(removed.begin(), removed.end(), true);
        search(middle, everywhere, got, asked, handed);
        EXPECT_EQ(asked, 0u) << "a box asked about with nothing left";
        EXPECT_EQ(handed, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Extents, BothIndexes, ::testing::Values(4095, (1 << 21) - 1, (1 << 25) - 1));

TEST(SpatialIndex, AutoTakesTheMeasuredDefaults) {
    EXPECT_EQ(resolveIndex(NeighbourIndex::Grid, IndexRole::NeighbourGraph), NeighbourIndex::Grid);
    EXPECT_EQ(resolveIndex(NeighbourIndex::Flann, IndexRole::Traversal), NeighbourIndex::Flann);
    EXPECT_NE(resolveIndex(NeighbourIndex::Auto, IndexRole::Traversal), NeighbourIndex::Auto);
    EXPECT_NE(resolveIndex(NeighbourIndex::Auto, IndexRole::NeighbourGraph), NeighbourIndex::Auto);
}

}  // namespace
}  // namespace drm
