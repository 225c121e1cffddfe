// The boundary flag lever (format 10): whether an edge is a boundary edge is
// coded apart from its rank, in a context of what the decoder sees around
// the edge. Checked here: that this context separates boundary edges from
// the others on a patch with one open border; that on meshes with holes the
// lever makes the rank stream smaller without changing a single rank, and
// decodes; that a closed mesh pays only a few bytes for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "ranks_only.h"
#include "drm/drm.h"
#include "connectivity/ranked/edge_model.h"
#include "mesh/mesh_check.h"
#include "entropy/rank_coder.h"
#include "spatial/spatial_index.h"
#include "test_meshes.h"
#include "tiny_ply.h"
#include "connectivity/traversal.h"

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
        // When this test was written: mech-holes-shark 208 -> 152 bytes,
        // elephant-with-holes 615 -> 521, blobby-3cc 122 -> 81.
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
// in all (none on these three when this test was written).
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
