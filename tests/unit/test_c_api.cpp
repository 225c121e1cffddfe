// The C API (<drmcodec/drmcodec_c.h>, c_api.cpp): the same meshes and the
// same messages as the C++ API, every array and figure a decoded file has,
// and failures reported as a status and a message, never thrown.
#include <drmcodec/drmcodec.h>
#include <drmcodec/drmcodec_c.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "test_meshes.h"

namespace {

std::vector<uint8_t> encoded(const drm::Mesh& mesh) { return drm::encode(mesh).bytes; }

TEST(CApi, DecodesTheArraysAndFiguresTheCppApiGives) {
    drm::Mesh mesh = drm_test::tetrahedron();
    mesh.colors = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    mesh.faceMaterial = {0, 1, 0, 1};
    mesh.materials = {"stone", "wood"};
    const std::vector<uint8_t> bytes = encoded(mesh);
    const drm::Decoded expected = drm::decode(bytes);

    drmcodec_decoded* d = drmcodec_decode(bytes.data(), bytes.size(), 1);
    ASSERT_EQ(drmcodec_decoded_status(d), DRMCODEC_OK);
    EXPECT_STREQ(drmcodec_decoded_error(d), "");
    size_t n = 0;
    const float* positions = static_cast<const float*>(drmcodec_decoded_array(d, DRMCODEC_POSITIONS, &n));
    ASSERT_EQ(n, expected.mesh.positions.size());
    EXPECT_EQ(std::memcmp(positions, expected.mesh.positions.data(), n * sizeof(float)), 0);
    const uint32_t* triangles = static_cast<const uint32_t*>(drmcodec_decoded_array(d, DRMCODEC_TRIANGLES, &n));
    ASSERT_EQ(n, expected.mesh.triangles.size());
    EXPECT_EQ(std::vector<uint32_t>(triangles, triangles + n), expected.mesh.triangles);
    const uint8_t* colors = static_cast<const uint8_t*>(drmcodec_decoded_array(d, DRMCODEC_COLORS, &n));
    EXPECT_EQ(std::vector<uint8_t>(colors, colors + n), expected.mesh.colors);
    drmcodec_decoded_array(d, DRMCODEC_FACE_MATERIAL, &n);
    EXPECT_EQ(n, 4u);
    drmcodec_decoded_array(d, DRMCODEC_FACE_RANK, &n);
    EXPECT_EQ(n, 4u);
    drmcodec_decoded_array(d, DRMCODEC_QUANTIZED, &n);
    EXPECT_EQ(n, expected.quantized.size());
    EXPECT_EQ(drmcodec_decoded_array(d, DRMCODEC_NORMALS, &n), nullptr);  // not in the file
    EXPECT_EQ(n, 0u);
    EXPECT_EQ(drmcodec_decoded_array(d, DRMCODEC_ARRAY_COUNT, &n), nullptr);
    ASSERT_EQ(drmcodec_decoded_name_count(d, DRMCODEC_MATERIAL_NAMES), 2u);
    EXPECT_STREQ(drmcodec_decoded_name(d, DRMCODEC_MATERIAL_NAMES, 1), "wood");
    EXPECT_EQ(drmcodec_decoded_name(d, DRMCODEC_MATERIAL_NAMES, 2), nullptr);
    EXPECT_EQ(drmcodec_decoded_name_count(d, DRMCODEC_TEXTURE_NAMES), 0u);
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_VERTICES), double(expected.stats.vertices));
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_FACES), 4.0);
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_TOTAL_BYTES), double(bytes.size()));
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_GRID_STEP), expected.grid.step);
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_BITS), 12.0);
    EXPECT_STREQ(drmcodec_decoded_connectivity(d), drm::connectivityCoderName(expected.stats.connectivity));
    EXPECT_STRNE(drmcodec_decoded_geometry(d), "");
    drmcodec_decoded_free(d);
}

TEST(CApi, ADamagedFileGivesTheCppMessageAndNoArrays) {
    std::vector<uint8_t> bytes = encoded(drm_test::tetrahedron());
    bytes[bytes.size() / 2] ^= 0x40;
    std::string message;
    try {
        drm::decode(bytes);
    } catch (const drm::Error& e) {
        message = e.what();
    }
    ASSERT_FALSE(message.empty());
    drmcodec_decoded* d = drmcodec_decode(bytes.data(), bytes.size(), 0);
    EXPECT_EQ(drmcodec_decoded_status(d), DRMCODEC_CORRUPT);
    EXPECT_EQ(drmcodec_decoded_error(d), message);
    size_t n = 7;
    EXPECT_EQ(drmcodec_decoded_array(d, DRMCODEC_POSITIONS, &n), nullptr);
    EXPECT_EQ(n, 0u);
    EXPECT_EQ(drmcodec_decoded_stat(d, DRMCODEC_VERTICES), 0.0);
    EXPECT_STREQ(drmcodec_decoded_connectivity(d), "");
    drmcodec_decoded_free(d);

    d = drmcodec_decode(nullptr, 0, 1);
    EXPECT_EQ(drmcodec_decoded_status(d), DRMCODEC_CORRUPT);
    drmcodec_decoded_free(d);
    d = drmcodec_decode(nullptr, 10, 1);
    EXPECT_EQ(drmcodec_decoded_status(d), DRMCODEC_INVALID_INPUT);
    drmcodec_decoded_free(d);
    d = drmcodec_decode(bytes.data(), bytes.size(), -1);
    EXPECT_EQ(drmcodec_decoded_status(d), DRMCODEC_INVALID_INPUT);
    drmcodec_decoded_free(d);
}

TEST(CApi, EncodesAsTheCppApiDoesAndRefusesBadIndices) {
    const drm::Mesh mesh = drm_test::tetrahedron();
    drmcodec_encoded* e = drmcodec_encode(mesh.positions.data(), mesh.vertexCount(), mesh.triangles.data(),
                                          mesh.faceCount(), DRMCODEC_DEFAULT_BITS);
    ASSERT_EQ(drmcodec_encoded_status(e), DRMCODEC_OK);
    size_t size = 0;
    const uint8_t* bytes = drmcodec_encoded_bytes(e, &size);
    EXPECT_EQ(std::vector<uint8_t>(bytes, bytes + size), encoded(mesh));
    drmcodec_encoded_free(e);

    std::vector<uint32_t> bad = mesh.triangles;
    bad[5] = 0xFFFFFFFFu;
    e = drmcodec_encode(mesh.positions.data(), mesh.vertexCount(), bad.data(), mesh.faceCount(), 12);
    EXPECT_EQ(drmcodec_encoded_status(e), DRMCODEC_INVALID_INPUT);
    EXPECT_NE(std::string(drmcodec_encoded_error(e)).find("face 1"), std::string::npos) << drmcodec_encoded_error(e);
    EXPECT_EQ(drmcodec_encoded_bytes(e, &size), nullptr);
    EXPECT_EQ(size, 0u);
    drmcodec_encoded_free(e);
    e = drmcodec_encode(mesh.positions.data(), mesh.vertexCount(), mesh.triangles.data(), mesh.faceCount(), 40);
    EXPECT_EQ(drmcodec_encoded_status(e), DRMCODEC_INVALID_INPUT);
    drmcodec_encoded_free(e);
    // A count no index can reach is refused before anything is read.
    e = drmcodec_encode(mesh.positions.data(), SIZE_MAX / 12 - 1, mesh.triangles.data(), mesh.faceCount(), 12);
    EXPECT_EQ(drmcodec_encoded_status(e), DRMCODEC_INVALID_INPUT);
    EXPECT_NE(std::string(drmcodec_encoded_error(e)).find("too large"), std::string::npos) << drmcodec_encoded_error(e);
    drmcodec_encoded_free(e);
}

TEST(CApi, StatusNamesAreTheErrorKinds) {
    EXPECT_STREQ(drmcodec_status_name(DRMCODEC_OK), "ok");
    EXPECT_STREQ(drmcodec_status_name(DRMCODEC_CORRUPT), drm::errorKindName(drm::ErrorKind::Corrupt));
    EXPECT_STREQ(drmcodec_status_name(DRMCODEC_INTERNAL), drm::errorKindName(drm::ErrorKind::Internal));
    EXPECT_STREQ(drmcodec_status_name(DRMCODEC_OUT_OF_MEMORY), "out of memory");
    EXPECT_STREQ(drmcodec_status_name(99), "unknown");
    EXPECT_STREQ(drmcodec_version(), drm::version());
    drmcodec_decoded_free(nullptr);
    drmcodec_encoded_free(nullptr);
}

}  // namespace
