// The encoder's own check (encode/verify.h): findMismatch finds nothing in
// what encode() writes, and names the first difference where the file,
// the vertex order, the face order or an attribute does not match the
// input: a file that does not decode, another face count, a vertex off its
// grid point, a face over other vertices, a colour, a quality's bits, a
// normal past the normal bits' bound, a material name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "encode/verify.h"
#include "test_meshes.h"

namespace drm {
namespace {

Mesh coloured() {
    Mesh m = drm_test::icosphere(2);
    for (size_t v = 0; v < m.vertexCount(); ++v) {
        const float* p = &m.positions[3 * v];
        m.colors.insert(m.colors.end(), {uint8_t(100 + 100 * p[0]), uint8_t(100 + 100 * p[1]), 7, 255});
        m.normals.insert(m.normals.end(), {p[0], p[1], p[2]});
        m.quality.push_back(p[2]);
    }
    m.faceMaterial.assign(m.faceCount(), 0);
    for (size_t f = 0; f < m.faceCount(); f += 3) m.faceMaterial[f] = 1;
    m.materials = {"a", "b"};
    return m;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

TEST(Verify, WhatEncodeWritesMatches) {
    const EncodeOptions options;
    for (const Mesh& m : {drm_test::mixedMesh(), drm_test::meshNeedingRepairs(), coloured()}) {
        const Encoded e = encode(m, options);
        EXPECT_EQ(findMismatch(m, options, e), "");
    }
    EncodeOptions kept;
    kept.keepVertexOrder = true;
    const Mesh m = coloured();
    EXPECT_EQ(findMismatch(m, kept, encode(m, kept)), "");
}

TEST(Verify, AFileThatDoesNotDecodeOrHoldsOtherFaces) {
    const Mesh m = coloured();
    const EncodeOptions options;
    Encoded e = encode(m, options);
    Encoded cut = e;
    cut.bytes.resize(cut.bytes.size() - 3);
    EXPECT_TRUE(startsWith(findMismatch(m, options, cut), "the decoder refuses it: ")) << findMismatch(m, options, cut);
    Mesh fewer = m;
    fewer.triangles.resize(fewer.triangles.size() - 3);
    fewer.faceMaterial.pop_back();
    EXPECT_EQ(findMismatch(fewer, options, e),
              "it has " + std::to_string(m.faceCount()) + " faces, not " + std::to_string(fewer.faceCount()));
}

TEST(Verify, AVertexOrderOrFaceOrderThatLiesIsFound) {
    const Mesh m = coloured();
    const EncodeOptions options;
    const Encoded e = encode(m, options);
    // Two decoded vertices on different grid points swapped in the order.
    Encoded swapped = e;
    std::swap(swapped.vertexOrder[0], swapped.vertexOrder[1]);
    EXPECT_EQ(findMismatch(m, options, swapped), "decoded vertex 0 is not on its input vertex's grid point");
    // A decoded face said to be another input face.
    Encoded faces = e;
    std::swap(faces.faceOrder[0], faces.faceOrder[5]);
    const std::string message = findMismatch(m, options, faces);
    EXPECT_TRUE(startsWith(message, "decoded face 0 (input face ")) << message;
    EXPECT_NE(message.find("has other vertices than the input's"), std::string::npos) << message;
    Encoded shorter = e;
    shorter.vertexOrder.pop_back();
    EXPECT_EQ(findMismatch(m, options, shorter), "its vertex count differs from the encoder's vertex order");
}

TEST(Verify, AttributesThatDifferAreNamed) {
    const Mesh m = coloured();
    const EncodeOptions options;
    const Encoded e = encode(m, options);
    auto messageFor = [&](void (*change)(Mesh&)) {
        Mesh other = m;
        change(other);
        return findMismatch(other, options, e);
    };
    const auto has = [](const std::string& s, const char* part) { return s.find(part) != std::string::npos; };
    std::string s = messageFor([](Mesh& x) { x.colors[4 * 3] ^= 1; });
    EXPECT_TRUE(has(s, ": a vertex colour differs")) << s;
    s = messageFor([](Mesh& x) { x.quality[9] = std::nextafter(x.quality[9], 10.0f); });  // one bit off
    EXPECT_TRUE(has(s, ": a vertex quality differs")) << s;
    s = messageFor([](Mesh& x) {
        // Turn vertex 2's normal by 2 degrees: well past 10 bits' bound.
        float* n = &x.normals[6];
        const float c = std::cos(0.035f), sn = std::sin(0.035f);
        const float a = n[0], b = n[1];
        n[0] = c * a - sn * b;
        n[1] = sn * a + c * b;
        if (a == 0 && b == 0) n[0] = 0.035f;
    });
    EXPECT_TRUE(has(s, ": a vertex normal is off by more than the normal bits allow")) << s;
    s = messageFor([](Mesh& x) { x.faceMaterial[1] = 1 - x.faceMaterial[1]; });
    EXPECT_TRUE(has(s, ": the material differs")) << s;
    EXPECT_EQ(messageFor([](Mesh& x) { x.materials[1] = "c"; }), "the material names differ");
    // An attribute the options leave out is not compared.
    EncodeOptions noColours;
    noColours.attributes = kAttrAll & ~kAttrColors;
    const Encoded without = encode(m, noColours);
    Mesh recoloured = m;
    recoloured.colors[0] ^= 0xFF;
    EXPECT_EQ(findMismatch(recoloured, noColours, without), "");
}

}  // namespace
}  // namespace drm
