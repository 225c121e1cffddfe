// Which input face each decoded face is: faces given back shuffled and
// rotated are matched to their input faces and corners, equal faces pair up
// in order, a vertex shared by many faces (the runs sorted otherwise) is
// matched like any other, and faces that differ are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/face_correspondence.h"

namespace drm {
namespace {

// Shuffles and rotates input's faces; returns them with, per decoded face,
// its input face and rotation as matchFaces must find them.
std::vector<uint32_t> shuffled(const std::vector<uint32_t>& input, std::mt19937& rng, std::vector<uint32_t>& order,
                               std::vector<uint8_t>& rotation) {
    const size_t faces = input.size() / 3;
    order.resize(faces);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), rng);
    rotation.resize(faces);
    std::vector<uint32_t> decoded(input.size());
    for (size_t d = 0; d < faces; ++d) {
        rotation[d] = uint8_t(rng() % 3);
        for (int k = 0; k < 3; ++k) decoded[3 * d + size_t(k)] = input[3 * size_t(order[d]) + size_t(k + rotation[d]) % 3];
    }
    return decoded;
}

TEST(FaceCorrespondence, ShuffledRotatedFacesFindTheirInputFaces) {
    std::mt19937 rng(9);
    std::vector<uint32_t> input;
    for (int f = 0; f < 3000; ++f) {  // random distinct triangles over 500 vertices
        uint32_t a = rng() % 500, b = rng() % 500, c = rng() % 500;
        if (a == b || b == c || a == c) continue;
        input.insert(input.end(), {a, b, c});
    }
    for (uint32_t k = 1; k <= 100; ++k) input.insert(input.end(), {0, k, k + 1});  // a fan of 100 around vertex 0
    std::vector<uint32_t> order;
    std::vector<uint8_t> rotation;
    const std::vector<uint32_t> decoded = shuffled(input, rng, order, rotation);
    std::vector<uint32_t> foundOrder;
    std::vector<uint8_t> foundRotation;
    matchFaces(input, decoded, foundOrder, foundRotation);
    for (size_t d = 0; d < order.size(); ++d) {
        // Any input face over the same corners in the same rotation is right
        // (random triangles may repeat one).
        const uint32_t f = foundOrder[d];
        for (int k = 0; k < 3; ++k)
            ASSERT_EQ(decoded[3 * d + size_t(k)], input[3 * size_t(f) + size_t(k + foundRotation[d]) % 3]) << "face " << d;
    }
    std::vector<uint32_t> sorted = foundOrder;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // each input face once
}

TEST(FaceCorrespondence, EqualFacesPairUpInOrder) {
    // Face 0 and 2 are the same triangle, as are 1 and 3 (rotated).
    const std::vector<uint32_t> input = {1, 2, 3, 4, 5, 6, 1, 2, 3, 5, 6, 4};
    const std::vector<uint32_t> decoded = {2, 3, 1, 6, 4, 5, 3, 1, 2, 4, 5, 6};
    std::vector<uint32_t> order;
    std::vector<uint8_t> rotation;
    matchFaces(input, decoded, order, rotation);
    EXPECT_EQ(order, (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(rotation, (std::vector<uint8_t>{1, 2, 2, 2}));  // decoded corner k is input corner (k + rotation) % 3
}

TEST(FaceCorrespondence, DifferentFacesAreRefused) {
    std::vector<uint32_t> order;
    std::vector<uint8_t> rotation;
    EXPECT_THROW(matchFaces({1, 2, 3}, {1, 3, 2}, order, rotation), Error);  // the other orientation
    EXPECT_THROW(matchFaces({1, 2, 3}, {1, 2, 3, 1, 2, 3}, order, rotation), Error);
}

}  // namespace
}  // namespace drm
