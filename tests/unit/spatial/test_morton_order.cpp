// The connectivity's vertex numbering: Morton order of the grid points
// (morton_order.h), and what encode() and decode() make of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "ranks_only.h"
#include "drmcodec/drmcodec.h"
#include "spatial/morton.h"
#include "spatial/morton_order.h"
#include "tiny_ply.h"

namespace drm {
namespace {

uint64_t keyAt(const std::vector<int32_t>& grid, uint32_t v) {
    return mortonKey(uint32_t(grid[3 * size_t(v)]), uint32_t(grid[3 * size_t(v) + 1]), uint32_t(grid[3 * size_t(v) + 2]));
}

bool inMortonOrder(const std::vector<int32_t>& grid) {
    for (uint32_t v = 1; v < grid.size() / 3; ++v)
        if (keyAt(grid, v - 1) > keyAt(grid, v)) return false;
    return true;
}

// The radix sort gives what a stable comparison sort gives, at every grid
// size, with repeated points kept in their order.
TEST(MortonOrder, SortsByKeyKeepingRepeatedPointsInOrder) {
    for (int bits : {1, 3, 12, 21}) {
        SCOPED_TRACE("bits " + std::to_string(bits));
        std::mt19937 rng{uint32_t(bits)};
        std::uniform_int_distribution<int32_t> coordinate(0, (int32_t(1) << bits) - 1);
        std::vector<int32_t> grid;
        for (int v = 0; v < 5000; ++v) {
            int32_t point[3];
            for (int32_t& c : point) c = coordinate(rng);
            grid.insert(grid.end(), point, point + 3);
            if (v % 9 == 0) grid.insert(grid.end(), point, point + 3);  // a repeated point
        }
        std::vector<uint32_t> expected(grid.size() / 3);
        std::iota(expected.begin(), expected.end(), 0u);
        std::stable_sort(expected.begin(), expected.end(),
                         [&](uint32_t a, uint32_t b) { return keyAt(grid, a) < keyAt(grid, b); });
        const std::vector<uint32_t> order = mortonOrder(grid);
        EXPECT_EQ(order, expected);
        EXPECT_TRUE(hasCoincidentPoints(grid, order));
        // Without the repeats (and, at 1 and 3 bits, the points that fell on
        // one another by chance) no point is coincident.
        std::vector<int32_t> distinct;
        for (size_t i = 0; i < order.size(); ++i)
            if (i == 0 || keyAt(grid, order[i]) != keyAt(grid, order[i - 1]))
                distinct.insert(distinct.end(), &grid[3 * size_t(order[i])], &grid[3 * size_t(order[i])] + 3);
        EXPECT_FALSE(hasCoincidentPoints(distinct, mortonOrder(distinct)));
    }
    EXPECT_TRUE(mortonOrder({}).empty());
}

Mesh meshOf(const std::string& name) { return drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name); }

// A file decodes its vertices in Morton order (without the
// section-order flag), and the encoder's vertexOrder says which input vertex
// each one is.
TEST(MortonNumbering, DecodedVerticesComeInMortonOrder) {
    for (const char* name : {"bunny-lres.ply", "fandisk.ply", "blobby-3cc.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = meshOf(name);
        for (GeometryCoder coder : {GeometryCoder::Auto, GeometryCoder::Sorted, GeometryCoder::Refine}) {
            EncodeOptions options = drm_test::ranksOnly();
            options.geometry = coder;
            options.refineBits = 3;
            options.searchStarts = false;  // so the section's order is not tried (small meshes)
            const Encoded encoded = encode(mesh, options);
            EXPECT_TRUE(encoded.stats.mortonNumbering);
            const Decoded decoded = decode(encoded.bytes);
            EXPECT_TRUE(decoded.stats.mortonNumbering);
            for (size_t d = 0; d < encoded.vertexOrder.size(); ++d)
                for (int k = 0; k < 3; ++k)
                    ASSERT_EQ(decoded.quantized[3 * d + k], encoded.quantized[3 * size_t(encoded.vertexOrder[d]) + k]);
            // Refine numbers them by its coarse grid, whose order the full
            // grid keeps only between cells.
            if (coder != GeometryCoder::Refine) EXPECT_TRUE(inMortonOrder(decoded.quantized));
        }
    }
}

// Raw bits keep the input's order, and so the vertex section's numbering.
TEST(MortonNumbering, RawBitsKeepTheInputOrder) {
    const Mesh mesh = meshOf("fandisk.ply");
    EncodeOptions options = drm_test::ranksOnly();
    options.geometry = GeometryCoder::Raw;
    for (int threads : {1, 2}) {
        options.threads = threads;
        const Encoded encoded = encode(mesh, options);
        EXPECT_FALSE(encoded.stats.mortonNumbering);
        std::vector<uint32_t> identity(mesh.vertexCount());
        std::iota(identity.begin(), identity.end(), 0u);
        EXPECT_EQ(encoded.vertexOrder, identity);
        EXPECT_EQ(decode(encoded.bytes).quantized, encoded.quantized);
    }
}

// Small meshes try both numberings and keep the smaller file: among these
// each numbering is kept somewhere (the golden files show which: torus
// Morton order, tray-bottom's CAD slivers the tree's), and either file
// decodes to the mesh, faces over the same vertices.
TEST(MortonNumbering, SmallMeshesKeepEitherNumbering) {
    std::vector<bool> kept;
    for (const char* name : {"torus.ply", "tray-bottom.ply", "bunny-lres.ply", "blobby-3cc.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = meshOf(name);
        const Encoded encoded = encode(mesh, drm_test::ranksOnly());
        const Decoded decoded = decode(encoded.bytes);
        EXPECT_EQ(decoded.stats.mortonNumbering, encoded.stats.mortonNumbering);
        kept.push_back(encoded.stats.mortonNumbering);
        for (size_t d = 0; d < encoded.vertexOrder.size(); ++d)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(decoded.quantized[3 * d + k], encoded.quantized[3 * size_t(encoded.vertexOrder[d]) + k]);
        std::vector<std::array<uint32_t, 3>> in, out;
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            const uint32_t* t = &mesh.triangles[3 * f];
            in.push_back({t[0], t[1], t[2]});
            std::rotate(in.back().begin(), std::min_element(in.back().begin(), in.back().end()), in.back().end());
            const uint32_t* u = &decoded.mesh.triangles[3 * f];
            out.push_back({encoded.vertexOrder[u[0]], encoded.vertexOrder[u[1]], encoded.vertexOrder[u[2]]});
            std::rotate(out.back().begin(), std::min_element(out.back().begin(), out.back().end()), out.back().end());
        }
        std::sort(in.begin(), in.end());
        std::sort(out.begin(), out.end());
        EXPECT_EQ(in, out);
    }
    EXPECT_NE(std::count(kept.begin(), kept.end(), true), 0);
    EXPECT_NE(std::count(kept.begin(), kept.end(), false), 0);
}

}  // namespace
}  // namespace drm
