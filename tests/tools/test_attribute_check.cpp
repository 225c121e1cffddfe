// drm verify's attribute check (tools/lossless_check.cpp), held to a
// simulated codec: decoded faces in another order, each starting at another
// corner, attributes moved with them, then spoiled one at a time. The check
// must follow faceOrder/faceRotation whatever the codec does inside.
#include "lossless_check.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// Two triangles over four vertices, every attribute kind.
drm::Mesh sampleMesh() {
    drm::Mesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    m.triangles = {0, 1, 2, 1, 3, 2};
    m.colors = {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 128, 1, 2, 3, 4};
    m.normals = {0, 0, 1, 0, 0, 1, 0, 0.6f, 0.8f, 0.6f, 0, 0.8f};
    m.quality = {0.5f, 1.5f, 2.5f, 3.5f};
    m.cornerTexCoords = {0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 1};
    m.faceColors = {1, 2, 3, 4, 5, 6, 7, 8};
    m.materials = {"a", "b"};
    m.faceMaterial = {1, 0};
    m.metadata = {{"obj.mtllib", "x.mtl"}};
    return m;
}

// The codec's answer: faces swapped, the first decoded face starting at
// its second corner; vertices in input order.
struct Simulated {
    drm::Encoded encoded;
    drm::Decoded decoded;
};

Simulated simulate(const drm::Mesh& in) {
    Simulated s;
    s.encoded.faceOrder = {1, 0};
    s.encoded.faceRotation = {1, 0};
    drm::Mesh& out = s.decoded.mesh;
    out = in;
    out.triangles.clear();
    out.cornerTexCoords.clear();
    out.faceColors.clear();
    out.faceMaterial.clear();
    for (size_t i = 0; i < 2; ++i) {
        const uint32_t f = s.encoded.faceOrder[i];
        for (int k = 0; k < 3; ++k) {
            const size_t corner = 3 * f + (s.encoded.faceRotation[i] + k) % 3;
            out.triangles.push_back(in.triangles[corner]);
            out.cornerTexCoords.push_back(in.cornerTexCoords[2 * corner]);
            out.cornerTexCoords.push_back(in.cornerTexCoords[2 * corner + 1]);
        }
        for (int k = 0; k < 4; ++k) out.faceColors.push_back(in.faceColors[4 * f + k]);
        out.faceMaterial.push_back(in.faceMaterial[f]);
    }
    return s;
}

std::string check(const drm::Mesh& in, const Simulated& s, const drm::EncodeOptions& options = {}) {
    return drm::cli::findAttributeMismatch(in, options, s.encoded, s.decoded);
}

TEST(AttributeCheck, FollowsFaceOrderAndRotation) {
    const drm::Mesh in = sampleMesh();
    EXPECT_EQ(check(in, simulate(in)), "");
}

TEST(AttributeCheck, PerCornerValuesMayComeBackPerVertexAndBack) {
    drm::Mesh in = sampleMesh();
    // A welded decode may give per-corner values for per-vertex input.
    Simulated s = simulate(in);
    s.decoded.mesh.cornerNormals.clear();
    for (uint32_t v : s.decoded.mesh.triangles)
        for (int k = 0; k < 3; ++k) s.decoded.mesh.cornerNormals.push_back(in.normals[3 * v + k]);
    s.decoded.mesh.normals.clear();
    EXPECT_EQ(check(in, s), "");
}

TEST(AttributeCheck, ColoursMustBeExact) {
    const drm::Mesh in = sampleMesh();
    Simulated s = simulate(in);
    s.decoded.mesh.colors[4 * 3 + 3] = 5;  // vertex 3's alpha
    EXPECT_NE(check(in, s).find("vertex colour"), std::string::npos) << check(in, s);
    s = simulate(in);
    s.decoded.mesh.faceColors[0] = 9;  // decoded face 0 = input face 1
    EXPECT_NE(check(in, s).find("face colour of input face 1"), std::string::npos) << check(in, s);
}

TEST(AttributeCheck, NormalsWithinTheBoundForTheirBits) {
    const drm::Mesh in = sampleMesh();
    Simulated s = simulate(in);
    const double small = 0.1 * 3.14159265358979 / 180, large = 0.5 * 3.14159265358979 / 180;
    s.decoded.mesh.normals[0] = float(std::sin(small));
    s.decoded.mesh.normals[2] = float(std::cos(small));
    EXPECT_EQ(check(in, s), "");
    s.decoded.mesh.normals[0] = float(std::sin(large));
    s.decoded.mesh.normals[2] = float(std::cos(large));
    EXPECT_NE(check(in, s).find("normal"), std::string::npos);
    drm::EncodeOptions coarse;
    coarse.normalBits = 8;  // 0.8 degrees
    EXPECT_EQ(check(in, s, coarse), "");
}

TEST(AttributeCheck, TexCoordsWithinHalfAStep) {
    const drm::Mesh in = sampleMesh();
    Simulated s = simulate(in);
    const float halfStep = 0.5f / 4095;
    s.decoded.mesh.cornerTexCoords[0] += 0.9f * halfStep;
    EXPECT_EQ(check(in, s), "");
    s.decoded.mesh.cornerTexCoords[0] += 0.5f * halfStep;
    EXPECT_NE(check(in, s).find("texture coordinate"), std::string::npos);
}

TEST(AttributeCheck, NamesMaterialsAndMetadataMustComeBack) {
    const drm::Mesh in = sampleMesh();
    Simulated s = simulate(in);
    s.decoded.mesh.faceMaterial = {1, 0};  // decoded face 0 is input face 1, of material 0
    EXPECT_NE(check(in, s).find("material"), std::string::npos);
    s = simulate(in);
    s.decoded.mesh.metadata.clear();
    EXPECT_NE(check(in, s).find("metadata"), std::string::npos);
    drm::EncodeOptions noMetadata;
    noMetadata.attributes = drm::kAttrAll & ~drm::kAttrMetadata;
    EXPECT_EQ(check(in, s, noMetadata), "");
}

TEST(AttributeCheck, MissingArraysAndFaceOrderAreNamed) {
    const drm::Mesh in = sampleMesh();
    Simulated s = simulate(in);
    s.decoded.mesh.quality.clear();
    EXPECT_NE(check(in, s).find("no vertex quality"), std::string::npos);
    s = simulate(in);
    s.encoded.faceOrder.clear();
    EXPECT_NE(check(in, s).find("face order"), std::string::npos);
    drm::EncodeOptions none;
    none.attributes = 0;
    EXPECT_EQ(check(in, s, none), "");
}

TEST(AttributeCheck, NormalBoundDoublesPerBitFewer) {
    EXPECT_DOUBLE_EQ(drm::cli::normalAngleBound(10), 0.2);
    EXPECT_DOUBLE_EQ(drm::cli::normalAngleBound(8), 0.8);
    EXPECT_DOUBLE_EQ(drm::cli::normalAngleBound(12), 0.2);
}

}  // namespace
