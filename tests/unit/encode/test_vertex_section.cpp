// An attempt's vertex section (encode/vertex_section.h): the coder asked
// for, or the first of its fallbacks that is no larger (scattered points
// end in sorted points or raw bits, a scan keeps its tree); refine codes
// the coarse grid; an attempt built on a section decodes to the mesh,
// numbered in Morton order or, for raw bits, in the input's; and the
// connectivity coded before the section, in the Morton order it guesses,
// is the attempt kept once the section exists.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "encode/vertex_section.h"
#include "geometry/refine_coder.h"
#include "prepared_session.h"
#include "spatial/morton_order.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

Mesh bunny() { return drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"); }

// The section decodes to the grid it coded, in the order it reports.
void expectSectionDecodes(const VertexSection& section, const std::vector<int32_t>& grid, int bits) {
    const size_t n = grid.size() / 3;
    const VertexSet decoded = section.coder->decode(section.encoding.bytes.data(), section.encoding.bytes.size(), n, bits);
    ASSERT_EQ(decoded.grid.size(), grid.size());
    for (size_t d = 0; d < n; ++d)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(decoded.grid[3 * d + k], grid[3 * size_t(section.encoding.order[d]) + k]);
}

TEST(VertexSection, TheCoderAskedForOrANoLargerFallback) {
    const Mesh scan = bunny();
    const EncodeOptions o;
    const std::vector<int32_t> q = quantize(scan.positions, makeGrid(scan.positions, o.bits));
    const VertexSection tree = codeVertexSection(q, o, GeometryCoder::SpanningTree, 0, nullptr, 1);
    EXPECT_EQ(tree.coder->id, GeometryCoder::SpanningTree);  // a scan predicts well
    expectSectionDecodes(tree, q, o.bits);
    const VertexSection raw = codeVertexSection(q, o, GeometryCoder::Raw, 0, nullptr, 1);
    EXPECT_EQ(raw.coder->id, GeometryCoder::Raw);
    EXPECT_LT(tree.encoding.bytes.size(), raw.encoding.bytes.size());
    // Points scattered at random over the whole grid: the tree does no
    // better than the sorted points or raw bits, which take its place.
    std::mt19937 rng(17);
    std::vector<int32_t> scattered(3 * 400);
    for (int32_t& c : scattered) c = int32_t(rng() % 4096);
    const VertexSection fallback = codeVertexSection(scattered, o, GeometryCoder::SpanningTree, 0, nullptr, 1);
    EXPECT_NE(fallback.coder->id, GeometryCoder::SpanningTree);
    EXPECT_LE(fallback.encoding.bytes.size(), (scattered.size() * size_t(o.bits) + 7) / 8);  // raw bits at most
    expectSectionDecodes(fallback, scattered, o.bits);
}

TEST(VertexSection, RefineCodesTheCoarseGrid) {
    const Mesh scan = bunny();
    const EncodeOptions o;
    const std::vector<int32_t> q = quantize(scan.positions, makeGrid(scan.positions, o.bits));
    const VertexSection refine = codeVertexSection(q, o, GeometryCoder::Refine, 3, nullptr, 1);
    EXPECT_EQ(refine.coder->id, GeometryCoder::Refine);
    // The first pass: the coarse grid as a tree section at 3 bits fewer
    // (the low bits follow after the connectivity).
    VertexSection coarse = refine;
    coarse.coder = geometryCoderOf(GeometryCoder::SpanningTree);
    expectSectionDecodes(coarse, coarsenGrid(q, 3), o.bits - 3);
}

TEST(VertexSection, AttemptsOnASectionDecodeToTheMesh) {
    const Progress none;
    for (GeometryCoder coder : {GeometryCoder::SpanningTree, GeometryCoder::Raw, GeometryCoder::Sorted}) {
        SCOPED_TRACE(geometryCoderName(coder));
        for (const Mesh& m : {bunny(), drm_test::meshNeedingRepairs()}) {
            EncodeOptions o;
            o.threads = 1;
            const drm_test::PreparedSession s(m, o);
            ProgressReporter progress(none);
            VertexSectionPlan plan;
            plan.coder = coder;
            const Attempt attempt = encodeWithGeometry(s.session(), plan, progress);
            drm_test::expectAttemptDecodes(attempt, s);
            if (attempt.header.geometryCoder == GeometryCoder::Raw) {
                // Raw bits keep the input's numbering.
                EXPECT_FALSE(attempt.header.mortonNumbering);
                for (size_t v = 0; v < attempt.encoded.vertexOrder.size(); ++v)
                    ASSERT_EQ(attempt.encoded.vertexOrder[v], v);
            }
        }
    }
}

TEST(VertexSection, TheEarlyConnectivityIsKeptOnceTheSectionExists) {
    const Mesh m = bunny();
    EncodeOptions o;
    o.threads = 1;
    o.searchStarts = false;  // one numbering: the early one
    const drm_test::PreparedSession s(m, o);
    const Progress none;
    ProgressReporter progress(none);
    EarlyConnectivity early = encodeBeforeVertexSection(s.session(), progress);
    const std::vector<uint32_t> morton = mortonOrder(s.prepared.quantized);
    EXPECT_EQ(early.order, morton);
    EXPECT_EQ(early.certain, !hasCoincidentPoints(s.prepared.quantized, early.order));
    const std::vector<uint8_t> connectivity = early.attempt.connectivity;
    VertexSectionPlan plan;
    plan.early = &early;
    const Attempt attempt = encodeWithGeometry(s.session(), plan, progress);
    drm_test::expectAttemptDecodes(attempt, s);
    EXPECT_TRUE(attempt.header.mortonNumbering);
    // The early attempt, numbered as guessed, is the one kept (and handed over).
    EXPECT_EQ(attempt.connectivity, connectivity);
    EXPECT_EQ(attempt.encoded.vertexOrder, morton);
    EXPECT_TRUE(early.order.empty());
}

}  // namespace
}  // namespace drm
