// The exact rank search against a brute-force ranking, on random points on a
// coarse grid, where equal distances and coincident vertices are common.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "drmcodec/drmcodec.h"
#include "connectivity/ranked/rank_search.h"
#include "connectivity/traversal.h"
#include "spatial/spatial_index.h"

namespace drm {
namespace {

struct Scene {
    std::vector<int32_t> grid;
    std::unique_ptr<SpatialIndex> index;
    std::unique_ptr<Traversal> traversal;
    std::unique_ptr<Admissibility> admissible;
};

// Every test runs on both indexes: they must agree with brute force alike.
const NeighbourIndex kIndexes[] = {NeighbourIndex::Grid, NeighbourIndex::Flann};

std::unique_ptr<SpatialIndex> makeIndex(const std::vector<int32_t>& grid, NeighbourIndex kind) {
    return kind == NeighbourIndex::Flann ? makeFlannIndex(grid) : makeGridIndex(grid);
}

Scene randomScene(std::mt19937& rng, size_t count, int extent, NeighbourIndex kind) {
    Scene s;
    std::uniform_int_distribution<int> coord(0, extent);
    for (size_t i = 0; i < 3 * count; ++i) s.grid.push_back(coord(rng));
    s.index = makeIndex(s.grid, kind);
    s.traversal.reset(new Traversal(count, 4, s.index.get()));
    s.admissible.reset(new Admissibility(*s.traversal, false));
    return s;
}

// All admissible vertices ordered by (exact fixed-point distance, index).
std::vector<uint32_t> bruteForceOrder(const Scene& s, RankSearch& search, Vec3 prediction, const OpenEdge& edge,
                                      int bits) {  // written against the definition, not the search
    const FixedPoint p = snapPrediction(prediction, bits);
    std::vector<std::pair<int64_t, uint32_t>> all;
    for (uint32_t v = 0; v < s.grid.size() / 3; ++v)
        if (v != edge.vi && v != edge.vj && !s.traversal->isCulled(v)) all.emplace_back(search.distance2(p, v), v);
    std::sort(all.begin(), all.end());
    std::vector<uint32_t> order;
    for (auto& d : all) order.push_back(d.second);
    return order;
}

TEST(RankSearch, MatchesBruteForceWithManyTies) {
  for (NeighbourIndex kind : kIndexes) {
    std::mt19937 rng(12345);
    const int bits = 12;
    for (int trial = 0; trial < 20; ++trial) {
        Scene s = randomScene(rng, 400, 12, kind);  // 400 points on a 13^3 grid: many duplicates and ties
        SCOPED_TRACE(s.index->name());
        RankSearch search(s.grid, *s.index, *s.admissible);
        std::uniform_real_distribution<double> at(-3.0, 15.0);
        for (int q = 0; q < 30; ++q) {
            OpenEdge edge{uint32_t(rng() % 400), uint32_t(rng() % 400), 0};
            if (edge.vi == edge.vj) continue;
            // Half the predictions sit exactly on grid points or half-steps, where ties abound.
            Vec3 p{at(rng), at(rng), at(rng)};
            if (q % 2) p = {std::floor(p.x * 2) / 2, std::floor(p.y * 2) / 2, std::floor(p.z * 2) / 2};
            const std::vector<uint32_t> order = bruteForceOrder(s, search, p, edge, bits);
            const FixedPoint fp = snapPrediction(p, bits);
            for (size_t k = 0; k < order.size(); k += 1 + k / 8) {
                EXPECT_EQ(search.rankOf(fp, order[k], edge), k + 1) << "trial " << trial << " query " << q;
                EXPECT_EQ(search.vertexOfRank(fp, uint32_t(k + 1), edge), order[k]);
            }
            EXPECT_THROW(search.vertexOfRank(fp, uint32_t(order.size() + 1), edge), Error);
            // A preferred vertex takes rank 1 and shifts the others by one.
            const uint32_t preferred = order[order.size() / 2];
            EXPECT_EQ(search.rankOf(fp, preferred, edge, preferred), 1u);
            EXPECT_EQ(search.vertexOfRank(fp, 1, edge, preferred), preferred);
            EXPECT_EQ(search.rankOf(fp, order[0], edge, preferred), 2u);
            EXPECT_EQ(search.vertexOfRank(fp, 2, edge, preferred), order[0]);
            const uint32_t last = order.back() == preferred ? order[order.size() - 2] : order.back();
            EXPECT_EQ(search.vertexOfRank(fp, search.rankOf(fp, last, edge, preferred), edge, preferred), last);
        }
    }
  }
}

// The ranks list the nearest candidates found in the predictor's ball,
// which need not be the nearest overall: listed vertices take the first
// ranks in the listed order, every other one follows by distance, counted
// without the listed ones wherever they lie.
TEST(RankSearch, ListedVerticesNeedNotBeTheNearest) {
  for (NeighbourIndex kind : kIndexes) {
    std::mt19937 rng(99);
    const int bits = 12;
    for (int trial = 0; trial < 10; ++trial) {
        Scene s = randomScene(rng, 300, 20, kind);
        SCOPED_TRACE(s.index->name());
        RankSearch search(s.grid, *s.index, *s.admissible);
        std::uniform_real_distribution<double> at(-2.0, 22.0);
        for (int q = 0; q < 20; ++q) {
            OpenEdge edge{uint32_t(rng() % 300), uint32_t(rng() % 300), 0};
            if (edge.vi == edge.vj) continue;
            const Vec3 p{at(rng), at(rng), at(rng)};
            const std::vector<uint32_t> order = bruteForceOrder(s, search, p, edge, bits);
            const FixedPoint fp = snapPrediction(p, bits);
            // Two far vertices and one near one, in that order.
            const std::vector<RankedVertex> listed = {{0, order[order.size() - 1]}, {0, order[order.size() / 2]}, {0, order[1]}};
            std::vector<uint32_t> expected;
            for (const RankedVertex& l : listed) expected.push_back(l.second);
            for (uint32_t v : order)
                if (std::find(expected.begin(), expected.end(), v) == expected.end()) expected.push_back(v);
            for (size_t k = listed.size(); k < expected.size(); k += 1 + k / 10) {
                ASSERT_EQ(search.rankOf(fp, expected[k], edge, kNoVertex, listed), k + 1) << "query " << q;
                ASSERT_EQ(search.vertexOfRank(fp, uint32_t(k + 1), edge, kNoVertex, listed), expected[k]);
            }
            EXPECT_THROW(search.vertexOfRank(fp, uint32_t(expected.size() + 1), edge, kNoVertex, listed), Error);
        }
    }
  }
}

// Among a given set, the nearest are those of the set by the same exact
// order; with every present vertex offered, they are the searched ones.
TEST(RankSearch, NearestAmongOfferedVertices) {
  for (NeighbourIndex kind : kIndexes) {
    std::mt19937 rng(5);
    Scene s = randomScene(rng, 200, 9, kind);  // many ties
    SCOPED_TRACE(s.index->name());
    RankSearch search(s.grid, *s.index, *s.admissible);
    std::uniform_real_distribution<double> at(-1.0, 10.0);
    for (int q = 0; q < 50; ++q) {
        const OpenEdge edge{uint32_t(q), uint32_t(q + 1), 0};
        const FixedPoint fp = snapPrediction(Vec3{at(rng), at(rng), at(rng)}, 12);
        auto offerAll = [&](auto offer, auto) {
            for (uint32_t v = 200; v-- > 0;) offer(v, s.grid.data() + 3 * size_t(v));
        };
        auto offerEven = [&](auto offer, auto) {
            for (uint32_t v = 0; v < 200; v += 2) offer(v, s.grid.data() + 3 * size_t(v));
        };
        std::vector<RankedVertex> allEven;
        for (uint32_t v = 0; v < 200; v += 2)
            if (v != edge.vi && v != edge.vj) allEven.emplace_back(search.distance2(fp, v), v);
        std::sort(allEven.begin(), allEven.end());
        // Up to 4 (the codec's lists) the insertion has no branches; more
        // take the general insertion.
        for (size_t count = 1; count <= 6; ++count) {
            SCOPED_TRACE(count);
            const std::vector<RankedVertex> among = search.nearestAmong(fp, count, edge, offerAll);
            EXPECT_EQ(among, search.nearest(fp, count, edge));
            // The bound: a searcher may pass over every vertex farther
            // than it says, and the answer is the same. Offered by
            // decreasing index, a vertex at the bound's own distance (the
            // scene has many ties) comes after the equal one listed: one
            // passed over because the bound is reached, not passed, would
            // lose the tie that the smaller index wins.
            size_t offered = 0;
            auto offerWithinBound = [&](auto offer, auto bound) {
                for (uint32_t v = 200; v-- > 0;) {
                    if (search.distance2(fp, v) > bound()) continue;
                    ++offered;
                    offer(v, s.grid.data() + 3 * size_t(v));
                }
            };
            EXPECT_EQ(search.nearestAmong(fp, count, edge, offerWithinBound), among);
            EXPECT_LT(offered, size_t(200)) << "the bound never let the search pass a vertex over";
            const std::vector<RankedVertex> even(allEven.begin(), allEven.begin() + ptrdiff_t(count));
            EXPECT_EQ(search.nearestAmong(fp, count, edge, offerEven), even);
            // Fewer offered than asked for: all of them, in order.
            auto offerThree = [&](auto offer, auto) {
                for (uint32_t v : {150u, 70u, 110u}) offer(v, s.grid.data() + 3 * size_t(v));
            };
            std::vector<RankedVertex> three;
            for (uint32_t v : {150u, 70u, 110u}) three.emplace_back(search.distance2(fp, v), v);
            std::sort(three.begin(), three.end());
            three.resize(std::min<size_t>(3, count));
            EXPECT_EQ(search.nearestAmong(fp, count, edge, offerThree), three);
        }
    }
  }
}

TEST(RankSearch, FarPredictionsAndLargeGrids) {
  for (NeighbourIndex kind : kIndexes) {
    std::mt19937 rng(7);
    const int bits = 21;
    Scene s = randomScene(rng, 300, (1 << bits) - 1, kind);
    SCOPED_TRACE(s.index->name());
    RankSearch search(s.grid, *s.index, *s.admissible);
    const OpenEdge edge{0, 1, 2};
    // Predictions far outside the box are clamped, never overflow.
    for (Vec3 p : {Vec3{-1e12, 5, 5}, Vec3{3e9, -4e9, 1e10}, Vec3{1048576.25, 7.5, 2097151}}) {
        const std::vector<uint32_t> order = bruteForceOrder(s, search, p, edge, bits);
        const FixedPoint fp = snapPrediction(p, bits);
        for (size_t k = 0; k < order.size(); k += 17) {
            EXPECT_EQ(search.rankOf(fp, order[k], edge), k + 1);
            EXPECT_EQ(search.vertexOfRank(fp, uint32_t(k + 1), edge), order[k]);
        }
    }
  }
}

TEST(RankSearch, CulledVerticesAreNotCandidates) {
  for (NeighbourIndex kind : kIndexes) {
    // A closed tetrahedron plus two loose points: once its four faces are in,
    // all four of its vertices are culled and only the loose points remain.
    std::vector<int32_t> grid = {0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0, 10, 3, 3, 3, 50, 50, 50};
    const std::unique_ptr<SpatialIndex> indexPtr = makeIndex(grid, kind);
    SpatialIndex& index = *indexPtr;
    Traversal traversal(6, 4, &index);
    traversal.startComponent(0, 2, 1);
    const uint32_t apexes[3] = {3, 1, 3};  // across (0, 2), then (0, 3), then (2, 1)
    OpenEdge edge;
    int attached = 0;
    while (traversal.popOpenEdge(edge)) traversal.attachApex(edge, apexes[attached++]);
    EXPECT_EQ(traversal.triangleCount(), 4u);
    for (uint32_t v = 0; v < 4; ++v) EXPECT_TRUE(traversal.isCulled(v));
    EXPECT_EQ(index.presentCount(), 2u);
    Admissibility admissible(traversal, false);
    RankSearch search(grid, index, admissible);
    const OpenEdge loose{4, 5, 4};  // an edge that is not in the mesh: only candidates matter
    EXPECT_THROW(search.vertexOfRank(FixedPoint(), 1, loose), Error);
    const OpenEdge other{0, 1, 2};
    EXPECT_EQ(search.vertexOfRank(FixedPoint(), 1, other), 4u);
    EXPECT_EQ(search.vertexOfRank(FixedPoint(), 2, other), 5u);
  }
}

}  // namespace
}  // namespace drm
