// The traversal and the whole codec on hand-made meshes: code counts
// (T + B - 1 per component), culling, holes, several components, the
// refusal of a directed edge used twice, the fan pieces against a walk
// around each fan, and a fan of high valence.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <set>
#include <string>

#include "drmcodec/drmcodec.h"
#include "connectivity/ranked/gap_closing.h"
#include "mesh/mesh_check.h"
#include "tiny_ply.h"
#include "connectivity/traversal.h"

namespace drm {
namespace {

Mesh gridPatch(int n, int m) {  // an n x m grid of quads, each split in two: an open square patch
    Mesh mesh;
    for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= n; ++i) mesh.positions.insert(mesh.positions.end(), {float(i), float(j), 0.f});
    auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return mesh;
}

std::multiset<std::array<uint32_t, 3>> orientedTriangles(const Mesh& mesh) {
    std::multiset<std::array<uint32_t, 3>> set;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        std::array<uint32_t, 3> t = {mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        set.insert(t);
    }
    return set;
}

uint64_t codeCount(const Stats& s) {
    return std::accumulate(s.rankHistogram.begin(), s.rankHistogram.end(), uint64_t(0));
}

void expectRoundTrip(const Mesh& mesh, uint64_t boundaryEdges, uint64_t components) {
    for (GeometryCoder geometry : {GeometryCoder::SpanningTree, GeometryCoder::Raw}) {
        for (bool levers : {true, false}) {
            EncodeOptions options;
            options.geometry = geometry;
            if (!levers) options.levers = Levers::none();
            options.tryWithoutLevers = false;
            const Encoded encoded = encode(mesh, options);
            EXPECT_EQ(encoded.stats.boundaryEdges, boundaryEdges);
            EXPECT_EQ(encoded.stats.components, components);
            EXPECT_EQ(codeCount(encoded.stats), mesh.faceCount() + boundaryEdges - components);
            const Decoded decoded = decode(encoded.bytes);
            ASSERT_EQ(decoded.quantized.size(), encoded.quantized.size());
            Mesh inInputIndices = decoded.mesh;
            for (size_t d = 0; d < encoded.vertexOrder.size(); ++d)
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(decoded.quantized[3 * d + k], encoded.quantized[3 * size_t(encoded.vertexOrder[d]) + k]);
            for (uint32_t& v : inInputIndices.triangles) v = encoded.vertexOrder[v];
            EXPECT_EQ(orientedTriangles(inInputIndices), orientedTriangles(mesh));
            EXPECT_EQ(decoded.stats.rankHistogram, encoded.stats.rankHistogram);
            if (geometry == GeometryCoder::Raw)
                for (size_t d = 0; d < encoded.vertexOrder.size(); ++d) EXPECT_EQ(encoded.vertexOrder[d], d);
        }
    }
}

TEST(Traversal, SingleTriangleCodesThreeBoundaries) {
    Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    expectRoundTrip(mesh, 3, 1);
}

TEST(Traversal, ClosedTetrahedronNeedsThreeCodes) { expectRoundTrip(tetrahedron(), 0, 1); }

TEST(Traversal, OpenPatchCodesItsBoundary) {
    const Mesh mesh = gridPatch(6, 4);
    expectRoundTrip(mesh, 2 * (6 + 4), 1);
}

TEST(Traversal, PatchWithAHole) {
    Mesh mesh = gridPatch(5, 5);
    // Drop the two triangles of the centre quad (2, 2): an inner boundary loop of 4 edges.
    const size_t centre = 2 * (2 * 5 + 2);
    mesh.triangles.erase(mesh.triangles.begin() + 3 * centre, mesh.triangles.begin() + 3 * (centre + 2));
    expectRoundTrip(mesh, 2 * (5 + 5) + 4, 1);
}

TEST(Traversal, SeveralComponentsAndIsolatedVertices) {
    Mesh mesh = tetrahedron();
    Mesh patch = gridPatch(3, 2);
    const uint32_t offset = uint32_t(mesh.vertexCount());
    for (float& x : patch.positions) x += 5.f;
    mesh.positions.insert(mesh.positions.end(), patch.positions.begin(), patch.positions.end());
    for (uint32_t v : patch.triangles) mesh.triangles.push_back(v + offset);
    mesh.positions.insert(mesh.positions.end(), {9.f, 9.f, 9.f, -1.f, 2.f, 3.f});  // two isolated vertices
    expectRoundTrip(mesh, 2 * (3 + 2), 2);
}

TEST(Traversal, CullsEveryVertexOfAClosedMesh) {
    Traversal traversal(4, 4, nullptr);
    traversal.startComponent(0, 2, 1);
    OpenEdge edge;
    ASSERT_TRUE(traversal.popOpenEdge(edge));
    EXPECT_EQ(edge.vi, 0u);
    EXPECT_EQ(edge.vj, 2u);
    EXPECT_EQ(edge.opposite, 1u);
    traversal.attachApex(edge, 3);  // triangle (2, 0, 3)
    EXPECT_FALSE(traversal.isCulled(0));
    // The apexes across the next open edges, (0, 3) and (2, 1), are 1 and 3;
    // (0, 1) is closed as soon as it is pushed and must be skipped.
    const uint32_t next[2] = {1, 3};
    int more = 0;
    while (traversal.popOpenEdge(edge)) {
        ASSERT_LT(more, 2);
        traversal.attachApex(edge, next[more++]);
    }
    EXPECT_EQ(more, 2);
    for (uint32_t v = 0; v < 4; ++v) EXPECT_TRUE(traversal.isCulled(v)) << v;
}

TEST(Traversal, RejectsAReusedDirectedEdge) {
    Traversal traversal(5, 4, nullptr);
    traversal.startComponent(0, 1, 2);
    OpenEdge edge;
    ASSERT_TRUE(traversal.popOpenEdge(edge));  // (0, 1)
    EXPECT_THROW(traversal.attachApex(edge, 0), Error);  // an end of the edge itself
    traversal.attachApex(edge, 3);                       // triangle (1, 0, 3)
    ASSERT_TRUE(traversal.popOpenEdge(edge));            // its left edge (0, 3) comes first
    EXPECT_EQ(edge.vi, 0u);
    EXPECT_EQ(edge.vj, 3u);
    EXPECT_THROW(traversal.attachApex(edge, 1), Error);  // (3, 0, 1) would reuse 0->1
}

// The far end of the rebuilt fan around `center` from the triangle (center,
// start, o), walked triangle by triangle (as fanEnds walks it where the
// traversal keeps no fan pieces): kNoVertex, with *boundary set, where the
// fan ends on a coded boundary edge.
uint32_t walkedFanEnd(const Traversal& t, uint32_t center, uint32_t o, bool clockwise, bool* boundary) {
    uint32_t far = o;
    for (size_t step = 0; step <= t.vertexCount(); ++step) {
        const uint32_t next = clockwise ? t.thirdVertex(far, center) : t.thirdVertex(center, far);
        if (next == Traversal::kNoTriangle) return far;
        if (next == Traversal::kBoundary) {
            *boundary = true;
            return kNoVertex;
        }
        far = next;
    }
    ADD_FAILURE() << "the fan around " << center << " has no end";
    return kNoVertex;
}

// Rebuilds a mesh with its true apexes, in the paper's order and depth
// first, and at every open edge checks fanEnds (the traversal's fan pieces,
// one look-up each, as the topological coder keeps them) against the walk
// around each end.
void expectFanEndsAsWalked(const Mesh& mesh, bool depthFirst) {
    MeshTopology topology;
    ASSERT_EQ(topologyProblem(mesh.triangles, mesh.vertexCount(), &topology), "");
    Traversal t(mesh.vertexCount(), mesh.faceCount(), nullptr);
    if (depthFirst) t.setDepthFirst();
    t.trackFanPieces();
    std::vector<uint8_t> faceDone(mesh.faceCount(), 0);
    size_t checked = 0, withEnds = 0, onBoundary = 0, boundaryEdges = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        if (faceDone[f]) continue;
        const uint32_t* v = &mesh.triangles[3 * f];
        if (t.isTouched(v[0]) || t.isTouched(v[1]) || t.isTouched(v[2])) continue;  // left for its own component
        t.startComponent(v[0], v[1], v[2]);
        faceDone[f] = 1;
        OpenEdge edge;
        while (t.popOpenEdge(edge)) {
            FanEnds walked;
            walked.atI = walkedFanEnd(t, edge.vi, edge.opposite, false, &walked.boundaryAtI);
            walked.atJ = walkedFanEnd(t, edge.vj, edge.opposite, true, &walked.boundaryAtJ);
            if (walked.atI == edge.opposite) walked.atI = kNoVertex;
            if (walked.atJ == edge.opposite) walked.atJ = kNoVertex;
            const FanEnds ends = fanEnds(edge, t);
            ASSERT_EQ(ends.atI, walked.atI) << "edge " << edge.vi << "-" << edge.vj;
            ASSERT_EQ(ends.atJ, walked.atJ) << "edge " << edge.vi << "-" << edge.vj;
            ASSERT_EQ(ends.boundaryAtI, walked.boundaryAtI);
            ASSERT_EQ(ends.boundaryAtJ, walked.boundaryAtJ);
            ++checked;
            withEnds += ends.atI != kNoVertex || ends.atJ != kNoVertex;
            onBoundary += ends.boundaryAtI || ends.boundaryAtJ;
            uint32_t face = 0;
            const uint32_t apex = topology.apexAcross(edge.vi, edge.vj, &face);
            if (apex == kNoVertex) {
                t.closeAsBoundary(edge);
                ++boundaryEdges;
            } else {
                t.attachApex(edge, apex);
                faceDone[face] = 1;
            }
        }
    }
    EXPECT_EQ(t.triangleCount(), mesh.faceCount());
    EXPECT_GT(withEnds, checked / 4);  // the test sees real fans, not only single triangles
    if (boundaryEdges > 0) EXPECT_GT(onBoundary, 0u);  // and fans that end on a coded boundary
}

TEST(Traversal, FanPiecesGiveTheEndsAWalkAroundTheFanFinds) {
    for (const char* name : {"bunny-lres.ply", "elephant-with-holes.ply", "fandisk.ply", "mech-holes-shark.ply",
                             "tray-bottom.ply", "genus3.ply", "blobby-3cc.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name);
        for (bool depthFirst : {false, true}) expectFanEndsAsWalked(mesh, depthFirst);
    }
}

// A disc fanned around its centre: every open edge at the centre asked for
// its fan's end. The walk made that O(valence) per edge (40,000 triangles
// took 14 s to decode topologically); the pieces answer it at once. Both
// coders round-trip it (the ranks, which walk, at this size), and Auto
// takes the topological coder alone.
TEST(Traversal, AHighValenceFanRoundTrips) {
    const uint32_t rim = 3000;
    Mesh disc;
    disc.positions = {0, 0, 0};
    for (uint32_t k = 0; k < rim; ++k) {
        // Points on a square's outline (no trigonometry): a fan of slivers.
        const float u = float(k % (rim / 4)) / float(rim / 4), side = float(k / (rim / 4));
        const float x = side == 0 ? u : side == 1 ? 1 : side == 2 ? 1 - u : 0;
        const float y = side == 0 ? 0 : side == 1 ? u : side == 2 ? 1 : 1 - u;
        disc.positions.insert(disc.positions.end(), {x - 0.5f, y - 0.5f, 0.f});
    }
    for (uint32_t k = 0; k < rim; ++k) disc.triangles.insert(disc.triangles.end(), {0, 1 + k, 1 + (k + 1) % rim});
    expectFanEndsAsWalked(disc, false);
    expectFanEndsAsWalked(disc, true);
    // Auto codes a mesh with such a hub topologically alone (the ranks'
    // searches around it would cost about the valence squared).
    for (ConnectivityCoder coder : {ConnectivityCoder::Ranks, ConnectivityCoder::Topological, ConnectivityCoder::Auto}) {
        SCOPED_TRACE(connectivityCoderName(coder));
        EncodeOptions options;
        options.connectivity = coder;
        options.bits = 16;
        options.keepVertexOrder = true;
        std::set<std::string> stages;
        options.progress = [&](double, const char* stage) {
            stages.insert(stage);
            return true;
        };
        const Encoded encoded = encode(disc, options);
        EXPECT_EQ(encoded.stats.connectivity, coder == ConnectivityCoder::Ranks ? coder : ConnectivityCoder::Topological);
        EXPECT_EQ(stages.count("ranking"), coder == ConnectivityCoder::Ranks ? 1u : 0u) << "the ranks' attempt";
        const Mesh decoded = decode(encoded.bytes).mesh;
        EXPECT_EQ(orientedTriangles(decoded), orientedTriangles(disc));
    }
}

// Without a hub, Auto makes both attempts (the ranks' first).
TEST(Traversal, AutoRanksAMeshWithoutHubs) {
    std::set<std::string> stages;
    EncodeOptions options;
    options.progress = [&](double, const char* stage) {
        stages.insert(stage);
        return true;
    };
    encode(gridPatch(40, 40), options);
    EXPECT_EQ(stages.count("ranking"), 1u);
    EXPECT_EQ(stages.count("coding topologically"), 1u);
}

}  // namespace
}  // namespace drm
