// One attribute section (attributes/attribute_coder.h) on a decoded mesh:
// every semantic and layout comes back value for value (colours, normals
// with zero flags, texture coordinates per corner with seams, qualities of
// 32 bits, per-face materials and colours, welded per-vertex values, and a
// vertex no face uses); the wedges are the corners an unbroken interior
// edge joins, numbered by their first corner; a payload says from its
// first bytes whether it needs the corner table's opposites; and a
// malformed payload is refused naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "attributes/attribute_coder.h"
#include "attributes/corner_table.h"
#include "attributes/octahedral.h"
#include "drmcodec/drmcodec.h"
#include "mesh/quantize.h"
#include "test_meshes.h"

namespace drm {
namespace {

// An icosphere on the 12-bit grid, with one vertex no face uses.
struct TestMesh {
    std::vector<uint32_t> triangles;
    std::vector<int32_t> grid;
    size_t vertexCount = 0;
    CornerTable corners;
    AttributeMesh view() const { return AttributeMesh{triangles, grid, vertexCount, corners}; }
};

TestMesh sphere() {
    Mesh m = drm_test::icosphere(3);
    drm_test::addVertex(m, 0.1f, 0.2f, 0.3f);  // isolated
    TestMesh t;
    t.triangles = m.triangles;
    t.grid = quantize(m.positions, makeGrid(m.positions, 12));
    t.vertexCount = m.vertexCount();
    t.corners = buildCornerTable(t.triangles, t.vertexCount);
    return t;
}

AttributeValues roundTrip(const AttributeValues& a, const TestMesh& mesh, size_t* size = nullptr) {
    const std::vector<uint8_t> bytes = encodeAttribute(a, mesh.view());
    if (size) *size = bytes.size();
    return decodeAttribute(bytes.data(), bytes.size(), mesh.view());
}

void expectSame(const AttributeValues& got, const AttributeValues& want) {
    EXPECT_EQ(got.semantic, want.semantic);
    EXPECT_EQ(got.layout, want.layout);
    EXPECT_EQ(got.components, want.components);
    EXPECT_EQ(got.bits, want.bits);
    ASSERT_EQ(got.values.size(), want.values.size());
    EXPECT_TRUE(got.values == want.values);
    EXPECT_EQ(got.zero, want.zero);
    EXPECT_EQ(got.uvOrigin[0], want.uvOrigin[0]);
    EXPECT_EQ(got.uvOrigin[1], want.uvOrigin[1]);
    EXPECT_EQ(got.uvStep, want.uvStep);
}

TEST(AttributeCoder, PerVertexColoursQualitiesAndNormalsRoundTrip) {
    const TestMesh mesh = sphere();
    const size_t V = mesh.vertexCount;
    AttributeValues colours;
    colours.semantic = AttributeSemantic::Color;
    colours.components = 3;
    colours.bits = 8;
    AttributeValues quality;
    quality.semantic = AttributeSemantic::Quality;
    quality.components = 1;
    quality.bits = 32;
    AttributeValues normals;
    normals.semantic = AttributeSemantic::Normal;
    normals.components = 2;
    normals.bits = 10;
    normals.zero.assign(V, 0);
    for (size_t v = 0; v < V; ++v) {
        const int32_t* p = &mesh.grid[3 * v];
        for (int k = 0; k < 3; ++k) colours.values.push_back(uint32_t(p[k]) >> 4);
        float q = float(p[2]) * 0.37f - 11.0f;
        uint32_t bits;
        std::memcpy(&bits, &q, sizeof bits);
        quality.values.push_back(bits);
        uint32_t o[2] = {0, 0};
        if (v % 17 == 4) {
            normals.zero[v] = 1;  // a zero normal: values 0
        } else {
            const double c = 2047.5;
            octahedralEncodeBest(p[0] - c, p[1] - c, p[2] - c, normals.bits, o);
        }
        normals.values.insert(normals.values.end(), {o[0], o[1]});
    }
    expectSame(roundTrip(colours, mesh), colours);
    expectSame(roundTrip(quality, mesh), quality);
    size_t normalBytes = 0;
    expectSame(roundTrip(normals, mesh, &normalBytes), normals);
    // The normals of a sphere follow its surface: well under the 20 bits a
    // normal that raw values would take.
    EXPECT_LT(normalBytes * 8, V * 20 * 2 / 5) << normalBytes;
}

TEST(AttributeCoder, PerCornerValuesWithSeamsRoundTrip) {
    const TestMesh mesh = sphere();
    const size_t corners = mesh.triangles.size();
    AttributeValues uv;
    uv.semantic = AttributeSemantic::TexCoord;
    uv.layout = AttributeLayout::Corner;
    uv.components = 2;
    uv.bits = 12;
    uv.uvOrigin[0] = -0.25;
    uv.uvOrigin[1] = 1.5;
    uv.uvStep = 1.0 / 4095;
    for (size_t c = 0; c < corners; ++c) {
        const int32_t* p = &mesh.grid[3 * size_t(mesh.triangles[c])];
        // Faces of every fifth index are given their own island: seams
        // along their edges.
        const uint32_t island = (c / 3) % 5 == 0 ? 900 : 0;
        uv.values.insert(uv.values.end(), {(uint32_t(p[0]) / 2 + island) & 4095, uint32_t(p[1]) / 2});
    }
    expectSame(roundTrip(uv, mesh), uv);
    AttributeValues cornerNormals;
    cornerNormals.semantic = AttributeSemantic::Normal;
    cornerNormals.layout = AttributeLayout::Corner;
    cornerNormals.components = 2;
    cornerNormals.bits = 8;
    for (size_t c = 0; c < corners; ++c) {
        // Flat shading: each face's corners share the face's direction.
        const uint32_t* f = &mesh.triangles[3 * (c / 3)];
        double n[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) n[a] += mesh.grid[3 * size_t(f[k]) + a] - 2047.5;
        uint32_t o[2];
        octahedralEncodeBest(n[0], n[1], n[2], cornerNormals.bits, o);
        cornerNormals.values.insert(cornerNormals.values.end(), {o[0], o[1]});
    }
    expectSame(roundTrip(cornerNormals, mesh), cornerNormals);
}

TEST(AttributeCoder, PerFaceValuesRoundTrip) {
    const TestMesh mesh = sphere();
    const size_t F = mesh.triangles.size() / 3;
    AttributeValues material;
    material.semantic = AttributeSemantic::Material;
    material.layout = AttributeLayout::Face;
    material.components = 1;
    material.bits = 2;
    AttributeValues colours;
    colours.semantic = AttributeSemantic::Color;
    colours.layout = AttributeLayout::Face;
    colours.components = 4;
    colours.bits = 8;
    for (size_t f = 0; f < F; ++f) {
        const int32_t z = mesh.grid[3 * size_t(mesh.triangles[3 * f]) + 2];
        material.values.push_back(z > 2048 ? 1 : (f % 11 == 0 ? 3 : 0));
        colours.values.insert(colours.values.end(), {uint32_t(z >> 4), 7, uint32_t(f % 256), 255});
    }
    expectSame(roundTrip(material, mesh), material);
    expectSame(roundTrip(colours, mesh), colours);
}

TEST(AttributeCoder, WeldedVertexValuesRoundTrip) {
    // Per corner, then one per vertex for the vertices no face uses.
    const TestMesh mesh = sphere();
    AttributeValues a;
    a.semantic = AttributeSemantic::Color;
    a.layout = AttributeLayout::WeldedVertex;
    a.components = 3;
    a.bits = 8;
    for (size_t c = 0; c < mesh.triangles.size(); ++c) {
        const uint32_t v = mesh.triangles[c];
        a.values.insert(a.values.end(), {v % 256, (v / 256) * 40, v % 3 == 0 && c % 2 ? 9u : 0u});
    }
    for (size_t v = 0; v < mesh.vertexCount; ++v) a.values.insert(a.values.end(), {1, 2, 3});
    const AttributeValues back = roundTrip(a, mesh);
    // Corner values come back exactly; of the per-vertex ones only the
    // vertex no face uses is coded.
    ASSERT_EQ(back.values.size(), a.values.size());
    const size_t corners = mesh.triangles.size();
    for (size_t i = 0; i < 3 * corners; ++i) ASSERT_EQ(back.values[i], a.values[i]) << i;
    const size_t isolated = mesh.vertexCount - 1;
    for (int j = 0; j < 3; ++j) EXPECT_EQ(back.values[3 * (corners + isolated) + size_t(j)], uint32_t(j + 1));
}

TEST(AttributeCoder, WedgesAreTheCornersUnbrokenEdgesJoin) {
    const TestMesh mesh = sphere();
    const AttributeMesh view = mesh.view();
    const size_t corners = mesh.triangles.size();
    uint32_t count = 0;
    // Per vertex: one wedge a vertex with corners, numbered by first corner.
    const std::vector<uint32_t> perVertex = wedgesOf(view, {}, true, &count);
    std::vector<uint32_t> firstSeen(mesh.vertexCount, kNoIndex);
    uint32_t next = 0;
    for (size_t c = 0; c < corners; ++c) {
        uint32_t& w = firstSeen[mesh.triangles[c]];
        if (w == kNoIndex) w = next++;
        ASSERT_EQ(perVertex[c], w);
    }
    EXPECT_EQ(count, next);
    EXPECT_EQ(count, mesh.vertexCount - 1);  // all but the isolated vertex
    // Per corner without seams: on a closed surface, the same wedges.
    const std::vector<uint8_t> noSeams(mesh.corners.interiorEdges.size(), 0);
    EXPECT_EQ(wedgesOf(view, noSeams, false, &count), perVertex);
    // Every edge a seam: every corner its own wedge.
    const std::vector<uint8_t> allSeams(mesh.corners.interiorEdges.size(), 1);
    const std::vector<uint32_t> own = wedgesOf(view, allSeams, false, &count);
    EXPECT_EQ(count, corners);
    for (size_t c = 0; c < corners; ++c) ASSERT_EQ(own[c], c);
    // One seam less than all: the two corner pairs that edge joins share
    // wedges, so two wedges fewer.
    std::vector<uint8_t> oneJoined = allSeams;
    oneJoined[0] = 0;
    wedgesOf(view, oneJoined, false, &count);
    EXPECT_EQ(count, corners - 2);
}

TEST(AttributeCoder, APayloadSaysWhetherItNeedsOpposites) {
    const TestMesh mesh = sphere();
    AttributeValues colours;
    colours.components = 3;
    colours.bits = 8;
    colours.values.assign(3 * mesh.vertexCount, 5);
    const std::vector<uint8_t> vertex = encodeAttribute(colours, mesh.view());
    const uint8_t predictor = vertex[2];
    EXPECT_EQ(attributeNeedsOpposites(vertex.data(), vertex.size()),
              predictor == uint8_t(AttributePredictor::Parallelogram));
    // The first three bytes decide: kind, layout, predictor.
    const uint8_t corner[] = {uint8_t(AttributeSemantic::Color), uint8_t(AttributeLayout::Corner),
                              uint8_t(AttributePredictor::Previous)};
    EXPECT_TRUE(attributeNeedsOpposites(corner, 3));
    const uint8_t ring[] = {uint8_t(AttributeSemantic::Color), uint8_t(AttributeLayout::Vertex),
                            uint8_t(AttributePredictor::RingAverage)};
    EXPECT_FALSE(attributeNeedsOpposites(ring, 3));
    const uint8_t adjacent[] = {uint8_t(AttributeSemantic::Material), uint8_t(AttributeLayout::Face),
                                uint8_t(AttributePredictor::AdjacentFace)};
    EXPECT_TRUE(attributeNeedsOpposites(adjacent, 3));
    EXPECT_FALSE(attributeNeedsOpposites(corner, 2));  // too short to say
}

TEST(AttributeCoder, MalformedPayloadsAreRefusedNamingTheProblem) {
    const TestMesh mesh = sphere();
    AttributeValues colours;
    colours.components = 3;
    colours.bits = 8;
    for (size_t v = 0; v < mesh.vertexCount; ++v) colours.values.insert(colours.values.end(), {uint32_t(v % 200), 3, 4});
    const std::vector<uint8_t> good = encodeAttribute(colours, mesh.view());
    auto refusal = [&](std::vector<uint8_t> bytes, ErrorKind kind) -> std::string {
        try {
            decodeAttribute(bytes.data(), bytes.size(), mesh.view());
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), kind) << e.what();
            return e.what();
        }
        return "accepted";
    };
    auto with = [&](size_t at, uint8_t value) {
        std::vector<uint8_t> bytes = good;
        bytes[at] = value;
        return bytes;
    };
    EXPECT_EQ(refusal(with(0, 7), ErrorKind::Unsupported), "unsupported file: unknown attribute kind 7");
    EXPECT_EQ(refusal(with(0, 0), ErrorKind::Unsupported), "unsupported file: unknown attribute kind 0");
    EXPECT_EQ(refusal(with(1, 4), ErrorKind::Corrupt), "corrupt file: unknown attribute layout 4");
    EXPECT_EQ(refusal(with(3, 0), ErrorKind::Corrupt), "corrupt file: an attribute section's value layout is invalid");
    EXPECT_EQ(refusal(with(3, 5), ErrorKind::Corrupt), "corrupt file: an attribute section's value layout is invalid");
    EXPECT_EQ(refusal(with(4, 33), ErrorKind::Corrupt), "corrupt file: an attribute section's value layout is invalid");
    EXPECT_EQ(refusal(with(5, 2), ErrorKind::Corrupt), "corrupt file: an attribute section's value layout is invalid");
    EXPECT_EQ(refusal(with(5, 1), ErrorKind::Corrupt), "corrupt file: zero flags on an attribute that is not a normal");
    // A colour predicted from texture space: not one of a colour's predictors.
    EXPECT_EQ(refusal(with(2, uint8_t(AttributePredictor::GeometricUv)), ErrorKind::Corrupt),
              "corrupt file: attribute predictor 4 does not fit its attribute");
    // Cut short in the header.
    EXPECT_NE(refusal(std::vector<uint8_t>(good.begin(), good.begin() + 4), ErrorKind::Corrupt), "accepted");
    // Values cut short: the residuals read past the end are refused, as
    // too long for their values or as reading past the section.
    const std::string cut = refusal(std::vector<uint8_t>(good.begin(), good.begin() + long(good.size() / 2)), ErrorKind::Corrupt);
    EXPECT_TRUE(cut == "corrupt file: an attribute section ends before its last value" ||
                cut == "corrupt file: an attribute residual is longer than its values")
        << cut;
}

}  // namespace
}  // namespace drm
