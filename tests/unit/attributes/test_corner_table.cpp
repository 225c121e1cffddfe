// The corner table (attributes/corner_table.h) against a plain search of
// the faces: each vertex lists exactly its corners, in corner order; two
// corners are opposite exactly when their edges are one undirected edge
// of exactly those two faces, both with three distinct vertices (so not
// on a boundary, a fin of three faces or a face repeating a vertex);
// opposites pair up; each interior edge is listed once, by its lower
// corner, in order; and opposites added later are the same table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "attributes/corner_table.h"
#include "test_meshes.h"

namespace drm {
namespace {

bool degenerate(const std::vector<uint32_t>& t, size_t f) {
    return t[3 * f] == t[3 * f + 1] || t[3 * f + 1] == t[3 * f + 2] || t[3 * f] == t[3 * f + 2];
}

// The opposite of corner c by its definition, searching every face.
uint32_t oppositeBySearch(const std::vector<uint32_t>& t, uint32_t c) {
    const size_t f = c / 3;
    if (degenerate(t, f)) return kNoCorner;
    const uint32_t u = t[nextCorner(c)], v = t[previousCorner(c)];
    uint32_t found = kNoCorner, count = 0;
    for (size_t g = 0; g < t.size() / 3; ++g) {
        if (g == f || degenerate(t, g)) continue;
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t o = uint32_t(3 * g + k);
            const uint32_t a = t[nextCorner(o)], b = t[previousCorner(o)];
            if ((a == u && b == v) || (a == v && b == u)) {
                ++count;
                found = o;
            }
        }
    }
    return count == 1 ? found : kNoCorner;
}

void expectAgreesWithSearch(const std::vector<uint32_t>& t, size_t vertexCount) {
    const CornerTable table = buildCornerTable(t, vertexCount);
    ASSERT_EQ(table.cornerStart.size(), vertexCount + 1);
    for (uint32_t v = 0; v < vertexCount; ++v) {
        std::vector<uint32_t> expected;
        for (uint32_t c = 0; c < t.size(); ++c)
            if (t[c] == v) expected.push_back(c);
        const std::vector<uint32_t> listed(table.vertexCorners.begin() + table.cornerStart[v],
                                           table.vertexCorners.begin() + table.cornerStart[v + 1]);
        ASSERT_EQ(listed, expected) << "vertex " << v;
    }
    ASSERT_EQ(table.opposite.size(), t.size());
    std::vector<uint32_t> interior;
    for (uint32_t c = 0; c < t.size(); ++c) {
        const uint32_t o = table.opposite[c];
        ASSERT_EQ(o, oppositeBySearch(t, c)) << "corner " << c;
        if (o == kNoCorner) continue;
        ASSERT_EQ(table.opposite[o], c);  // they pair up
        if (c < o) interior.push_back(c);
    }
    EXPECT_EQ(table.interiorEdges, interior);
    // Built without opposites, then given them: the same table.
    CornerTable later = buildCornerTable(t, vertexCount, false);
    EXPECT_TRUE(later.opposite.empty());
    EXPECT_TRUE(later.interiorEdges.empty());
    EXPECT_EQ(later.vertexCorners, table.vertexCorners);
    addOpposites(later, t);
    EXPECT_EQ(later.opposite, table.opposite);
    EXPECT_EQ(later.interiorEdges, table.interiorEdges);
}

TEST(CornerTable, CornersStepAroundTheirFace) {
    for (uint32_t c = 0; c < 30; ++c) {
        EXPECT_EQ(nextCorner(c) / 3, c / 3);
        EXPECT_EQ(previousCorner(c) / 3, c / 3);
        EXPECT_EQ(nextCorner(nextCorner(nextCorner(c))), c);
        EXPECT_EQ(previousCorner(nextCorner(c)), c);
        EXPECT_EQ(nextCorner(c) % 3, (c % 3 + 1) % 3);
    }
    const std::vector<uint32_t> t = {4, 5, 6, 6, 5, 7};
    EXPECT_EQ(cornerAt(t, 1, 5), 4u);
    EXPECT_EQ(cornerAt(t, 1, 7), 5u);
    EXPECT_EQ(cornerAt(t, 0, 7), kNoCorner);
}

TEST(CornerTable, AClosedMeshHasAnOppositeForEveryCorner) {
    const Mesh sphere = drm_test::icosphere(2);
    expectAgreesWithSearch(sphere.triangles, sphere.vertexCount());
    const CornerTable table = buildCornerTable(sphere.triangles, sphere.vertexCount());
    EXPECT_EQ(std::count(table.opposite.begin(), table.opposite.end(), kNoCorner), 0);
    EXPECT_EQ(table.interiorEdges.size(), sphere.triangles.size() / 2);  // E = 3F / 2
}

TEST(CornerTable, BoundariesHolesAndIsolatedVertices) {
    const Mesh patch = drm_test::gridPatch(6, true);  // a hole and an isolated centre vertex
    expectAgreesWithSearch(patch.triangles, patch.vertexCount());
    const Mesh mixed = drm_test::mixedMesh();
    expectAgreesWithSearch(mixed.triangles, mixed.vertexCount());
}

TEST(CornerTable, FinsAndFacesRepeatingAVertexHaveNoOpposites) {
    // Three faces on the edge 0-1 (a fin), a face repeating vertex 4, and
    // two faces sharing the edge 2-5 in the same direction (still one
    // undirected edge of exactly two faces).
    const std::vector<uint32_t> t = {0, 1, 2, 1, 0, 3, 0, 1, 4, 4, 4, 2, 2, 5, 6, 2, 5, 7};
    expectAgreesWithSearch(t, 8);
    const CornerTable table = buildCornerTable(t, 8);
    for (uint32_t c : {2u, 5u, 8u}) EXPECT_EQ(table.opposite[c], kNoCorner) << c;  // the fin's corners
    for (uint32_t c : {9u, 10u, 11u}) EXPECT_EQ(table.opposite[c], kNoCorner) << c;
    EXPECT_EQ(table.opposite[14], 17u);
}

}  // namespace
}  // namespace drm
