// encode() and decode() as the library offers them (mesh_codec.cpp): the
// drm::Error kind of each refusal at the library's boundary.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "drmcodec/drmcodec.h"
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
    future[8] = uint8_t(drm::kFileFormatVersion + 1);  // the version, little-endian, after the signature
    future[9] = 0;
    EXPECT_EQ(kindOf([&] { drm::decode(future); }), drm::ErrorKind::Unsupported);
    EXPECT_EQ(kindOf([&] { drm::inspect(future); }), drm::ErrorKind::Unsupported);
}

}  // namespace
