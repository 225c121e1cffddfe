// The paper's choice of predictor (connectivity/ranked/predictor_selection.h)
// on meshes whose votes follow from the definition: on a lattice of
// parallelograms the parallelogram predictor lands on every apex, and
// wins where the triangles are slivers (the midpoint's equilateral guess
// misses) but ties with the midpoint, which then wins, where they are
// nearly equilateral; a face whose apex neither predictor hits votes for
// the nearer; boundary faces do not vote; and a mesh of over 131,072
// faces votes through a sample of at most that many and at least half.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common.h"
#include "connectivity/ranked/predictor_selection.h"
#include "mesh/mesh_check.h"

namespace drm {
namespace {

struct Lattice {
    std::vector<int32_t> grid;
    std::vector<uint32_t> triangles;
    size_t vertexCount = 0;
    size_t interiorEdges = 0;
};

// Points i * u + j * v (0 <= i, j <= n), two triangles per cell, every
// cell cut along the same diagonal (from (i + 1, j) to (i, j + 1)), so that
// any two triangles sharing an edge form a parallelogram.
Lattice lattice(int n, const int32_t u[2], const int32_t v[2]) {
    Lattice l;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) l.grid.insert(l.grid.end(), {100 + i * u[0] + j * v[0], 100 + i * u[1] + j * v[1], 0});
    auto at = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            l.triangles.insert(l.triangles.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
            l.triangles.insert(l.triangles.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    l.vertexCount = size_t(n + 1) * size_t(n + 1);
    return l;
}

PredictorVotes votesOf(const Lattice& l) {
    MeshTopology topology;
    buildTopology(l.triangles, l.vertexCount, &topology);
    return countPredictorVotes(l.triangles, l.vertexCount, topology, l.grid);
}

// The faces whose voting edge (the k-th for face k modulo 3, every face
// voting below the sampling size) has a face across.
uint64_t votingFaces(const Lattice& l) {
    MeshTopology topology;
    buildTopology(l.triangles, l.vertexCount, &topology);
    uint64_t n = 0;
    for (size_t f = 0; f < l.triangles.size() / 3; ++f) {
        const size_t k = f % 3;
        if (topology.apexAcross(l.triangles[3 * f + k], l.triangles[3 * f + (k + 1) % 3], nullptr) != kNoVertex) ++n;
    }
    return n;
}

TEST(PredictorSelection, ParallelogramWinsOnALatticeOfSlivers) {
    const int32_t u[2] = {20, 0}, v[2] = {1, 3};  // triangles 20 units long, 3 high
    const Lattice l = lattice(12, u, v);
    const PredictorVotes votes = votesOf(l);
    // The parallelogram lands on every apex: a vote from every face that
    // has a face across its voting edge.
    EXPECT_EQ(votes.parallelogram, votingFaces(l));
    EXPECT_LT(votes.midpoint, votes.parallelogram);
    EXPECT_EQ(votes.winner(), Predictor::Parallelogram);
}

TEST(PredictorSelection, ATieGoesToTheMidpoint) {
    const int32_t u[2] = {20, 0}, v[2] = {10, 17};  // nearly equilateral triangles
    const Lattice l = lattice(12, u, v);
    const PredictorVotes votes = votesOf(l);
    // Both land within the nearest neighbour's distance of every apex.
    EXPECT_EQ(votes.parallelogram, votingFaces(l));
    EXPECT_EQ(votes.midpoint, votes.parallelogram);
    EXPECT_EQ(votes.winner(), Predictor::Midpoint);
    EXPECT_EQ((PredictorVotes{5, 5}).winner(), Predictor::Midpoint);
    EXPECT_EQ((PredictorVotes{6, 5}).winner(), Predictor::Parallelogram);
}

TEST(PredictorSelection, NeitherHitsThenTheNearerVotes) {
    // Face 0 (a, b, o) votes through its edge (a, b) for the apex p of face
    // 1, the mirror image of o; p has a neighbour r one unit away, so
    // neither predictor hits it: the parallelogram (16, -17) misses p by 12,
    // the midpoint's equilateral apex near (10, -17.3) by about 6.3, and the
    // midpoint gets the vote. Face 1 (p, b, a) votes through (b, a) for o,
    // whose nearest neighbour lies 17.5 away: both predictors hit it. Face 2
    // (p, a, r) votes through (r, p), a boundary edge: no vote.
    const std::vector<int32_t> grid = {0, 0, 0, 20, 0, 0, 4, 17, 0, 4, -17, 0, 4, -18, 0};
    const uint32_t a = 0, b = 1, o = 2, p = 3, r = 4;
    const std::vector<uint32_t> triangles = {a, b, o, p, b, a, p, a, r};
    MeshTopology topology;
    ASSERT_EQ(topologyProblem(triangles, 5, &topology), "");
    const PredictorVotes votes = countPredictorVotes(triangles, 5, topology, grid);
    EXPECT_EQ(votes.parallelogram, 1u);
    EXPECT_EQ(votes.midpoint, 2u);
}

TEST(PredictorSelection, LargeMeshesVoteThroughASample) {
    const int32_t u[2] = {20, 0}, v[2] = {1, 3};
    const Lattice l = lattice(260, u, v);  // 135,200 faces
    ASSERT_GT(l.triangles.size() / 3, size_t(1) << 17);
    const PredictorVotes votes = votesOf(l);
    EXPECT_LE(votes.parallelogram, uint64_t(1) << 17);
    // Every sampled face but those on the border has a face across.
    EXPECT_GE(votes.parallelogram, (uint64_t(1) << 16) - 4 * 260);
    EXPECT_EQ(votes.winner(), Predictor::Parallelogram);
}

}  // namespace
}  // namespace drm
