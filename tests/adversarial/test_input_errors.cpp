// What no repair can save: an empty mesh, a coordinate that is not a
// number or not finite, a face naming a vertex that does not exist. encode
// throws drm::Error, and its message names the problem.
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

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

// The tetrahedron with one kind of attribute filled in, each a path of its
// own through encode() (welding, vertex splitting, corner tables).
struct AttributeKind {
    const char* name;
    void (*fill)(drm::Mesh& mesh);
};
const AttributeKind kAttributeKinds[] = {
    {"none", [](drm::Mesh&) {}},
    {"colors", [](drm::Mesh& m) { m.colors.assign(4 * m.vertexCount(), 200); }},
    {"normals", [](drm::Mesh& m) { for (size_t v = 0; v < m.vertexCount(); ++v) m.normals.insert(m.normals.end(), {0, 0, 1}); }},
    {"texcoords", [](drm::Mesh& m) { m.texCoords.assign(2 * m.vertexCount(), 0.25f); }},
    {"quality", [](drm::Mesh& m) { m.quality.assign(m.vertexCount(), 1.5f); }},
    {"corner texcoords", [](drm::Mesh& m) { m.cornerTexCoords.assign(6 * m.faceCount(), 0.5f); }},
    {"corner normals", [](drm::Mesh& m) { for (size_t c = 0; c < 3 * m.faceCount(); ++c) m.cornerNormals.insert(m.cornerNormals.end(), {1, 0, 0}); }},
    {"face colors", [](drm::Mesh& m) { m.faceColors.assign(4 * m.faceCount(), 9); }},
    {"face quality", [](drm::Mesh& m) { m.faceQuality.assign(m.faceCount(), 2.0f); }},
    {"materials", [](drm::Mesh& m) { m.faceMaterial.assign(m.faceCount(), 0); m.materials = {"stone"}; }},
    {"textures", [](drm::Mesh& m) { m.faceTexture.assign(m.faceCount(), 0); m.textures = {"stone.png"}; }},
    {"metadata", [](drm::Mesh& m) { m.metadata = {{"obj.mtllib", "stone.mtl"}}; }},
    {"all", [](drm::Mesh& m) {
         m.colors.assign(4 * m.vertexCount(), 200);
         m.texCoords.assign(2 * m.vertexCount(), 0.25f);
         m.quality.assign(m.vertexCount(), 1.5f);
         m.cornerTexCoords.assign(6 * m.faceCount(), 0.5f);
         m.faceColors.assign(4 * m.faceCount(), 9);
         m.faceMaterial.assign(m.faceCount(), 0);
         m.materials = {"stone"};
     }},
};

// Every attribute kind, with welding forced on, off or left to the encoder,
// and an index just past the vertices, far past them, or at the top of
// uint32_t: the error names the face and the index, whichever path through
// encode() would have read the index first.
TEST(InputErrors, IndexOutOfRangeWithEachAttributeKind) {
    const uint32_t badIndices[] = {4u, 1000000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    const drm::EncodeOptions::Weld welds[] = {drm::EncodeOptions::Weld::Auto, drm::EncodeOptions::Weld::On,
                                              drm::EncodeOptions::Weld::Off};
    for (const AttributeKind& kind : kAttributeKinds)
        for (uint32_t bad : badIndices)
            for (drm::EncodeOptions::Weld weld : welds)
                for (size_t face : {size_t(0), size_t(3)}) {
                    drm::Mesh mesh = drm_test::tetrahedron();
                    kind.fill(mesh);
                    mesh.triangles[3 * face + 2] = bad;
                    drm::EncodeOptions options;
                    options.weld = weld;
                    const std::string where = std::string(kind.name) + ", index " + std::to_string(bad) + ", face " +
                                              std::to_string(face) + ", weld " + std::to_string(int(weld));
                    try {
                        drm::encode(mesh, options);
                        ADD_FAILURE() << "accepted: " << where;
                    } catch (const drm::Error& e) {
                        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << where;
                        const std::string message = e.what();
                        EXPECT_NE(message.find("face " + std::to_string(face)), std::string::npos) << where << ": " << message;
                        EXPECT_NE(message.find("refers to vertex " + std::to_string(bad)), std::string::npos)
                            << where << ": " << message;
                    }
                }
}

// A face's material or texture must be one the mesh names (where it names
// any): the error names the face.
TEST(InputErrors, AMaterialOrTextureTheMeshDoesNotNameIsRefused) {
    drm::Mesh mesh = drm_test::tetrahedron();
    mesh.faceMaterial = {0, 0, 0, 7};
    mesh.materials = {"stone"};
    EXPECT_TRUE(refusedNaming(mesh, {"face 3 uses material 7, but the mesh names only 1"}));
    mesh.materials.clear();  // indices without names are kept as they are
    EXPECT_NO_THROW(drm::encode(mesh));
    mesh = drm_test::tetrahedron();
    mesh.faceTexture = {0, 1, 0, 0};
    mesh.textures = {"a.png"};
    EXPECT_TRUE(refusedNaming(mesh, {"face 1 uses texture 1, but the mesh names only 1"}));
}

}  // namespace
}  // namespace adversarial
