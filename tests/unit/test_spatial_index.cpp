// The two spatial indexes (the grid, FLANN's kd-tree) against brute force
// on the exact integer definition: nearest vertices by (fixed-point squared
// distance, index) with a filter, as vertices are removed; every vertex's
// nearest others; the ball searches' superset. Clustered points with many
// exact ties, coincident points, a far outlier, and coordinates beyond
// float's 24 bits (FLANN's float distances then round even on the grid
// points), where only the certified bound keeps FLANN exact; the ordered
// search of a ball (the grid through its hierarchy of cells).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "spatial/all_nearest.h"
#include "spatial/spatial_index.h"
#include "tiny_ply.h"

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

// The batch search by cells, on its own: every point it certifies has
// exactly its k nearest others (ties by index), at every cell width, on a
// sampled surface with coincident points (stacks of up to 12, so that a
// point's own entry can fall out of the first k + 1) and far outliers;
// the points it leaves uncertain keep their rows untouched. At the width it
// picks itself, a scan's vertices leave few points uncertain (the speed it
// is for).
TEST(AllNearest, CertifiedPointsHaveExactlyTheirNearestAtEveryCellWidth) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    std::vector<int32_t> grid;
    for (int i = 0; i < 1500; ++i) {  // a sphere of radius 1000 around (2000, 2000, 2000)
        const double a = angle(rng), b = angle(rng) / 2;
        for (double c : {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)})
            grid.push_back(int32_t(std::lround(2000 + 1000 * c)));
        if (i % 50 == 0)
            for (int copy = 0; copy < 1 + i % 12; ++copy) grid.insert(grid.end(), grid.end() - 3, grid.end());
    }
    grid.insert(grid.end(), {0, 0, 0, 4095, 4095, 4095, 4095, 0, 17});
    const size_t n = grid.size() / 3;
    for (size_t k : {size_t(1), size_t(8)}) {
        std::vector<std::vector<RankedVertex>> expected(n);
        for (uint32_t v = 0; v < n; ++v) {
            for (uint32_t w = 0; w < n; ++w)
                if (w != v) expected[v].emplace_back(fixedDistance2(grid, fixedPointOf(grid, v), w) / (kSubUnits * kSubUnits), w);
            std::sort(expected[v].begin(), expected[v].end());
            expected[v].resize(k);
        }
        for (int shift : {-1, 0, 3, 5, 7, 9, 12, 21}) {
            SCOPED_TRACE("k " + std::to_string(k) + " cell shift " + std::to_string(shift));
            std::vector<uint32_t> neighbours(n * k, 12345);
            std::vector<int64_t> distance2(n * k, -1);
            const std::vector<uint32_t> uncertain = nearestOfEachByCells(grid, k, shift, neighbours, &distance2);
            ASSERT_TRUE(std::is_sorted(uncertain.begin(), uncertain.end()));
            for (uint32_t v = 0; v < n; ++v) {
                const bool certain = !std::binary_search(uncertain.begin(), uncertain.end(), v);
                for (size_t j = 0; j < k; ++j) {
                    if (certain) {
                        ASSERT_EQ(neighbours[v * k + j], expected[v][j].second) << "vertex " << v << " neighbour " << j;
                        ASSERT_EQ(distance2[v * k + j], expected[v][j].first);
                    } else {
                        ASSERT_EQ(neighbours[v * k + j], 12345u);
                        ASSERT_EQ(distance2[v * k + j], -1);
                    }
                }
            }
            if (shift == 21) EXPECT_TRUE(uncertain.empty());  // one cell: the whole grid is every point's block
        }
    }
    // On a scan's vertices, at the width it picks, the batch leaves a
    // minority of points to the one-by-one search (bunny-lres, 2,583
    // vertices at 12 bits: 20 %; on the corpus horse 5 %, igea 0.7 %).
    const drm::Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    float low = bunny.positions[0], high = bunny.positions[0];
    for (float c : bunny.positions) low = std::min(low, c), high = std::max(high, c);
    std::vector<int32_t> scan(bunny.positions.size());
    for (size_t i = 0; i < scan.size(); ++i) scan[i] = int32_t(std::lround((bunny.positions[i] - low) * 4095.0 / (high - low)));
    std::vector<uint32_t> scanNeighbours(scan.size() / 3 * 8);
    std::vector<int64_t> scanDistance2(scanNeighbours.size());
    const size_t left = nearestOfEachByCells(scan, 8, -1, scanNeighbours, &scanDistance2).size();
    EXPECT_LT(double(left), 0.25 * double(scan.size() / 3)) << left << " of " << scan.size() / 3;
    // Outside [0, 2^21) nothing is certified.
    std::vector<int32_t> negative = {-1, 0, 0, 5, 5, 5, 6, 6, 6};
    std::vector<uint32_t> neighbours(3, kNoVertex);
    std::vector<int64_t> distance2(3, 0);
    EXPECT_EQ(nearestOfEachByCells(negative, 1, -1, neighbours, &distance2).size(), 3u);
}

// Squared distances of 2^31 or more do not fit the batch's sort keys: such
// block points are left out like points outside the block, which still
// certifies a point whose k + 1 nearest (itself included) all lie nearer,
// and no point whose k-th does not. Two clusters at opposite corners of the
// 2^21 grid, a lone point between them, and one cell holding all of them.
TEST(AllNearest, FarBlockPointsNeverEnterAndNeverWrongACertifiedPoint) {
    const int32_t top = (1 << 21) - 1;
    std::vector<int32_t> grid;
    for (int i = 0; i < 12; ++i) grid.insert(grid.end(), {i % 3, i / 3, i % 2});
    for (int i = 0; i < 12; ++i) grid.insert(grid.end(), {top - i % 3, top - i / 3, top - i % 2});
    grid.insert(grid.end(), {top / 2, top / 2, top / 2});
    const size_t n = grid.size() / 3, k = 8;
    std::vector<uint32_t> neighbours(n * k, 12345);
    std::vector<int64_t> distance2(n * k, -1);
    const std::vector<uint32_t> uncertain = nearestOfEachByCells(grid, k, 21, neighbours, &distance2);
    EXPECT_EQ(uncertain, std::vector<uint32_t>{uint32_t(n - 1)});  // only the lone point's neighbours are all far
    for (uint32_t v = 0; v + 1 < n; ++v) {
        std::vector<RankedVertex> expected;
        for (uint32_t w = 0; w < n; ++w)
            if (w != v) expected.emplace_back(fixedDistance2(grid, fixedPointOf(grid, v), w) / (kSubUnits * kSubUnits), w);
        std::sort(expected.begin(), expected.end());
        for (size_t j = 0; j < k; ++j) {
            ASSERT_EQ(neighbours[v * k + j], expected[j].second) << "vertex " << v << " neighbour " << j;
            ASSERT_EQ(distance2[v * k + j], expected[j].first);
        }
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

// Two threads split the cells between them (from kSplitFromPoints points
// on): every row and the uncertain list are what one thread gives. A sphere
// of 30,000 points with clusters of coincident copies (ties by index across
// the split) and a few far outliers (uncertain points on both sides).
TEST(AllNearest, TwoThreadsGiveWhatOneGives) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    std::vector<int32_t> grid;
    for (int i = 0; i < 30000; ++i) {
        const double a = angle(rng), b = angle(rng) / 2;
        for (double c : {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)})
            grid.push_back(int32_t(std::lround(40000 + 30000 * c)));
        if (i % 997 == 0)
            for (int copy = 0; copy < 9; ++copy) grid.insert(grid.end(), grid.end() - 3, grid.end());
    }
    grid.insert(grid.end(), {0, 0, 0, 90000, 3, 7, 5, 90000, 11});
    const size_t n = grid.size() / 3, k = 8;
    std::vector<uint32_t> oneNeighbours(n * k, 12345), twoNeighbours(n * k, 12345);
    std::vector<int64_t> oneDistance2(n * k, -1), twoDistance2(n * k, -1);
    const std::vector<uint32_t> oneUncertain = nearestOfEachByCells(grid, k, -1, oneNeighbours, &oneDistance2, 1);
    const std::vector<uint32_t> twoUncertain = nearestOfEachByCells(grid, k, -1, twoNeighbours, &twoDistance2, 2);
    EXPECT_FALSE(oneUncertain.empty());  // the outliers at least
    EXPECT_EQ(twoUncertain, oneUncertain);
    EXPECT_EQ(twoNeighbours, oneNeighbours);
    EXPECT_EQ(twoDistance2, oneDistance2);
    EXPECT_LT(double(oneUncertain.size()), 0.5 * double(n));  // most rows were filled, so compared
}

}  // namespace
}  // namespace drm
