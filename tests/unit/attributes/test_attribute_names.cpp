// The attributes' names (attributes/attribute_names.cpp, declared in
// drmcodec.h): every subset names and parses back, "all" and "none" included; an
// unknown name is refused naming it and the choices; sectionAttributes
// tells what each section's name keeps; attributesOf sees each array.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "drmcodec/drmcodec.h"

namespace {

TEST(AttributeNames, EverySubsetNamesAndParsesBack) {
    for (uint32_t bits = 0; bits <= drm::kAttrAll; ++bits) {
        const std::string name = drm::attributesName(bits);
        ASSERT_EQ(drm::parseAttributes(name), bits) << name;
    }
    EXPECT_EQ(drm::attributesName(0), "none");
    EXPECT_EQ(drm::attributesName(drm::kAttrAll), "all");
    EXPECT_EQ(drm::attributesName(drm::kAttrAll | (1u << 20)), "all");  // bits past the known ones are ignored
    EXPECT_EQ(drm::attributesName(drm::kAttrColors | drm::kAttrFaceMaterial), "colors,materials");
    EXPECT_EQ(drm::attributesName(drm::kAttrAll & ~drm::kAttrMetadata),
              "colors,normals,texcoords,quality,corner-texcoords,corner-normals,face-colors,face-quality,materials,"
              "textures");
    // Order and repeats do not matter to the parser.
    EXPECT_EQ(drm::parseAttributes("metadata,colors,colors"), drm::kAttrMetadata | drm::kAttrColors);
}

TEST(AttributeNames, AnUnknownNameIsRefusedWithTheChoices) {
    for (const char* bad : {"colours", "", "colors,", "Colors", "all,colors"}) {
        try {
            drm::parseAttributes(bad);
            FAIL() << "'" << bad << "' taken";
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput);
            const std::string message = e.what();
            EXPECT_NE(message.find("unknown attribute '"), std::string::npos) << message;
            EXPECT_NE(message.find("corner-texcoords"), std::string::npos) << message;  // the choices
        }
    }
}

TEST(AttributeNames, SectionNamesSayWhatTheyKeep) {
    for (uint32_t bit = 1; bit < drm::kAttrAll; bit <<= 1) EXPECT_EQ(drm::sectionAttributes(drm::attributesName(bit)), bit);
    EXPECT_EQ(drm::sectionAttributes("material names"), drm::kAttrFaceMaterial);
    EXPECT_EQ(drm::sectionAttributes("texture names"), drm::kAttrFaceTexture);
    EXPECT_EQ(drm::sectionAttributes("all"), 0u);
    EXPECT_EQ(drm::sectionAttributes("framing"), 0u);
}

TEST(AttributeNames, AttributesOfSeesEachArray) {
    drm::Mesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    m.triangles = {0, 1, 2};
    EXPECT_EQ(drm::attributesOf(m), 0u);
    EXPECT_FALSE(m.hasAttributes());
    struct Case {
        uint32_t bit;
        void (*give)(drm::Mesh&);
    };
    const Case cases[] = {
        {drm::kAttrColors, [](drm::Mesh& x) { x.colors.assign(12, 1); }},
        {drm::kAttrNormals, [](drm::Mesh& x) { x.normals.assign(9, 0.5f); }},
        {drm::kAttrTexCoords, [](drm::Mesh& x) { x.texCoords.assign(6, 0.5f); }},
        {drm::kAttrQuality, [](drm::Mesh& x) { x.quality.assign(3, 1); }},
        {drm::kAttrCornerTexCoords, [](drm::Mesh& x) { x.cornerTexCoords.assign(6, 0); }},
        {drm::kAttrCornerNormals, [](drm::Mesh& x) { x.cornerNormals.assign(9, 0); }},
        {drm::kAttrFaceColors, [](drm::Mesh& x) { x.faceColors.assign(4, 0); }},
        {drm::kAttrFaceQuality, [](drm::Mesh& x) { x.faceQuality.assign(1, 0); }},
        {drm::kAttrFaceMaterial, [](drm::Mesh& x) { x.faceMaterial.assign(1, 0); }},
        {drm::kAttrFaceMaterial, [](drm::Mesh& x) { x.materials = {"only a name"}; }},
        {drm::kAttrFaceTexture, [](drm::Mesh& x) { x.faceTexture.assign(1, 0); }},
        {drm::kAttrFaceTexture, [](drm::Mesh& x) { x.textures = {"a.png"}; }},
        {drm::kAttrMetadata, [](drm::Mesh& x) { x.metadata = {{"k", "v"}}; }},
    };
    uint32_t all = 0;
    drm::Mesh everything = m;
    for (const Case& c : cases) {
        drm::Mesh one = m;
        c.give(one);
        EXPECT_EQ(drm::attributesOf(one), c.bit) << drm::attributesName(c.bit);
        EXPECT_TRUE(one.hasAttributes());
        c.give(everything);
        all |= c.bit;
    }
    EXPECT_EQ(all, uint32_t(drm::kAttrAll));
    EXPECT_EQ(drm::attributesOf(everything), uint32_t(drm::kAttrAll));
}

}  // namespace
