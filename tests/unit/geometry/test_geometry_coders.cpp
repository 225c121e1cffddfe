// The table of geometry coders (geometry/geometry_coders.h), keyed by the
// id the header stores: ids 1 to 4 and the names the parser takes find
// their rows, nothing else does; every coder's section decodes to the grid
// it was given, in the order it reports (the raw coder's being the input
// order); fallbacks and second passes are where the header says; and a
// one-pass coder reports no refine bits.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "geometry/geometry_coders.h"
#include "geometry/refine_coder.h"
#include "mesh/quantize.h"
#include "tiny_ply.h"

namespace drm {
namespace {

TEST(GeometryCoders, IdsAndNamesFindTheirRows) {
    EXPECT_EQ(geometryCoderById(0), nullptr);
    for (uint8_t id = 5; id != 0; ++id) EXPECT_EQ(geometryCoderById(id), nullptr) << int(id);
    std::set<std::string> names;
    for (uint8_t id = 1; id <= 4; ++id) {
        const GeometryCoderEntry* entry = geometryCoderById(id);
        ASSERT_NE(entry, nullptr) << int(id);
        EXPECT_EQ(uint8_t(entry->id), id);
        EXPECT_EQ(geometryCoderByName(entry->name), entry);
        EXPECT_EQ(geometryCoderOf(entry->id), entry);
        EXPECT_TRUE(names.insert(entry->name).second);
        EXPECT_NE(entry->encode, nullptr);
        EXPECT_NE(entry->decode, nullptr);
        EXPECT_NE(entry->refineBits, nullptr);
        // Both passes of a two-pass coder, or neither.
        EXPECT_EQ(entry->encodeAfterConnectivity == nullptr, entry->decodeAfterConnectivity == nullptr);
    }
    EXPECT_EQ(names, (std::set<std::string>{"raw", "tree", "refine", "sorted"}));
    EXPECT_EQ(geometryCoderByName("auto"), nullptr);  // an option, not a coder
    EXPECT_EQ(geometryCoderByName("Tree"), nullptr);
    EXPECT_EQ(geometryCoderOf(GeometryCoder::Auto), nullptr);
}

TEST(GeometryCoders, TheListingHoldsEveryCoderTheDefaultFirst) {
    const std::vector<const GeometryCoderEntry*>& listed = geometryCoders();
    ASSERT_EQ(listed.size(), 4u);
    EXPECT_EQ(listed[0]->id, GeometryCoder::SpanningTree);
    std::set<const GeometryCoderEntry*> distinct(listed.begin(), listed.end());
    EXPECT_EQ(distinct.size(), 4u);
}

TEST(GeometryCoders, FallbacksAndPassesAreWhereTheFormatSaysTheyAre) {
    const GeometryCoderEntry* raw = geometryCoderOf(GeometryCoder::Raw);
    const GeometryCoderEntry* tree = geometryCoderOf(GeometryCoder::SpanningTree);
    const GeometryCoderEntry* refine = geometryCoderOf(GeometryCoder::Refine);
    const GeometryCoderEntry* sorted = geometryCoderOf(GeometryCoder::Sorted);
    // The tree falls back to the sorted points, they to raw bits, raw to
    // nothing; following fallbacks always ends.
    EXPECT_EQ(tree->fallback, sorted);
    EXPECT_EQ(sorted->fallback, raw);
    EXPECT_EQ(raw->fallback, nullptr);
    EXPECT_EQ(refine->fallback, nullptr);
    // Only refine codes anything after the connectivity; only raw keeps
    // the input's numbering.
    for (const GeometryCoderEntry* e : geometryCoders()) {
        EXPECT_EQ(e->encodeAfterConnectivity != nullptr, e == refine) << e->name;
        EXPECT_EQ(e->keepsInputOrder, e == raw) << e->name;
    }
}

// Every one-pass coder's section decodes to the grid in the order it says.
void expectRoundTrip(const std::vector<int32_t>& grid, int bits) {
    for (GeometryCoder id : {GeometryCoder::Raw, GeometryCoder::SpanningTree, GeometryCoder::Sorted}) {
        const GeometryCoderEntry* coder = geometryCoderOf(id);
        SCOPED_TRACE(coder->name);
        const GeometryEncoding encoding = coder->encode(grid, bits, NeighbourIndex::Grid, nullptr, 1);
        const size_t n = grid.size() / 3;
        ASSERT_EQ(encoding.order.size(), n);
        const VertexSet decoded = coder->decode(encoding.bytes.data(), encoding.bytes.size(), n, bits);
        ASSERT_EQ(decoded.grid.size(), grid.size());
        EXPECT_EQ(decoded.lowBits, 0);
        EXPECT_EQ(coder->refineBits(encoding.bytes.data(), encoding.bytes.size(), bits), 0);
        std::vector<uint8_t> seen(n, 0);
        for (size_t d = 0; d < n; ++d) {
            const uint32_t v = encoding.order[d];
            ASSERT_LT(v, n);
            ASSERT_FALSE(seen[v]) << "vertex " << v << " twice in the order";
            seen[v] = 1;
            for (int k = 0; k < 3; ++k) ASSERT_EQ(decoded.grid[3 * d + k], grid[3 * size_t(v) + k]);
            if (coder->keepsInputOrder) ASSERT_EQ(v, d);
        }
        // A section cut short never decodes quietly to the full grid.
        if (encoding.bytes.size() > 1) {
            try {
                const VertexSet cut = coder->decode(encoding.bytes.data(), encoding.bytes.size() - 1, n, bits);
                EXPECT_NE(cut.grid, decoded.grid);
            } catch (const Error& e) {
                EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
            }
        }
    }
}

TEST(GeometryCoders, EachCoderDecodesTheGridItWasGiven) {
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    expectRoundTrip(quantize(bunny.positions, makeGrid(bunny.positions, 12)), 12);
    // Scattered points with repeats, at a few depths.
    std::mt19937 rng(9);
    for (int bits : {1, 5, 16, 21}) {
        std::vector<int32_t> grid;
        for (int i = 0; i < 300; ++i)
            for (int k = 0; k < 3; ++k) grid.push_back(int32_t(rng() & ((1u << bits) - 1)));
        grid.insert(grid.end(), grid.begin(), grid.begin() + 30);
        SCOPED_TRACE(std::to_string(bits) + " bits");
        expectRoundTrip(grid, bits);
    }
    expectRoundTrip({5, 6, 7}, 3);  // a single point
}

// Refine through the table's two passes: the coarse grid coded first, the
// low bits across the decoded triangles after; the section reports its low
// bits, and the decoder's two passes give back the full grid.
TEST(GeometryCoders, RefinesTwoPassesGiveBackTheFullGrid) {
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    const int bits = 12;
    const std::vector<int32_t> fine = quantize(bunny.positions, makeGrid(bunny.positions, bits));
    const size_t n = fine.size() / 3;
    const GeometryCoderEntry* refine = geometryCoderOf(GeometryCoder::Refine);
    for (int lowBits : {1, 3, kMaxRefineBits}) {
        SCOPED_TRACE(std::to_string(lowBits) + " low bits");
        const GeometryEncoding first = refine->encode(coarsenGrid(fine, lowBits), bits - lowBits, NeighbourIndex::Grid,
                                                      nullptr, 1);
        ASSERT_EQ(first.order.size(), n);
        // The full grid and the triangles in the decoded order.
        std::vector<uint32_t> decodedOf(n);
        std::vector<int32_t> fineDecoded(fine.size());
        for (size_t d = 0; d < n; ++d) {
            decodedOf[first.order[d]] = uint32_t(d);
            for (int k = 0; k < 3; ++k) fineDecoded[3 * d + k] = fine[3 * size_t(first.order[d]) + k];
        }
        std::vector<uint32_t> triangles = bunny.triangles;
        for (uint32_t& v : triangles) v = decodedOf[v];
        const std::vector<uint8_t> section = refine->encodeAfterConnectivity(first.bytes, fineDecoded, lowBits, triangles);
        EXPECT_EQ(refine->refineBits(section.data(), section.size(), bits), lowBits);
        const VertexSet vertices = refine->decode(section.data(), section.size(), n, bits);
        EXPECT_EQ(vertices.lowBits, lowBits);
        EXPECT_EQ(vertices.grid, coarsenGrid(fineDecoded, lowBits));
        EXPECT_EQ(refine->decodeAfterConnectivity(vertices, vertices.grid, triangles), fineDecoded);
    }
}

}  // namespace
}  // namespace drm
