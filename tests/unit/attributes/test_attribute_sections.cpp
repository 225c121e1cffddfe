// A mesh's attribute sections (attributes/attribute_sections.h), through
// encode and decode: every kind, per vertex, per corner with seams, per
// face, names and metadata; welding of a mesh with a vertex per corner;
// the normal error bound measured; options and bad values. And on their
// own: the checks of sizes and options, the welding and when it is
// chosen, and a section's name read from its first bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <set>
#include <vector>

#include "attributes/attribute_sections.h"
#include "container/file_format.h"
#include "drmcodec/drmcodec.h"
#include "mesh/quantize.h"
#include "test_meshes.h"

namespace {

// A sphere with colours from position, normals from position, spherical
// texture coordinates (per vertex, and per corner with a seam where u
// wraps), qualities, face colours and two materials.
drm::Mesh decoratedSphere() {
    drm::Mesh m = drm_test::icosphere(3);
    const size_t V = m.vertexCount(), F = m.faceCount();
    for (size_t v = 0; v < V; ++v) {
        const float* p = &m.positions[3 * v];
        const float len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int k = 0; k < 3; ++k) m.colors.push_back(uint8_t(127.5f + 127.0f * p[k] / len));
        m.colors.push_back(255);
        for (int k = 0; k < 3; ++k) m.normals.push_back(p[k] / len);
        const float u = 0.5f + std::atan2(p[1], p[0]) / 6.2831853f, w = 0.5f + std::asin(p[2] / len) / 3.1415927f;
        m.texCoords.insert(m.texCoords.end(), {u, w});
        m.quality.push_back(p[2] * 10.0f);
    }
    for (size_t f = 0; f < F; ++f) {
        float us[3];
        for (int k = 0; k < 3; ++k) us[k] = m.texCoords[2 * m.triangles[3 * f + k]];
        const bool wraps = *std::max_element(us, us + 3) - *std::min_element(us, us + 3) > 0.5f;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = m.triangles[3 * f + k];
            float u = m.texCoords[2 * v];
            if (wraps && u < 0.5f) u += 1.0f;  // the seam: this face's corners continue past 1
            m.cornerTexCoords.insert(m.cornerTexCoords.end(), {u, m.texCoords[2 * v + 1]});
        }
        const bool north = m.positions[3 * m.triangles[3 * f] + 2] > 0;
        m.faceColors.insert(m.faceColors.end(), {uint8_t(north ? 200 : 20), 90, uint8_t(f % 7), 255});
        m.faceQuality.push_back(float(f) * 0.25f);
        m.faceMaterial.push_back(north ? 1 : 0);
        m.faceTexture.push_back(0);
    }
    m.materials = {"south", "north"};
    m.textures = {"sphere.png"};
    m.metadata = {{"obj.mtllib", "sphere.mtl"}, {"obj.mtl", "newmtl south\nnewmtl north\n"}};
    return m;
}

// Every face on its own three vertices, as many exporters write meshes.
drm::Mesh vertexPerCorner(const drm::Mesh& m) {
    drm::Mesh out;
    for (size_t c = 0; c < m.triangles.size(); ++c) {
        const uint32_t v = m.triangles[c];
        out.positions.insert(out.positions.end(), &m.positions[3 * v], &m.positions[3 * v] + 3);
        out.normals.insert(out.normals.end(), &m.normals[3 * v], &m.normals[3 * v] + 3);
        out.texCoords.insert(out.texCoords.end(), &m.cornerTexCoords[2 * c], &m.cornerTexCoords[2 * c] + 2);
        out.triangles.push_back(uint32_t(c));
    }
    return out;
}

drm::EncodeOptions verifying() {
    drm::EncodeOptions o;
    o.verify = true;
    return o;
}

// The angle between two directions, from atan2 (acos loses it near zero).
double angle(const float* a, const float* b) {
    const double cx = double(a[1]) * b[2] - double(a[2]) * b[1], cy = double(a[2]) * b[0] - double(a[0]) * b[2],
                 cz = double(a[0]) * b[1] - double(a[1]) * b[0];
    const double dot = double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
}

TEST(Attributes, EveryKindComesBackThroughTheDecodedOrder) {
    const drm::Mesh m = decoratedSphere();
    const drm::Encoded e = drm::encode(m, verifying());  // verify compares every corner itself
    const drm::Decoded d = drm::decode(e.bytes);
    ASSERT_EQ(d.mesh.vertexCount(), m.vertexCount());
    ASSERT_EQ(e.faceOrder.size(), m.faceCount());
    EXPECT_EQ(d.mesh.materials, m.materials);
    EXPECT_EQ(d.mesh.textures, m.textures);
    EXPECT_EQ(d.mesh.metadata, m.metadata);
    double worstNormal = 0;
    for (size_t f = 0; f < d.mesh.faceCount(); ++f) {
        const size_t g = e.faceOrder[f];
        EXPECT_EQ(d.mesh.faceMaterial[f], m.faceMaterial[g]);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(d.mesh.faceColors[4 * f + k], m.faceColors[4 * g + k]);
        EXPECT_EQ(d.mesh.faceQuality[f], m.faceQuality[g]);
        for (size_t k = 0; k < 3; ++k) {
            const size_t ic = 3 * g + (k + e.faceRotation[f]) % 3, oc = 3 * f + k;
            const uint32_t u = m.triangles[ic], v = d.mesh.triangles[oc];
            ASSERT_EQ(e.vertexOrder[v], u);
            for (int a = 0; a < 3; ++a) EXPECT_EQ(d.mesh.colors[4 * v + a], m.colors[4 * u + a]);
            EXPECT_EQ(d.mesh.quality[v], m.quality[u]);
            worstNormal = std::max(worstNormal, angle(&d.mesh.normals[3 * v], &m.normals[3 * u]));
            for (int a = 0; a < 2; ++a) {
                EXPECT_NEAR(d.mesh.texCoords[2 * v + a], m.texCoords[2 * u + a], 0.5 / 4095 + 1e-6);
                EXPECT_NEAR(d.mesh.cornerTexCoords[2 * oc + a], m.cornerTexCoords[2 * ic + a], 1.0 / 4095 + 1e-6);
            }
        }
    }
    EXPECT_LE(worstNormal, drm::maxNormalError(10));
    EXPECT_LT(worstNormal * 180 / 3.14159265, 1.0);
    ASSERT_FALSE(e.stats.attributeSizes.empty());
    EXPECT_EQ(e.stats.attributeSizes.size(), d.stats.attributeSizes.size());
    uint64_t sum = 0;
    for (const auto& s : e.stats.attributeSizes) sum += s.bytes;
    EXPECT_LE(sum, e.stats.attributeBytes);
    EXPECT_EQ(e.stats.headerBytes + e.stats.connectivityBytes + e.stats.geometryBytes + e.stats.attributeBytes,
              e.stats.totalBytes);
}

TEST(Attributes, EachSectionHasItsOwnNameThatSaysWhatItKeeps) {
    const drm::Mesh m = decoratedSphere();
    const drm::Encoded e = drm::encode(m, verifying());
    const drm::Decoded d = drm::decode(e.bytes);
    for (const drm::Stats* stats : {&e.stats, &d.stats}) {
        std::set<std::string> names;
        uint32_t kept = 0;
        for (const auto& section : stats->attributeSizes) {
            EXPECT_TRUE(names.insert(section.name).second) << "two sections named " << section.name;
            EXPECT_NE(drm::sectionAttributes(section.name), 0u) << section.name;
            kept |= drm::sectionAttributes(section.name);
        }
        EXPECT_TRUE(names.count("material names") && names.count("texture names"));
        EXPECT_EQ(kept, drm::attributesOf(m));
    }
    EXPECT_EQ(drm::sectionAttributes("framing"), 0u);
}

TEST(Attributes, TheNormalBoundHoldsOverManyDirections) {
    for (int bits : {4, 8, 10, 12, 16}) {
        drm::Mesh m = drm_test::icosphere(4);
        uint32_t state = 12345;
        for (size_t v = 0; v < m.vertexCount(); ++v)
            for (int k = 0; k < 3; ++k) {
                state = state * 1664525u + 1013904223u;
                m.normals.push_back(float(int32_t(state >> 8) % 20001 - 10000) / 10000.0f);
            }
        m.normals[0] = m.normals[1] = m.normals[2] = 0;  // a zero normal stays zero
        drm::EncodeOptions o = verifying();
        o.normalBits = bits;
        const drm::Encoded e = drm::encode(m, o);
        const drm::Decoded d = drm::decode(e.bytes);
        double worst = 0;
        for (size_t v = 0; v < d.mesh.vertexCount(); ++v) {
            const float* in = &m.normals[3 * e.vertexOrder[v]];
            if (in[0] == 0 && in[1] == 0 && in[2] == 0) {
                EXPECT_EQ(d.mesh.normals[3 * v], 0.0f);
                continue;
            }
            worst = std::max(worst, angle(&d.mesh.normals[3 * v], in));
        }
        EXPECT_LE(worst, drm::maxNormalError(bits)) << bits << " bits";
        if (bits == 10) EXPECT_LT(worst * 180 / 3.14159265, 0.25);
    }
}

TEST(Attributes, AVertexPerCornerMeshIsWeldedAndEveryCornerComesBack) {
    const drm::Mesh sphere = decoratedSphere();
    const drm::Mesh split = vertexPerCorner(sphere);
    const drm::Encoded welded = drm::encode(split, verifying());
    EXPECT_GT(welded.stats.weldedVertices, split.vertexCount() / 2);
    drm::EncodeOptions off = verifying();
    off.weld = drm::EncodeOptions::Weld::Off;
    const drm::Encoded unwelded = drm::encode(split, off);
    EXPECT_LT(2 * welded.bytes.size(), unwelded.bytes.size()) << welded.bytes.size() << " vs " << unwelded.bytes.size();
    const drm::Decoded d = drm::decode(welded.bytes);
    // One vertex per distinct (position, normal, uv): fewer than the input's,
    // more than the sphere's (the seam splits some).
    EXPECT_LT(d.mesh.vertexCount(), split.vertexCount());
    EXPECT_GT(d.mesh.vertexCount(), sphere.vertexCount());
    EXPECT_EQ(d.mesh.vertexCount(), welded.vertexOrder.size());
    EXPECT_EQ(d.mesh.texCoords.size(), 2 * d.mesh.vertexCount());
}

TEST(Attributes, OnlyTheChosenAttributesAreKept) {
    const drm::Mesh m = decoratedSphere();
    drm::EncodeOptions o = verifying();
    o.attributes = drm::parseAttributes("colors,materials");
    const drm::Decoded d = drm::decode(drm::encode(m, o).bytes);
    EXPECT_FALSE(d.mesh.colors.empty());
    EXPECT_FALSE(d.mesh.faceMaterial.empty());
    EXPECT_TRUE(d.mesh.normals.empty());
    EXPECT_TRUE(d.mesh.cornerTexCoords.empty());
    o.attributes = 0;
    const drm::Encoded bare = drm::encode(m, o);
    drm::Mesh plain;
    plain.positions = m.positions;
    plain.triangles = m.triangles;
    EXPECT_EQ(bare.bytes, drm::encode(plain).bytes) << "no attributes: the file of the bare mesh";
    EXPECT_THROW(drm::parseAttributes("colours"), drm::Error);
}

TEST(Attributes, BadValuesAndSizesAreNamed) {
    drm::Mesh m = decoratedSphere();
    m.normals[3 * 5 + 1] = std::numeric_limits<float>::quiet_NaN();
    try {
        drm::encode(m);
        FAIL() << "a NaN normal was taken";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
        // The message names the element at fault (drmcodec.h's promise), so it is checked too.
        EXPECT_NE(std::string(e.what()).find("vertex 5"), std::string::npos) << e.what();
    }
    m = decoratedSphere();
    m.cornerTexCoords[2 * 7] = std::numeric_limits<float>::infinity();
    try {
        drm::encode(m);
        FAIL() << "an infinite texture coordinate was taken";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
        EXPECT_NE(std::string(e.what()).find("face 2"), std::string::npos) << e.what();  // names the element
    }
    m = decoratedSphere();
    m.colors.pop_back();
    EXPECT_THROW(drm::encode(m), drm::Error);
    m = decoratedSphere();
    drm::EncodeOptions o;
    o.normalBits = 30;
    EXPECT_THROW(drm::encode(m, o), drm::Error);
}

TEST(Attributes, HugeAndDegenerateTextureRangesRoundTrip) {
    drm::Mesh m = drm_test::icosphere(2);
    for (size_t v = 0; v < m.vertexCount(); ++v) m.texCoords.insert(m.texCoords.end(), {0.25f, 0.25f});  // one point
    EXPECT_NO_THROW(drm::encode(m, verifying()));
    for (size_t v = 0; v < m.vertexCount(); ++v) m.texCoords[2 * v] = (v % 2 ? 3e38f : -3e38f);
    EXPECT_NO_THROW(drm::encode(m, verifying()));
}

TEST(Attributes, CorruptAttributeSectionsAreRefusedOrSound) {
    const drm::Encoded e = drm::encode(decoratedSphere());
    const size_t attributeStart = e.bytes.size() - e.stats.attributeBytes;
    int refused = 0;
    for (size_t i = attributeStart; i < e.bytes.size(); i += 7) {
        std::vector<uint8_t> bad = e.bytes;
        bad[i] ^= 0x20;
        try {
            drm::decode(bad);
        } catch (const drm::Error& err) {
            ++refused;
            EXPECT_TRUE(err.kind() == drm::ErrorKind::Corrupt || err.kind() == drm::ErrorKind::Unsupported)
                << drm::errorKindName(err.kind()) << ": " << err.what();
        }
    }
    EXPECT_GT(refused, 0);
    for (size_t cut = attributeStart; cut < e.bytes.size(); cut += 5) {
        const std::vector<uint8_t> truncated(e.bytes.begin(), e.bytes.begin() + cut);
        EXPECT_THROW(drm::decode(truncated), drm::Error) << cut;
    }
}

}  // namespace

namespace {

// Welding asked for on a mesh whose attributes are all per face (nothing
// tells corners apart): the vertices the encoder reports are numbered as
// the file numbers them.
TEST(Attributes, WeldingWithOnlyFaceAttributesKeepsTheWeldedVertices) {
    for (bool keepOrder : {false, true}) {
        drm::Mesh m = drm_test::gridPatch(3, false);
        m.faceMaterial.assign(m.faceCount(), 1);
        m.materials = {"a", "b"};
        drm::EncodeOptions o;
        o.verify = true;
        o.weld = drm::EncodeOptions::Weld::On;
        o.keepVertexOrder = keepOrder;
        const drm::Encoded e = drm::encode(m, o);
        const drm::Decoded d = drm::decode(e.bytes);
        ASSERT_EQ(d.mesh.vertexCount(), e.vertexOrder.size());
        for (size_t v = 0; v < d.mesh.vertexCount(); ++v)
            for (int k = 0; k < 3; ++k) EXPECT_EQ(d.quantized[3 * v + k], e.quantized[3 * e.vertexOrder[v] + k]);
    }
}

}  // namespace

namespace drm {
namespace {

// The message of the Error f throws (of the given kind), or "".
template <class F>
std::string errorOf(F f, ErrorKind kind) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        return e.what();
    }
    return "";
}

TEST(AttributeSections, CheckNamesTheArrayItsSizeAndTheOption) {
    const Mesh sphere = drm_test::icosphere(1);  // 42 vertices, 80 faces
    const EncodeOptions defaults;
    EXPECT_EQ(errorOf([&] { checkAttributes(sphere, defaults); }, ErrorKind::InvalidInput), "");
    Mesh m = sphere;
    m.colors.assign(4 * 42 - 1, 0);
    EXPECT_EQ(errorOf([&] { checkAttributes(m, defaults); }, ErrorKind::InvalidInput),
              "the mesh's colors array holds 167 values; it must hold 4 per vertex (168)");
    m = sphere;
    m.cornerNormals.assign(9 * 80 + 9, 0);
    EXPECT_EQ(errorOf([&] { checkAttributes(m, defaults); }, ErrorKind::InvalidInput),
              "the mesh's cornerNormals array holds 729 values; it must hold 9 per face (720)");
    m = sphere;
    m.faceMaterial.assign(1, 0);
    EXPECT_EQ(errorOf([&] { checkAttributes(m, defaults); }, ErrorKind::InvalidInput),
              "the mesh's faceMaterial array holds 1 values; it must hold 1 per face (80)");
    EncodeOptions o;
    o.normalBits = kMaxNormalBits + 1;
    EXPECT_EQ(errorOf([&] { checkAttributes(sphere, o); }, ErrorKind::InvalidInput),
              "normal bits must be between 4 and 16, not 17");
    o = EncodeOptions();
    o.uvBits = 0;
    EXPECT_EQ(errorOf([&] { checkAttributes(sphere, o); }, ErrorKind::InvalidInput),
              "texture coordinate bits must be between 1 and 24, not 0");
    o = EncodeOptions();
    o.attributes = kAttrAll + 1;
    EXPECT_NE(errorOf([&] { checkAttributes(sphere, o); }, ErrorKind::InvalidInput), "");
}

TEST(AttributeSections, WeldingMergesUsedVerticesOnOneGridPoint) {
    // Two triangles over six vertices, two pairs of them on one point, and
    // an unused vertex on a used one's point (it stays apart).
    Mesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 0};
    m.triangles = {0, 1, 2, 3, 4, 5};
    const std::vector<int32_t> q = quantize(m.positions, makeGrid(m.positions, 8));
    const Welding w = weld(m, q);
    EXPECT_EQ(w.weldedOf, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 4}));
    EXPECT_EQ(w.representative, (std::vector<uint32_t>{0, 1, 2, 4, 6}));  // first occurrence
    EXPECT_EQ(w.merged(), 2u);
    EXPECT_EQ(w.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
    ASSERT_EQ(w.mesh.positions.size(), 3 * w.representative.size());
    for (size_t i = 0; i < w.representative.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(w.mesh.positions[3 * i + k], m.positions[3 * w.representative[i] + k]);
}

TEST(AttributeSections, WeldingIsChosenWhereItMergesAThird) {
    const Mesh sphere = drm_test::icosphere(2);
    Mesh split;  // a vertex per corner
    for (uint32_t v : sphere.triangles) {
        split.positions.insert(split.positions.end(), &sphere.positions[3 * v], &sphere.positions[3 * v] + 3);
        split.triangles.push_back(uint32_t(split.triangles.size()));
    }
    const std::vector<int32_t> q = quantize(split.positions, makeGrid(split.positions, 12));
    EncodeOptions o;
    EXPECT_FALSE(shouldWeld(split, q, o)) << "no per-vertex attribute: nothing to weld for";
    split.colors.assign(4 * split.vertexCount(), 128);
    EXPECT_TRUE(shouldWeld(split, q, o));  // six corners a vertex: five sixths merge
    o.weld = EncodeOptions::Weld::Off;
    EXPECT_FALSE(shouldWeld(split, q, o));
    o.weld = EncodeOptions::Weld::Auto;
    o.attributes = kAttrAll & ~kAttrColors;
    EXPECT_FALSE(shouldWeld(split, q, o)) << "the colours are not kept";
    // A mesh already shared has nothing to merge, unless asked to weld.
    Mesh shared = sphere;
    shared.colors.assign(4 * shared.vertexCount(), 128);
    const std::vector<int32_t> sq = quantize(shared.positions, makeGrid(shared.positions, 12));
    EXPECT_FALSE(shouldWeld(shared, sq, EncodeOptions()));
    EncodeOptions on;
    on.weld = EncodeOptions::Weld::On;
    EXPECT_TRUE(shouldWeld(shared, sq, on));
}

TEST(AttributeSections, SectionNamesAreReadFromTheFirstBytes) {
    const Mesh m = decoratedSphere();
    const Encoded e = encode(m);
    const FileParts parts = readFile(e.bytes.data(), e.bytes.size());
    ASSERT_EQ(parts.attributes.size(), e.stats.attributeSizes.size());
    for (size_t s = 0; s < parts.attributes.size(); ++s)
        EXPECT_EQ(attributeSectionName(parts.attributes[s].data, parts.attributes[s].size), e.stats.attributeSizes[s].name);
    const uint8_t unknown[] = {99, 0};
    EXPECT_EQ(errorOf([&] { attributeSectionName(unknown, 2); }, ErrorKind::Unsupported),
              "unsupported file: unknown attribute kind 99");
    EXPECT_EQ(errorOf([&] { attributeSectionName(unknown, 0); }, ErrorKind::Corrupt),
              "corrupt file: an attribute section is empty");
    const uint8_t colourOnly[] = {1};
    EXPECT_EQ(errorOf([&] { attributeSectionName(colourOnly, 1); }, ErrorKind::Corrupt),
              "corrupt file: an attribute section ends inside its header");
}

}  // namespace
}  // namespace drm
