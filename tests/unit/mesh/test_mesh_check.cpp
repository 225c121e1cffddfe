// MeshTopology, the encoder's table of directed edges, against a plain
// search of the faces: every edge's face and apex, a hub vertex whose many
// edges are searched by halving, and the message for a directed edge in two
// faces, which names the pair met first face by face; the table built
// without the checks is the same; and the message for a vertex of two fans
// or more, which names the vertex and face a union of corners meets first.
// Through encode(): what is refused (named) and what is cut and repaired.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "common.h"
#include "mesh/mesh_check.h"

namespace drm {
namespace {

// The face holding (a, b) by looking at every face.
uint32_t faceBySearch(const std::vector<uint32_t>& t, uint32_t a, uint32_t b) {
    for (size_t f = 0; f < t.size() / 3; ++f)
        for (int k = 0; k < 3; ++k)
            if (t[3 * f + k] == a && t[3 * f + (k + 1) % 3] == b) return uint32_t(f);
    return kNoIndex;
}

void expectAgreesWithSearch(const std::vector<uint32_t>& t, size_t vertexCount) {
    MeshTopology topology;
    ASSERT_EQ(topologyProblem(t, vertexCount, &topology), "");
    // The table alone, unchecked (the encoder's for faces known to pass),
    // is the same table.
    MeshTopology unchecked;
    buildTopology(t, vertexCount, &unchecked);
    ASSERT_EQ(unchecked.start, topology.start);
    ASSERT_EQ(unchecked.out.size(), topology.out.size());
    for (size_t i = 0; i < topology.out.size(); ++i) {
        ASSERT_EQ(unchecked.out[i].to, topology.out[i].to);
        ASSERT_EQ(unchecked.out[i].face, topology.out[i].face);
    }
    for (uint32_t a = 0; a < vertexCount; ++a)
        for (uint32_t b = 0; b < vertexCount; ++b) {
            const uint32_t expected = faceBySearch(t, a, b);
            ASSERT_EQ(topology.faceOf(a, b), expected) << a << "->" << b;
            uint32_t face = 0;
            const uint32_t apex = topology.apexAcross(b, a, &face);
            ASSERT_EQ(face, expected);
            if (expected == kNoIndex) {
                ASSERT_EQ(apex, kNoVertex);
            } else {
                const uint32_t* f = t.data() + 3 * size_t(expected);
                ASSERT_TRUE(apex != a && apex != b && (apex == f[0] || apex == f[1] || apex == f[2]));
            }
        }
}

TEST(MeshTopology, EveryDirectedEdgeOfAClosedMesh) {
    // An octahedron: every vertex has four neighbours.
    const std::vector<uint32_t> t = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    expectAgreesWithSearch(t, 6);
}

TEST(MeshTopology, AHubSearchedByHalving) {
    // A disc of 40 triangles around vertex 0: 40 edges leave it, more than
    // are searched one by one.
    std::vector<uint32_t> t;
    const uint32_t rim = 40;
    for (uint32_t i = 0; i < rim; ++i) t.insert(t.end(), {0, 1 + i, 1 + (i + 1) % rim});
    expectAgreesWithSearch(t, rim + 1);
}

// Vertices without faces (the round-trip fuzzer's find: the empty edge
// array has no storage to point into, which UBSan caught).
TEST(MeshTopology, NoFacesAtAll) {
    MeshTopology topology;
    EXPECT_EQ(topologyProblem(std::vector<uint32_t>(), 3, &topology), "");
    EXPECT_EQ(topology.faceOf(0, 1), kNoIndex);
    EXPECT_EQ(topology.apexAcross(1, 2, nullptr), kNoVertex);
}

TEST(MeshTopology, ADirectedEdgeInTwoFacesIsNamedAsMetFaceByFace) {
    // 3->4 is repeated by face 2, 0->1 only by face 3: face 2's clash comes
    // first, though vertex 0's edges are looked at before vertex 3's.
    const std::vector<uint32_t> t = {0, 1, 2, 3, 4, 5, 3, 4, 6, 0, 1, 7};
    MeshTopology topology;
    EXPECT_EQ(topologyProblem(t, 8, &topology),
              "face 2 (3, 4, 6) and face 1 (3, 4, 5) both contain the directed edge 3->4: "
              "the mesh is non-manifold or inconsistently oriented there");
    // Three faces on one directed edge: the second is named, with the first.
    const std::vector<uint32_t> three = {5, 6, 0, 1, 2, 3, 1, 2, 4, 1, 2, 0};
    EXPECT_EQ(topologyProblem(three, 7, &topology),
              "face 2 (1, 2, 4) and face 1 (1, 2, 3) both contain the directed edge 1->2: "
              "the mesh is non-manifold or inconsistently oriented there");
}

// The message a union of corners gives: corners at one vertex joined when
// their faces share an edge there, the first corner (face by face) whose
// vertex's first corner lies in another set named. The check walks each
// vertex's own fan instead; both must name the same vertex and face.
std::string twoFansBySearch(const std::vector<uint32_t>& t, size_t vertexCount) {
    std::vector<uint32_t> set(t.size());
    for (size_t c = 0; c < t.size(); ++c) set[c] = uint32_t(c);
    auto root = [&](uint32_t c) {
        while (set[c] != c) c = set[c];
        return c;
    };
    for (size_t f = 0; f < t.size() / 3; ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = t[3 * f + k], next = t[3 * f + (k + 1) % 3];
            const uint32_t g = faceBySearch(t, next, v);
            if (g == kNoIndex) continue;
            for (int j = 0; j < 3; ++j)
                if (t[3 * size_t(g) + j] == v) set[root(uint32_t(3 * f + k))] = root(uint32_t(3 * g + j));
        }
    std::vector<uint32_t> fanOf(vertexCount, kNoIndex);
    for (size_t c = 0; c < t.size(); ++c) {
        const uint32_t v = t[c];
        if (fanOf[v] == kNoIndex) fanOf[v] = root(uint32_t(c));
        else if (fanOf[v] != root(uint32_t(c))) {
            const size_t f = c / 3;
            return "vertex " + std::to_string(v) + " is non-manifold: its faces form more than one fan (first seen at face " +
                   std::to_string(f) + " (" + std::to_string(t[3 * f]) + ", " + std::to_string(t[3 * f + 1]) + ", " +
                   std::to_string(t[3 * f + 2]) + "))";
        }
    }
    return "";
}

TEST(MeshTopology, AVertexOfTwoFansIsNamedAsMetFaceByFace) {
    const std::vector<std::vector<uint32_t>> meshes = {
        // Two triangles touching at vertex 0 (a bowtie).
        {0, 1, 2, 0, 3, 4},
        // Vertex 0's second fan met before its first is closed: face 1
        // lies in another fan than face 0, though face 2 joins face 0.
        {0, 1, 2, 0, 3, 4, 0, 2, 5},
        // Two closed cones sharing their apex 0: neither fan has an end.
        {0, 1, 2, 0, 2, 3, 0, 3, 1, 0, 4, 5, 0, 5, 6, 0, 6, 4},
        // A closed cone and an open fan at 0, and a later vertex of two
        // fans (7) whose corner comes first.
        {0, 1, 2, 0, 2, 3, 7, 8, 9, 0, 3, 1, 7, 10, 11, 0, 4, 5, 0, 5, 6},
        // Two vertices of two fans each, whose first stray corners lie in
        // one face (face 2): vertex 1's comes first there.
        {0, 2, 3, 1, 4, 5, 1, 0, 6},
        // Three fans around a hub of more than 16 edges (searched by halving).
        {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 7, 0, 7, 8, 0, 8, 9, 0, 9, 10, 0, 11, 12, 0, 12, 13,
         0, 13, 14, 0, 14, 15, 0, 15, 16, 0, 16, 17, 0, 17, 18, 0, 18, 19, 0, 20, 21},
    };
    for (const std::vector<uint32_t>& t : meshes) {
        const size_t vertexCount = *std::max_element(t.begin(), t.end()) + 1;
        const std::string expected = twoFansBySearch(t, vertexCount);
        ASSERT_NE(expected, "");
        MeshTopology topology;
        EXPECT_EQ(topologyProblem(t, vertexCount, &topology), expected);
    }
    // One fan, open or closed, passes.
    MeshTopology topology;
    EXPECT_EQ(topologyProblem(std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}, 5, &topology), "");
    EXPECT_EQ(topologyProblem(std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1}, 4, &topology), "");
}

// A closed tetrahedron, outward-facing.
Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return mesh;
}

TEST(MeshCheck, RefusesOnlyWhatNoFileCanHold) {
    // A refusal is InvalidInput, and its message names the element at
    // fault (drmcodec.h's promise): the text is checked for that.
    auto message = [](const Mesh& m) {
        try {
            encode(m);
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::InvalidInput) << e.what();
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    Mesh empty;
    EXPECT_NE(message(empty).find("empty"), std::string::npos);

    Mesh badIndex = tetrahedron();
    badIndex.triangles[4] = 7;
    EXPECT_NE(message(badIndex).find("refers to vertex 7"), std::string::npos);

    // Meshes the traversal cannot take as they are are cut and repaired,
    // not refused (tests/adversarial checks that they come back exactly).
    Mesh repeated = tetrahedron();
    repeated.triangles[1] = repeated.triangles[0];
    EXPECT_EQ(message(repeated), "accepted");

    Mesh flipped = tetrahedron();
    std::swap(flipped.triangles[1], flipped.triangles[2]);
    EXPECT_EQ(message(flipped), "accepted");

    Mesh fin;  // three faces on edge 0-1
    fin.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    fin.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    EXPECT_EQ(message(fin), "accepted");

    Mesh nan = tetrahedron();
    nan.positions[5] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(message(nan).find("vertex 1 has a non-finite coordinate"), std::string::npos);

    EncodeOptions tooManyBits;
    tooManyBits.bits = 22;
    EXPECT_THROW(encode(tetrahedron(), tooManyBits), Error);
}

}  // namespace
}  // namespace drm
