// Geometry coder 4, the sorted points (sorted_coder.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "geometry/sorted_coder.h"
#include "tiny_ply.h"

namespace drm {
namespace {

std::vector<int32_t> randomCloud(size_t n, int bits, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int32_t> coordinate(0, (int32_t(1) << bits) - 1);
    std::vector<int32_t> grid;
    for (size_t v = 0; v < n; ++v) {
        for (int k = 0; k < 3; ++k) grid.push_back(coordinate(rng));
        if (v % 7 == 0) grid.insert(grid.end(), grid.end() - 3, grid.end());  // a repeated point
    }
    grid.insert(grid.end(), {0, 0, 0});
    const int32_t top = (int32_t(1) << bits) - 1;
    grid.insert(grid.end(), {top, top, top});
    return grid;
}

// Decoded vertex d is input vertex order[d], at the same grid point; the
// order is a permutation, in Morton order with ties by input index.
TEST(SortedPoints, RoundTripGivesEveryPointInItsOrder) {
    for (int bits : {1, 5, 12, 21}) {
        SCOPED_TRACE("bits " + std::to_string(bits));
        const std::vector<int32_t> grid = randomCloud(3000, bits, uint32_t(bits));
        std::vector<uint32_t> order;
        const std::vector<uint8_t> bytes = encodeSortedPoints(grid, bits, order);
        const size_t n = grid.size() / 3;
        ASSERT_EQ(order.size(), n);
        std::vector<uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        for (size_t v = 0; v < n; ++v) ASSERT_EQ(sorted[v], v);
        const std::vector<int32_t> decoded = decodeSortedPoints(bytes.data(), bytes.size(), n, bits);
        ASSERT_EQ(decoded.size(), grid.size());
        for (size_t d = 0; d < n; ++d)
            for (int k = 0; k < 3; ++k) ASSERT_EQ(decoded[3 * d + k], grid[3 * size_t(order[d]) + k]) << "vertex " << d;
        for (size_t d = 1; d < n; ++d)
            if (std::equal(&decoded[3 * d], &decoded[3 * d + 3], &decoded[3 * d - 3])) EXPECT_LT(order[d - 1], order[d]);
    }
}

// A set of random points costs what the set itself holds (log2 C(cells, n)
// / n bits a point: 25.89 for 3000 points on a 12-bit grid) plus the
// lengths' learning, and far less than raw bits (36).
TEST(SortedPoints, RandomPointsCostNearTheirEntropy) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int32_t> coordinate(0, 4095);
    std::vector<int32_t> grid(9000);
    for (int32_t& c : grid) c = coordinate(rng);
    std::vector<uint32_t> order;
    const double bitsPerPoint = 8.0 * double(encodeSortedPoints(grid, 12, order).size()) / 3000.0;
    EXPECT_LT(bitsPerPoint, 26.2);  // 25.98 measured
    EXPECT_GT(bitsPerPoint, 25.88);
}

TEST(SortedPoints, EmptyAndSingle) {
    std::vector<uint32_t> order;
    const std::vector<uint8_t> none = encodeSortedPoints({}, 12, order);
    EXPECT_TRUE(order.empty());
    EXPECT_TRUE(decodeSortedPoints(none.data(), none.size(), 0, 12).empty());
    const std::vector<uint8_t> one = encodeSortedPoints({7, 4095, 0}, 12, order);
    EXPECT_EQ(decodeSortedPoints(one.data(), one.size(), 1, 12), (std::vector<int32_t>{7, 4095, 0}));
}

TEST(SortedPoints, MalformedSectionsAreCorrupt) {
    const std::vector<int32_t> grid = randomCloud(500, 21, 3);
    std::vector<uint32_t> order;
    const std::vector<uint8_t> bytes = encodeSortedPoints(grid, 21, order);
    const size_t n = grid.size() / 3;
    auto expectCorrupt = [](const std::vector<uint8_t>& data, uint64_t count, int bits, const char* what) {
        try {
            decodeSortedPoints(data.data(), data.size(), count, bits);
            ADD_FAILURE() << what << ": decoded";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << what << ": " << e.what();
        }
    };
    expectCorrupt(std::vector<uint8_t>(bytes.begin(), bytes.begin() + ptrdiff_t(bytes.size() / 2)), n, 21, "truncated");
    expectCorrupt(bytes, n, 6, "points beyond a smaller grid");
    expectCorrupt(bytes, uint64_t(1) << 40, 21, "a count no section of this size holds");
    expectCorrupt({}, 5, 12, "empty");
    std::vector<uint8_t> garbage(200, 0xFF);
    expectCorrupt(garbage, 100, 12, "garbage");
}

// The encoder keeps the sorted points where the tree predicts no better:
// a soup of 100 scattered triangles (tests/data/soup.ply).
TEST(SortedPoints, TheEncoderTakesThemForASoup) {
    const Mesh soup = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/soup.ply");
    const Encoded chosen = encode(soup, EncodeOptions());
    EXPECT_EQ(inspect(chosen.bytes).stats.geometry, GeometryCoder::Sorted);
    EncodeOptions raw;
    raw.geometry = GeometryCoder::Raw;
    EXPECT_LT(chosen.bytes.size(), encode(soup, raw).bytes.size());
    const Decoded decoded = decode(chosen.bytes.data(), chosen.bytes.size());
    EXPECT_EQ(decoded.mesh.triangles.size(), soup.triangles.size());
    EXPECT_EQ(decoded.mesh.vertexCount(), soup.vertexCount());
}

}  // namespace
}  // namespace drm
