// EdgeModel's front-neighbour lever: the rank an apex would have
// had in the order not used, which encoder and decoder both compute to
// choose the order of the next edge, against orders enumerated in full; and
// the lever on a CAD mesh with slivers (tests/data/tray-bottom.ply), where
// it changes the rank stream and round-trips.
//
// The boundary flag lever: whether an edge is a boundary edge is
// coded apart from its rank, in a context of what the decoder sees around
// the edge. Checked here: that this context separates boundary edges from
// the others on a patch with one open border; that on meshes with holes the
// lever makes the rank stream smaller without changing a single rank, and
// decodes; that a closed mesh pays only a few bytes for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "ranks_only.h"
#include "drmcodec/drmcodec.h"
#include "connectivity/ranked/edge_model.h"
#include "connectivity/ranked/gap_closing.h"
#include "mesh/mesh_check.h"
#include "spatial/spatial_index.h"
#include "tiny_ply.h"
#include "connectivity/traversal.h"
#include "entropy/rank_coder.h"
#include "test_meshes.h"

namespace drm {
namespace {

Mesh trayBottom() { return drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/tray-bottom.ply"); }

Levers withoutFront() {
    Levers levers;
    levers.frontNeighbours = false;
    return levers;
}

// Drives two models over one traversal, as the encoder drives one: `front`
// with every lever, `plain` with all but the front neighbours. The plain
// model's ranks are the plain order's by construction; the front order is
// enumerated from the plain one by its definition (docs/format.md,
// "Ranks", the paragraph "Front neighbours"), vertex by vertex.
TEST(EdgeModel, RanksInTheOrderNotUsedMatchFullOrders) {
    const Mesh mesh = trayBottom();
    EncodeOptions options = drm_test::ranksOnly();
    options.tryWithoutLevers = false;
    const std::vector<int32_t> grid = encode(mesh, options).quantized;  // input order
    const MeshTopology topology = checkMesh(mesh);
    const std::unique_ptr<SpatialIndex> index = makeSpatialIndex(grid, NeighbourIndex::Grid, IndexRole::Traversal);
    const size_t faces = mesh.faceCount();
    Traversal traversal(mesh.vertexCount(), faces, index.get());
    EdgeModel front(grid, 12, Predictor::Midpoint, false, Levers(), faces, *index, traversal);
    EdgeModel plain(grid, 12, Predictor::Midpoint, false, withoutFront(), faces, *index, traversal);
    EXPECT_EQ(front.contextCount(), 2 * plain.contextCount());

    size_t checked = 0, frontUsed = 0, apexMovedUp = 0, apexPushedDown = 0, differ = 0;
    std::vector<uint8_t> attached(faces, 0);
    for (size_t f = 0; f < faces; ++f) {
        if (attached[f]) continue;
        attached[f] = 1;
        traversal.startComponent(mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]);
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            uint32_t face = 0;
            const uint32_t apex = topology.apexAcross(edge.vi, edge.vj, &face);
            front.forecast(edge);
            plain.forecast(edge);
            if (apex == kNoVertex) {
                traversal.closeAsBoundary(edge);
                continue;
            }
            const uint32_t used = front.rankOf(apex, edge);
            const uint32_t plainRank = plain.rankOf(apex, edge);
            front.resolved(apex);
            plain.resolved(apex);
            const EdgeModel::OrderLesson lesson = front.lastLesson();
            EXPECT_EQ(lesson.plain, plainRank) << "face " << face;
            EXPECT_EQ(used, lesson.frontUsed ? lesson.front : lesson.plain) << "face " << face;

            // The plain order in full as far as it matters: up to the apex
            // and the admissible front neighbours.
            const FanEnds ends = fanEnds(edge, traversal);
            std::vector<uint32_t> wanted = {apex};
            for (uint32_t v : {ends.atI, ends.atJ})
                if (v != kNoVertex && plain.admissible(v, edge)) wanted.push_back(v);
            std::vector<uint32_t> order;  // order[k] has plain rank k + 1
            while (std::any_of(wanted.begin(), wanted.end(),
                               [&](uint32_t v) { return std::find(order.begin(), order.end(), v) == order.end(); }))
                order.push_back(plain.vertexOfRank(uint32_t(order.size() + 1), edge));
            ASSERT_EQ(order[plainRank - 1], apex);
            // The front order: plain rank 1, the front neighbours the plain
            // order does not list (by plain rank, which beyond the list is
            // distance order), then the rest of the plain order.
            std::vector<uint32_t> moved;
            for (size_t k = lesson.plainListed; k < order.size(); ++k)
                if (order[k] != order[0] && std::find(wanted.begin() + 1, wanted.end(), order[k]) != wanted.end())
                    moved.push_back(order[k]);
            std::vector<uint32_t> frontOrder = {order[0]};
            frontOrder.insert(frontOrder.end(), moved.begin(), moved.end());
            for (size_t k = 1; k < order.size(); ++k)
                if (std::find(moved.begin(), moved.end(), order[k]) == moved.end()) frontOrder.push_back(order[k]);
            const auto at = std::find(frontOrder.begin(), frontOrder.end(), apex);
            const uint32_t frontRank = at != frontOrder.end() ? uint32_t(at - frontOrder.begin() + 1) : 0;
            EXPECT_EQ(lesson.front, frontRank) << "face " << face;

            ++checked;
            frontUsed += lesson.frontUsed ? 1 : 0;
            differ += lesson.plain != lesson.front ? 1 : 0;
            apexMovedUp += std::find(moved.begin(), moved.end(), apex) != moved.end() && lesson.frontUsed ? 1 : 0;
            apexPushedDown += lesson.front > lesson.plain ? 1 : 0;
            traversal.attachApex(edge, apex);
            attached[face] = 1;
        }
    }
    EXPECT_EQ(checked, faces - 1);
    // Every case of the computation was met: ranked in either order, the
    // apex a moved front neighbour (a count of nearer vertices) or not.
    EXPECT_GT(frontUsed, 100u);
    EXPECT_LT(frontUsed, checked);
    EXPECT_GT(apexMovedUp, 10u);
    EXPECT_GT(apexPushedDown, 10u);
    EXPECT_GT(differ, 100u);
}

// The front neighbours lever doubles the coder's contexts (the rank's
// place in the front order); without it the model keeps the plain ones.
TEST(EdgeModel, FrontLeverDoublesTheContexts) {
    const Mesh mesh = trayBottom();
    const std::vector<int32_t> grid = encode(mesh, drm_test::ranksOnly()).quantized;
    const std::unique_ptr<SpatialIndex> index = makeSpatialIndex(grid, NeighbourIndex::Grid, IndexRole::Traversal);
    Traversal traversal(mesh.vertexCount(), mesh.faceCount(), index.get());
    Levers withoutFront;
    withoutFront.frontNeighbours = false;
    const EdgeModel plain(grid, 12, Predictor::Midpoint, false, withoutFront, mesh.faceCount(), *index, traversal);
    const EdgeModel front(grid, 12, Predictor::Midpoint, false, Levers(), mesh.faceCount(), *index, traversal);
    EXPECT_EQ(plain.contextCount(), 16);
    EXPECT_EQ(front.contextCount(), 32);
}

uint64_t codeCount(const Stats& s) { return std::accumulate(s.rankHistogram.begin(), s.rankHistogram.end(), uint64_t(0)); }

// On a sliver-rich CAD mesh the lever changes the ranks (more rank 2 and
// 3, fewer far ranks) and makes the connectivity smaller; both ways the
// file decodes to the same mesh.
TEST(EdgeModel, FrontLeverOnCadSlivers) {
    const Mesh mesh = trayBottom();
    EncodeOptions on = drm_test::ranksOnly(), off = drm_test::ranksOnly();
    on.tryWithoutLevers = off.tryWithoutLevers = false;
    off.levers = withoutFront();
    const Encoded withFront = encode(mesh, on), without = encode(mesh, off);
    EXPECT_TRUE(withFront.stats.levers.frontNeighbours);
    EXPECT_FALSE(without.stats.levers.frontNeighbours);
    EXPECT_NE(withFront.stats.rankHistogram, without.stats.rankHistogram);
    EXPECT_EQ(codeCount(withFront.stats), codeCount(without.stats));
    // The front order saves more than a twentieth of the connectivity here.
    EXPECT_LT(double(withFront.stats.connectivityBytes), 0.95 * double(without.stats.connectivityBytes));
    for (const Encoded* e : {&withFront, &without}) {
        const Decoded decoded = decode(e->bytes);
        EXPECT_EQ(decoded.stats.rankHistogram, e->stats.rankHistogram);
        EXPECT_EQ(decoded.stats.levers.frontNeighbours, e->stats.levers.frontNeighbours);
        ASSERT_EQ(decoded.quantized.size(), e->quantized.size());
        std::vector<uint32_t> faces = decoded.mesh.triangles;
        for (uint32_t& v : faces) v = e->vertexOrder[v];
        std::vector<std::array<uint32_t, 3>> got, want;
        for (size_t f = 0; f < faces.size(); f += 3) {
            std::array<uint32_t, 3> t = {faces[f], faces[f + 1], faces[f + 2]};
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            got.push_back(t);
            std::array<uint32_t, 3> u = {mesh.triangles[f], mesh.triangles[f + 1], mesh.triangles[f + 2]};
            std::rotate(u.begin(), std::min_element(u.begin(), u.end()), u.end());
            want.push_back(u);
        }
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        EXPECT_EQ(got, want);
    }
}

}  // namespace
}  // namespace drm

namespace drm {
namespace {

Mesh testMesh(const std::string& name) { return drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name); }

Levers withoutBoundaryFlag() {
    Levers levers;
    levers.boundaryFlag = false;
    return levers;
}

// The mesh encoded with every lever and with all but the boundary flags,
// each component started at its smallest vertex and no lever-free trial,
// so that both make the same traversal and the same ranks.
struct BothWays {
    Encoded with, without;
};
BothWays encodeBothWays(const Mesh& mesh) {
    EncodeOptions on = drm_test::ranksOnly(), off = drm_test::ranksOnly();
    on.tryWithoutLevers = off.tryWithoutLevers = false;
    on.searchStarts = off.searchStarts = false;
    off.levers = withoutBoundaryFlag();
    return {encode(mesh, on), encode(mesh, off)};
}

// The mesh's triangles as a set of oriented triangles (each rotated to
// start at its smallest vertex), input numbering.
std::vector<std::array<uint32_t, 3>> orientedSet(const std::vector<uint32_t>& t) {
    std::vector<std::array<uint32_t, 3>> set;
    for (size_t f = 0; f + 2 < t.size(); f += 3) {
        std::array<uint32_t, 3> a = {t[f], t[f + 1], t[f + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        set.push_back(a);
    }
    std::sort(set.begin(), set.end());
    return set;
}

// Drives the model over a patch of 24 x 24 jittered quads (one open
// border of 96 edges) and sorts each edge's class by what it turned out
// to be. Past the border the size step finds nothing ahead (classes 6 to
// 8); inside the patch it finds a vertex in its first ball.
TEST(BoundaryFlag, ClassesTellTheBorderFromTheInside) {
    const Mesh mesh = drm_test::gridPatch(24, false, 0.2, 3);
    EncodeOptions options = drm_test::ranksOnly();
    options.tryWithoutLevers = false;
    const std::vector<int32_t> grid = encode(mesh, options).quantized;  // input order
    const MeshTopology topology = checkMesh(mesh);
    const std::unique_ptr<SpatialIndex> index = makeSpatialIndex(grid, NeighbourIndex::Grid, IndexRole::Traversal);
    Traversal traversal(mesh.vertexCount(), mesh.faceCount(), index.get());
    EdgeModel model(grid, 12, Predictor::Midpoint, false, Levers(), mesh.faceCount(), *index, traversal);
    std::array<size_t, kBoundaryClasses> border{}, inside{};
    traversal.startComponent(mesh.triangles[0], mesh.triangles[1], mesh.triangles[2]);
    OpenEdge edge;
    while (traversal.popOpenEdge(edge)) {
        const int c = model.forecast(edge).boundaryClass;
        ASSERT_GE(c, 0);
        ASSERT_LT(c, kBoundaryClasses);
        uint32_t face = 0;
        const uint32_t apex = topology.apexAcross(edge.vi, edge.vj, &face);
        if (apex == kNoVertex) {
            ++border[size_t(c)];
            traversal.closeAsBoundary(edge);
        } else {
            ++inside[size_t(c)];
            model.rankOf(apex, edge);
            model.resolved(apex);
            traversal.attachApex(edge, apex);
        }
    }
    ASSERT_EQ(traversal.triangleCount(), mesh.faceCount());
    size_t borderEdges = 0, insideEdges = 0, borderNothingAhead = 0, insideNothingAhead = 0, insideFirstBall = 0;
    for (int c = 0; c < kBoundaryClasses; ++c) {
        borderEdges += border[size_t(c)];
        insideEdges += inside[size_t(c)];
        if (c >= 6) borderNothingAhead += border[size_t(c)], insideNothingAhead += inside[size_t(c)];
        if (c < 3) insideFirstBall += inside[size_t(c)];
    }
    EXPECT_EQ(borderEdges, 4u * 24u);
    EXPECT_GE(borderNothingAhead, borderEdges * 9 / 10);
    EXPECT_LE(insideNothingAhead, insideEdges / 100);
    EXPECT_GE(insideFirstBall, insideEdges * 9 / 10);
    // Most of the border is coded edge after edge: its fans end on it.
    EXPECT_GE(border[7] + border[8], borderEdges / 2);
}

// On meshes with holes the ranks stay the same, face for face, and the
// stream shrinks; both files decode to the input's triangles.
TEST(BoundaryFlag, MeshesWithHolesCodeSmallerWithTheSameRanks) {
    for (const char* name : {"mech-holes-shark.ply", "elephant-with-holes.ply", "blobby-3cc.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = testMesh(name);
        const BothWays both = encodeBothWays(mesh);
        const Encoded &with = both.with, &without = both.without;
        EXPECT_TRUE(with.stats.levers.boundaryFlag);
        EXPECT_FALSE(without.stats.levers.boundaryFlag);
        ASSERT_GT(with.stats.rankHistogram.size(), 0u);
        EXPECT_GT(with.stats.rankHistogram[0], 0u);
        EXPECT_EQ(with.stats.rankHistogram, without.stats.rankHistogram);
        EXPECT_EQ(with.faceRank, without.faceRank);  // face by face
        // On these meshes with holes the flags save more than a tenth of
        // the connectivity.
        EXPECT_LT(double(with.stats.connectivityBytes), 0.9 * double(without.stats.connectivityBytes));
        for (const Encoded* e : {&with, &without}) {
            const Decoded decoded = decode(e->bytes);
            EXPECT_EQ(decoded.stats.levers.boundaryFlag, e->stats.levers.boundaryFlag);
            EXPECT_EQ(decoded.stats.rankHistogram, e->stats.rankHistogram);
            std::vector<uint32_t> faces = decoded.mesh.triangles;
            for (uint32_t& v : faces) v = e->vertexOrder[v];
            EXPECT_EQ(orientedSet(faces), orientedSet(mesh.triangles));
        }
    }
}

// A closed mesh has no boundary edge: nearly every flag is a "no" in the
// class of edges with a vertex in the first ball, which costs a few bytes
// in all.
TEST(BoundaryFlag, ClosedMeshesPayLittle) {
    for (const char* name : {"torus.ply", "fandisk.ply", "genus3.ply"}) {
        SCOPED_TRACE(name);
        const BothWays both = encodeBothWays(testMesh(name));
        const Encoded &with = both.with, &without = both.without;
        EXPECT_EQ(with.faceRank, without.faceRank);
        EXPECT_LE(with.stats.connectivityBytes, without.stats.connectivityBytes + 4);
    }
}

TEST(BoundaryFlag, IsALeverOfItsOwn) {
    EXPECT_STREQ(leverName(5), "boundary");
    Levers only = Levers::none();
    only.boundaryFlag = true;
    EXPECT_EQ(leversName(only), "boundary");
    EXPECT_EQ(leversName(parseLevers("boundary")), "boundary");
    EXPECT_EQ(leversName(withoutBoundaryFlag()), "filter,gap,context,angle,front");
    EXPECT_EQ(leversName(Levers()), "all");
}

}  // namespace
}  // namespace drm
