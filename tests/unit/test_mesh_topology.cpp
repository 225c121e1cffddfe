// MeshTopology, the encoder's table of directed edges, against a plain
// search of the faces: every edge's face and apex, a hub vertex whose many
// edges are searched by halving, and the message for a directed edge in two
// faces, which names the pair met first face by face; the table built
// without the checks is the same.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "common.h"
#include "mesh_check.h"

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

}  // namespace
}  // namespace drm
