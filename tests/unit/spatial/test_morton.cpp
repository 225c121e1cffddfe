// morton.h against its definition: bit 3i of a key is bit i of x, 3i + 1
// bit i of y, 3i + 2 bit i of z, for coordinates of 21 bits; spreading and
// gathering are each other's inverse; and every cell of power-of-two width
// is one run of keys (the property the cell searches rely on).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "spatial/morton.h"

namespace drm {
namespace {

// The key bit by bit, as the definition reads.
uint64_t keyByBits(uint32_t x, uint32_t y, uint32_t z) {
    uint64_t key = 0;
    for (int i = 0; i < 21; ++i) {
        key |= uint64_t((x >> i) & 1) << (3 * i);
        key |= uint64_t((y >> i) & 1) << (3 * i + 1);
        key |= uint64_t((z >> i) & 1) << (3 * i + 2);
    }
    return key;
}

TEST(Morton, KeysInterleaveTheBitsOfXYAndZ) {
    EXPECT_EQ(mortonKey(0, 0, 0), 0u);
    EXPECT_EQ(mortonKey(1, 0, 0), 1u);
    EXPECT_EQ(mortonKey(0, 1, 0), 2u);
    EXPECT_EQ(mortonKey(0, 0, 1), 4u);
    EXPECT_EQ(mortonKey(2, 0, 0), 8u);
    const uint32_t top = (1u << 21) - 1;
    EXPECT_EQ(mortonKey(top, top, top), (uint64_t(1) << 63) - 1);  // 63 bits, all set
    std::mt19937 rng(6);
    for (int i = 0; i < 10000; ++i) {
        const uint32_t x = rng() & top, y = rng() & top, z = rng() & top;
        ASSERT_EQ(mortonKey(x, y, z), keyByBits(x, y, z));
        const int32_t p[3] = {int32_t(x), int32_t(y), int32_t(z)};
        ASSERT_EQ(mortonKeyOf(p), keyByBits(x, y, z));
    }
}

TEST(Morton, SpreadAndGatherAreInverses) {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 10000; ++i) {
        const uint32_t x = uint32_t(rng()) & 0x1FFFFF;
        ASSERT_EQ(gatherMortonBits(spreadMortonBits(x)), x);
        const uint64_t key = rng() >> 1;
        // Each coordinate gathered from its own bits, spread back, gives the key.
        const uint64_t rebuilt = spreadMortonBits(gatherMortonBits(key)) | spreadMortonBits(gatherMortonBits(key >> 1)) << 1 |
                                 spreadMortonBits(gatherMortonBits(key >> 2)) << 2;
        ASSERT_EQ(rebuilt, key);
    }
    // Bits above the 21st are dropped, not carried into the next coordinate.
    EXPECT_EQ(spreadMortonBits(uint64_t(1) << 21), 0u);
    EXPECT_EQ(spreadMortonBits((uint64_t(1) << 21) | 1), 1u);
}

TEST(Morton, EveryPowerOfTwoCellIsOneRunOfKeys) {
    // Points of an 8^3 block: for every cell width 2^w, the points of one
    // cell have consecutive keys once sorted, and no other point's key
    // lies among them.
    std::vector<std::pair<uint64_t, uint32_t>> keyed;
    for (uint32_t x = 0; x < 8; ++x)
        for (uint32_t y = 0; y < 8; ++y)
            for (uint32_t z = 0; z < 8; ++z) keyed.emplace_back(mortonKey(x + 16, y + 8, z), (x << 6) | (y << 3) | z);
    std::sort(keyed.begin(), keyed.end());
    for (int w = 0; w <= 3; ++w) {
        std::vector<uint32_t> cellOf;
        for (const auto& k : keyed) {
            const uint32_t x = (k.second >> 6) >> w, y = ((k.second >> 3) & 7) >> w, z = (k.second & 7) >> w;
            cellOf.push_back((x << 6) | (y << 3) | z);
        }
        // A cell seen again after another one started would split its run.
        std::vector<uint32_t> finished;
        for (size_t i = 0; i < cellOf.size(); ++i) {
            if (i > 0 && cellOf[i] != cellOf[i - 1]) finished.push_back(cellOf[i - 1]);
            ASSERT_EQ(std::find(finished.begin(), finished.end(), cellOf[i]), finished.end()) << "width " << (1 << w);
        }
    }
}

}  // namespace
}  // namespace drm
