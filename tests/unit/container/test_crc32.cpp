// CRC-32 (container/crc32.h), the checksum of every section: the check
// values of the standard's definition, resumption over any split of the
// data, and detection of every single-bit error.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "container/crc32.h"

namespace {

std::vector<uint8_t> bytesOf(const char* s) { return std::vector<uint8_t>(s, s + std::strlen(s)); }

TEST(Crc32, StandardCheckValue) {
    const std::vector<uint8_t> digits = bytesOf("123456789");
    EXPECT_EQ(drm::crc32(digits.data(), digits.size()), 0xCBF43926u);
    EXPECT_EQ(drm::crc32(nullptr, 0), 0u);
    const std::vector<uint8_t> fox = bytesOf("The quick brown fox jumps over the lazy dog");
    EXPECT_EQ(drm::crc32(fox.data(), fox.size()), 0x414FA339u);
}

TEST(Crc32, IsIncremental) {
    std::mt19937 rng(23);
    std::vector<uint8_t> data(300);
    for (uint8_t& b : data) b = uint8_t(rng());
    const uint32_t whole = drm::crc32(data.data(), data.size());
    for (size_t split = 0; split <= data.size(); ++split) {
        const uint32_t head = drm::crc32(data.data(), split);
        ASSERT_EQ(drm::crc32(data.data() + split, data.size() - split, head), whole) << split;
    }
}

TEST(Crc32, DetectsEverySingleBitFlip) {
    std::vector<uint8_t> data = bytesOf("distance-ranked connectivity");
    const uint32_t original = drm::crc32(data.data(), data.size());
    for (size_t bit = 0; bit < data.size() * 8; ++bit) {
        data[bit / 8] ^= uint8_t(1u << (bit % 8));
        EXPECT_NE(drm::crc32(data.data(), data.size()), original) << bit;
        data[bit / 8] ^= uint8_t(1u << (bit % 8));
    }
}

}  // namespace
