// The minimum spanning forest of the nearest-neighbour graph is taken in
// chunks of sorted edges (spanning_tree.cpp); it must be the very forest a
// full sort gives, ties included: points on a coarse grid (many equal
// lengths), clusters far apart (a forest, not a tree), and sizes on both
// sides of the chunk; edges sorted as one 64-bit number each, or, where
// the longest does not fit beside its ends, as triples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "common.h"
#include "geometry/tree/spanning_tree.h"

namespace drm {
namespace {

using EdgeSet = std::set<std::pair<uint32_t, uint32_t>>;

// Kruskal over every edge of the graph, sorted at once by (squared length,
// smaller end, larger end).
EdgeSet fullySortedForest(const std::vector<int32_t>& grid, const NearestNeighbours& nearest) {
    const size_t n = grid.size() / 3, k = size_t(nearest.k);
    struct Edge {
        int64_t length2;
        uint32_t a, b;
    };
    std::vector<Edge> edges;
    EdgeSet seen;
    for (size_t v = 0; v < n; ++v)
        for (size_t j = 0; j < k; ++j) {
            const uint32_t w = nearest.neighbours[v * k + j];
            if (w == kNoVertex) continue;
            const uint32_t a = std::min(uint32_t(v), w), b = std::max(uint32_t(v), w);
            if (!seen.insert({a, b}).second) continue;
            int64_t d2 = 0;
            for (int c = 0; c < 3; ++c) {
                const int64_t d = int64_t(grid[3 * a + size_t(c)]) - grid[3 * b + size_t(c)];
                d2 += d * d;
            }
            edges.push_back({d2, a, b});
        }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
        return x.length2 != y.length2 ? x.length2 < y.length2 : (x.a != y.a ? x.a < y.a : x.b < y.b);
    });
    UnionFind sets(n);
    EdgeSet forest;
    for (const Edge& e : edges)
        if (sets.join(e.a, e.b)) forest.insert({e.a, e.b});
    return forest;
}

EdgeSet edgesOf(const Forest& forest) {
    EdgeSet edges;
    for (uint32_t v = 0; v < forest.vertexCount(); ++v)
        for (const uint32_t* c = forest.begin(v); c != forest.end(v); ++c)
            edges.insert({std::min(v, *c), std::max(v, *c)});
    return edges;
}

std::vector<int32_t> clusteredPoints(size_t n, int clusters, int32_t side, uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<int32_t> grid;
    for (size_t v = 0; v < n; ++v) {
        const int32_t offset = int32_t(v % size_t(clusters)) * 1000;  // clusters far apart
        for (int c = 0; c < 3; ++c) grid.push_back(offset + int32_t(rng() % uint32_t(side)));
    }
    return grid;
}

TEST(SpanningForest, IsTheForestOfAFullSortWithTiesAndSeveralComponents) {
    for (const size_t n : {size_t(300), size_t(1500), size_t(6000)}) {
        for (const int clusters : {1, 3}) {
            const std::vector<int32_t> grid = clusteredPoints(n, clusters, 24, uint32_t(n) + uint32_t(clusters));
            const NearestNeighbours nearest = nearestNeighbours(grid, NeighbourIndex::Grid, kNeighbours);
            const EdgeSet expected = fullySortedForest(grid, nearest);
            const Forest forest = spanningForest(grid, nearest);
            const EdgeSet found = edgesOf(forest);
            EXPECT_EQ(found, expected) << n << " points in " << clusters << " clusters";
            // The preorder walks every vertex once, each child after its parent.
            const std::vector<uint32_t> order = preorder(forest);
            std::vector<size_t> at(n, n);
            for (size_t i = 0; i < order.size(); ++i) at[order[i]] = i;
            EXPECT_EQ(order.size(), n);
            EXPECT_EQ(std::count(at.begin(), at.end(), n), 0);
            for (uint32_t v = 0; v < n; ++v)
                for (const uint32_t* c = forest.begin(v); c != forest.end(v); ++c) EXPECT_LT(at[v], at[*c]);
            for (const auto& e : found)
                EXPECT_EQ(e.first % size_t(clusters), e.second % size_t(clusters)) << "clusters far apart stay apart";
        }
    }
}

// Clusters 2^20 apart on a 21-bit grid: squared lengths need 64 bits, but
// the graph's edges are short, and sort as one number each with their ends
// (13 bits each for 6,000 points). Beside one cluster, Q just outside it and
// P 2^19 further on: P's nearest is Q, 2^38 - 2^20 + 1 squared, its next
// the cluster's points at 2^38 and a little more. Those 39 bits do not fit
// beside 26 of ends: the edges sort as triples. Squeezed into 38 bits, the
// cluster's points would come before Q and the forest would join P to one
// of them. Either way the forest must be the full sort's.
TEST(SpanningForest, LongEdgesThatDoNotFitInOneNumberSortAsTriples) {
    for (const bool farPoint : {false, true}) {
        std::mt19937 rng(7);
        std::vector<int32_t> grid;
        for (size_t v = 0; v < 6000; ++v) {
            const int32_t offset = farPoint ? 0 : int32_t(v % 2) << 20;
            for (int c = 0; c < 3; ++c) grid.push_back(offset + int32_t(rng() % 40u));
        }
        if (farPoint) grid.insert(grid.end(), {40, 20, 20, (1 << 19) + 39, 20, 20});
        const NearestNeighbours nearest = nearestNeighbours(grid, NeighbourIndex::Grid, kNeighbours);
        const EdgeSet forest = edgesOf(spanningForest(grid, nearest));
        EXPECT_EQ(forest, fullySortedForest(grid, nearest)) << (farPoint ? "with" : "without") << " the far point";
        if (farPoint) EXPECT_EQ(forest.count({6000, 6001}), 1u) << "P joins the forest through Q";
    }
}

}  // namespace
}  // namespace drm
