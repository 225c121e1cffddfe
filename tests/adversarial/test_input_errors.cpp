// What no repair can save: an empty mesh, a coordinate that is not a
// number or not finite, a face naming a vertex that does not exist. encode
// throws drm::Error, and its message names the problem.
#include <drm/drm.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <limits>
#include <string>

#include "adversarial_options.h"
#include "test_meshes.h"

namespace adversarial {
namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Success if encode(mesh) throws drm::Error of kind InvalidInput whose
// message contains one of the keywords (case-insensitive), with every
// option set: the text is checked because naming the problem for the user
// is the behaviour under test.
::testing::AssertionResult refusedNaming(const drm::Mesh& mesh, std::initializer_list<const char*> keywords) {
    for (const NamedOptions& set : adversarialOptions()) {
        std::string message;
        try {
            drm::encode(mesh, set.options);
            return ::testing::AssertionFailure() << "encode accepted the mesh (" << set.name << ")";
        } catch (const drm::Error& e) {
            if (e.kind() != drm::ErrorKind::InvalidInput)
                return ::testing::AssertionFailure() << "refused as " << drm::errorKindName(e.kind()) << ", not "
                                                     << "invalid input (" << set.name << "): " << e.what();
            message = e.what();
        } catch (const std::exception& e) {
            return ::testing::AssertionFailure() << "encode threw something else than drm::Error (" << set.name
                                                 << "): " << e.what();
        }
        const std::string lower = lowercase(message);
        const bool named = std::any_of(keywords.begin(), keywords.end(),
                                       [&](const char* k) { return lower.find(lowercase(k)) != std::string::npos; });
        if (!named) return ::testing::AssertionFailure() << "the message does not name the problem: " << message;
    }
    return ::testing::AssertionSuccess();
}

TEST(InputErrors, EmptyMesh) { EXPECT_TRUE(refusedNaming(drm::Mesh(), {"empty"})); }

TEST(InputErrors, FacesButNoVertices) {
    drm::Mesh mesh;
    mesh.triangles = {0, 1, 2};
    EXPECT_TRUE(refusedNaming(mesh, {"empty", "out of range", "refers to vertex"}));
}

TEST(InputErrors, NaNCoordinate) {
    drm::Mesh mesh = drm_test::tetrahedron();
    mesh.positions[3 * 2 + 1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(refusedNaming(mesh, {"NaN", "finite"}));
}

TEST(InputErrors, NaNCoordinateOfAnUnreferencedVertex) {
    drm::Mesh mesh = drm_test::tetrahedron();
    drm_test::addVertex(mesh, 0, std::numeric_limits<float>::quiet_NaN(), 0);
    EXPECT_TRUE(refusedNaming(mesh, {"NaN", "finite"}));
}

TEST(InputErrors, InfiniteCoordinate) {
    for (float infinity : {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        drm::Mesh mesh = drm_test::tetrahedron();
        mesh.positions[3 * 1 + 2] = infinity;
        EXPECT_TRUE(refusedNaming(mesh, {"finite", "infinit"})) << "coordinate " << infinity;
    }
}

TEST(InputErrors, IndexOutOfRange) {
    for (uint32_t bad : {4u, 5u, 0xFFFFFFFFu}) {  // the tetrahedron has vertices 0..3
        drm::Mesh mesh = drm_test::tetrahedron();
        mesh.triangles[3 * 2 + 1] = bad;
        EXPECT_TRUE(refusedNaming(mesh, {"out of range", "refers to vertex"})) << "index " << bad;
    }
}

// Faces repeating a vertex are kept as they are, but not with an index that
// does not exist.
TEST(InputErrors, IndexOutOfRangeInAFaceRepeatingAVertex) {
    drm::Mesh mesh = drm_test::tetrahedron();
    mesh.triangles.insert(mesh.triangles.end(), {7, 7, 1});
    EXPECT_TRUE(refusedNaming(mesh, {"out of range", "refers to vertex"}));
}

}  // namespace
}  // namespace adversarial
