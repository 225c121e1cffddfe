// The manifold report counts each kind of problem and names the first one.
#include <drm/drm.h>
#include <drm_vcg/manifold.h>

#include <gtest/gtest.h>

namespace {

using drm::vcgio::checkManifold;

drm::Mesh meshOf(size_t vertexCount, std::vector<uint32_t> triangles) {
    drm::Mesh mesh;
    for (size_t i = 0; i < vertexCount; ++i) {
        mesh.positions.push_back(float(i % 3));
        mesh.positions.push_back(float(i / 3));
        mesh.positions.push_back(float(i * i % 5));
    }
    mesh.triangles = std::move(triangles);
    return mesh;
}

// A closed, consistently oriented tetrahedron.
const std::vector<uint32_t> kTetrahedron = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};

TEST(CheckManifold, AcceptsAClosedTetrahedronAndAnOpenStrip) {
    EXPECT_TRUE(checkManifold(meshOf(4, kTetrahedron)).ok());
    const drm::vcgio::ManifoldReport strip = checkManifold(meshOf(4, {0, 1, 2, 2, 1, 3}));
    EXPECT_TRUE(strip.ok());
    EXPECT_EQ(strip.summary(), "manifold and consistently oriented");
}

TEST(CheckManifold, CountsAFin) {
    const auto report = checkManifold(meshOf(5, {0, 1, 2, 1, 0, 3, 0, 1, 4}));
    EXPECT_EQ(report.nonManifoldEdges, 1u);
    EXPECT_FALSE(report.ok());
    EXPECT_EQ(report.firstProblem, "edge (0, 1) is shared by 3 faces (0, 1, 2)");
}

TEST(CheckManifold, CountsABowTieVertex) {
    // Two triangles touching only at vertex 2.
    const auto report = checkManifold(meshOf(5, {0, 1, 2, 2, 3, 4}));
    EXPECT_EQ(report.nonManifoldEdges, 0u);
    EXPECT_EQ(report.nonManifoldVertices, 1u);
    EXPECT_EQ(report.firstProblem, "vertex 2 joins faces that do not form a single fan around it");
}

TEST(CheckManifold, CountsInconsistentOrientation) {
    const auto report = checkManifold(meshOf(4, {0, 1, 2, 1, 2, 3}));
    EXPECT_EQ(report.misorientedEdges, 1u);
    EXPECT_NE(report.firstProblem.find("faces 0 and 1"), std::string::npos) << report.firstProblem;
}

TEST(CheckManifold, CountsFacesRepeatingAVertexFirst) {
    std::vector<uint32_t> triangles = kTetrahedron;
    triangles.insert(triangles.end(), {3, 3, 1});
    const auto report = checkManifold(meshOf(4, triangles));
    EXPECT_EQ(report.facesRepeatingVertex, 1u);
    EXPECT_EQ(report.firstProblem, "face 4 (3, 3, 1) uses a vertex twice");
    EXPECT_NE(report.summary().find("1 face repeating a vertex; first: face 4"), std::string::npos) << report.summary();
}

TEST(CheckManifold, RefusesIndicesOutOfRange) {
    EXPECT_THROW(checkManifold(meshOf(3, {0, 1, 5})), drm::Error);
}

}  // namespace
