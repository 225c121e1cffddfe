// The raw geometry section (geometry/raw_coder.h): every coordinate in
// `bits` bits, packed least significant bit first, so its size is exactly
// ceil(3 * vertices * bits / 8) bytes; it round-trips every bit depth, and
// a section of any other size is refused with the sizes named.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "geometry/raw_coder.h"

namespace drm {
namespace {

TEST(RawCoder, PacksLeastSignificantBitFirst) {
    // Three coordinates of 4 bits: 0x1, 0x2, 0x3 -> nibbles low first.
    EXPECT_EQ(packGrid({1, 2, 3}, 4), (std::vector<uint8_t>{0x21, 0x03}));
    // 12 bits: 0xABC, 0x123, 0x456 -> 0xBC, 0x3A, 0x12, 0x56, 0x04.
    EXPECT_EQ(packGrid({0xABC, 0x123, 0x456}, 12), (std::vector<uint8_t>{0xBC, 0x3A, 0x12, 0x56, 0x04}));
    // One bit a coordinate.
    EXPECT_EQ(packGrid({1, 0, 1, 1, 1, 0}, 1), (std::vector<uint8_t>{0x1D}));
    EXPECT_TRUE(packGrid({}, 12).empty());
}

TEST(RawCoder, EveryBitDepthRoundTrips) {
    std::mt19937 rng(8);
    for (int bits = 1; bits <= 21; ++bits) {
        for (size_t vertices : {size_t(1), size_t(2), size_t(7), size_t(100)}) {
            std::vector<int32_t> grid(3 * vertices);
            for (int32_t& q : grid) q = int32_t(rng() & ((1u << bits) - 1));
            grid[0] = (1 << bits) - 1;  // the top value
            const std::vector<uint8_t> bytes = packGrid(grid, bits);
            ASSERT_EQ(bytes.size(), (3 * vertices * size_t(bits) + 7) / 8) << bits;
            ASSERT_EQ(unpackGrid(bytes.data(), bytes.size(), vertices, bits), grid) << bits << " bits";
        }
    }
}

TEST(RawCoder, ASectionOfAnyOtherSizeIsCorrupt) {
    const std::vector<uint8_t> bytes = packGrid({1, 2, 3, 4, 5, 6}, 12);  // 9 bytes
    ASSERT_EQ(bytes.size(), 9u);
    for (size_t size : {size_t(0), size_t(8), size_t(10)}) {
        std::vector<uint8_t> data = bytes;
        data.resize(size, 0);
        try {
            unpackGrid(data.data(), data.size(), 2, 12);
            FAIL() << size << " bytes taken";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
            EXPECT_EQ(std::string(e.what()), "corrupt file: the geometry section has " + std::to_string(size) +
                                                 " bytes, but 2 vertices at 12 bits need 9");
        }
    }
    // A count no section could hold is refused before anything is allocated.
    EXPECT_THROW(unpackGrid(bytes.data(), bytes.size(), uint64_t(1) << 40, 12), Error);
}

}  // namespace
}  // namespace drm
