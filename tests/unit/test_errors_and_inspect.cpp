// drm::Error kinds at the library's boundary, and drm::inspect against what
// decode() reports for the same file.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "drm/drm.h"
#include "test_meshes.h"

namespace {

drm::ErrorKind kindOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const drm::Error& e) {
        return e.kind();
    }
    ADD_FAILURE() << "no drm::Error thrown";
    return drm::ErrorKind::Internal;
}

TEST(ErrorKinds, EncodeRefusesInvalidInput) {
    drm::Mesh mesh = drm_test::icosphere(1);
    drm::EncodeOptions options;
    options.bits = drm::kMaxQuantizationBits + 1;
    EXPECT_EQ(kindOf([&] { drm::encode(mesh, options); }), drm::ErrorKind::InvalidInput);
    drm::Mesh outOfRange = mesh;
    outOfRange.triangles[4] = uint32_t(mesh.vertexCount());
    EXPECT_EQ(kindOf([&] { drm::encode(outOfRange); }), drm::ErrorKind::InvalidInput);
    EXPECT_EQ(kindOf([&] { drm::encode(drm::Mesh()); }), drm::ErrorKind::InvalidInput);
    EXPECT_EQ(kindOf([&] { drm::parseLevers("filter,sideways"); }), drm::ErrorKind::InvalidInput);
}

TEST(ErrorKinds, ProgressThatSaysStopCancels) {
    drm::EncodeOptions options;
    options.progress = [](double, const char*) { return false; };
    EXPECT_EQ(kindOf([&] { drm::encode(drm_test::icosphere(2), options); }), drm::ErrorKind::Cancelled);
}

TEST(ErrorKinds, DecodeTellsCorruptFromUnsupported) {
    const std::vector<uint8_t> bytes = drm::encode(drm_test::icosphere(2)).bytes;
    EXPECT_EQ(kindOf([&] { drm::decode(nullptr, 0); }), drm::ErrorKind::Corrupt);
    EXPECT_EQ(kindOf([&] { drm::decode(bytes.data(), bytes.size() - 1); }), drm::ErrorKind::Corrupt);
    std::vector<uint8_t> flipped = bytes;
    flipped[bytes.size() / 2] ^= 1;
    EXPECT_EQ(kindOf([&] { drm::decode(flipped); }), drm::ErrorKind::Corrupt);
    EXPECT_EQ(kindOf([&] { drm::inspect(flipped); }), drm::ErrorKind::Corrupt);
    std::vector<uint8_t> future = bytes;
    future[8] = uint8_t(drm::kNewestReadableFormatVersion + 1);  // the version, little-endian, after the signature
    future[9] = 0;
    EXPECT_EQ(kindOf([&] { drm::decode(future); }), drm::ErrorKind::Unsupported);
    EXPECT_EQ(kindOf([&] { drm::inspect(future); }), drm::ErrorKind::Unsupported);
}

TEST(ErrorKinds, NamesAreDistinct) {
    EXPECT_STREQ(drm::errorKindName(drm::ErrorKind::Corrupt), "corrupt");
    EXPECT_STRNE(drm::errorKindName(drm::ErrorKind::Io), drm::errorKindName(drm::ErrorKind::Internal));
}

TEST(Inspect, AgreesWithDecodeOnEveryHeaderField) {
    for (int variant = 0; variant < 4; ++variant) {
        drm::Mesh mesh = drm_test::gridPatch(12, variant % 2 == 1, 0.2, 7);
        drm::EncodeOptions options;
        options.keepVertexOrder = variant == 2;
        options.geometry = variant == 3 ? drm::GeometryCoder::Refine : drm::GeometryCoder::SpanningTree;
        if (variant == 1) mesh.colors.assign(4 * mesh.vertexCount(), 200);
        const drm::Encoded encoded = drm::encode(mesh, options);
        const drm::FileInfo info = drm::inspect(encoded.bytes);
        const drm::Stats& d = drm::decode(encoded.bytes).stats;
        const drm::Stats& i = info.stats;
        EXPECT_EQ(info.formatVersion, drm::kFileFormatVersion);
        EXPECT_EQ(info.keepsVertexOrder, options.keepVertexOrder);
        EXPECT_EQ(i.vertices, d.vertices);
        EXPECT_EQ(i.faces, d.faces);
        EXPECT_EQ(i.components, d.components);
        EXPECT_EQ(i.bits, d.bits);
        EXPECT_EQ(i.predictor, d.predictor);
        EXPECT_EQ(i.geometry, d.geometry);
        EXPECT_EQ(i.refineBits, d.refineBits);
        EXPECT_EQ(drm::leversName(i.levers), drm::leversName(d.levers));
        EXPECT_EQ(i.headerBytes, d.headerBytes);
        EXPECT_EQ(i.connectivityBytes, d.connectivityBytes);
        EXPECT_EQ(i.geometryBytes, d.geometryBytes);
        EXPECT_EQ(i.vertexOrderBytes, d.vertexOrderBytes);
        EXPECT_EQ(i.attributeBytes, d.attributeBytes);
        ASSERT_EQ(i.attributeSizes.size(), d.attributeSizes.size());
        for (size_t s = 0; s < i.attributeSizes.size(); ++s) {
            EXPECT_EQ(i.attributeSizes[s].name, d.attributeSizes[s].name);
            EXPECT_EQ(i.attributeSizes[s].bytes, d.attributeSizes[s].bytes);
        }
        EXPECT_EQ(i.totalBytes, encoded.bytes.size());
        EXPECT_TRUE(i.rankHistogram.empty());
    }
}

TEST(Limits, LeverNamesParseBack) {
    for (int l = 0; l < drm::kLeverCount; ++l) EXPECT_NO_THROW(drm::parseLevers(drm::leverName(l)));
    EXPECT_EQ(drm::leverName(drm::kLeverCount), nullptr);
    EXPECT_EQ(drm::rankPaletteEntry(1).r, 180);
}

}  // namespace
