// A ranked attempt (encode/ranked_attempt.h): over a numbering the caller
// chooses, encodeNumbered codes the connectivity and its file, written by
// writeAttempt with a vertex section, decodes to the mesh, repairs and the
// input numbering kept included; writeAttempt writes the header, sections
// and figures of a file readFile reads back; and repairsInDecodedOrder puts
// the cut's flips and repeated faces in the decoder's face order.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "container/file_format.h"
#include "encode/ranked_attempt.h"
#include "geometry/geometry_coders.h"
#include "prepared_session.h"
#include "spatial/morton_order.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

// The attempt over the raw bits of the input's points, numbered in the
// input's order: a file that needs nothing else.
Attempt rawAttempt(const drm_test::PreparedSession& s) {
    NumberedMesh numbered;
    numbered.geometryCoder = GeometryCoder::Raw;
    numbered.mortonNumbering = false;
    numbered.order.resize(s.mesh.vertexCount());
    std::iota(numbered.order.begin(), numbered.order.end(), 0u);
    const Progress none;
    ProgressReporter progress(none);
    Attempt attempt = encodeNumbered(s.session(), numbered, s.prepared.quantized, progress);
    writeAttempt(attempt, GeometryCoder::Raw, geometryCoderOf(GeometryCoder::Raw)->encode(s.prepared.quantized, s.options.bits,
                                                                                         NeighbourIndex::Grid, nullptr, 1).bytes);
    return attempt;
}

TEST(RankedAttempt, ANumberingTheCallerChoosesDecodes) {
    for (const Mesh& m : {drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"),
                          drm_test::meshNeedingRepairs(), drm_test::mixedMesh()}) {
        EncodeOptions o;
        o.threads = 1;
        const drm_test::PreparedSession s(m, o);
        const Attempt attempt = rawAttempt(s);
        EXPECT_EQ(attempt.header.geometryCoder, GeometryCoder::Raw);
        EXPECT_EQ(attempt.header.hasRepairs, s.prepared.repaired);
        EXPECT_EQ(attempt.header.copyCount, s.cut.copyOf.size());
        drm_test::expectAttemptDecodes(attempt, s);
        // Ranked faces: every face but the start triangles and the repaired
        // ones has a rank of 1 or more.
        ASSERT_EQ(attempt.encoded.faceRank.size(), m.faceCount());
        uint64_t ranked = 0;
        for (uint32_t r : attempt.encoded.faceRank) ranked += r > 0 ? 1 : 0;
        EXPECT_EQ(ranked + attempt.header.componentCount + attempt.encoded.stats.repeatedFaces +
                      attempt.encoded.stats.looseFaces,
                  m.faceCount());
    }
}

TEST(RankedAttempt, KeepVertexOrderNumbersTheOutputAsTheInput) {
    EncodeOptions o;
    o.threads = 1;
    o.keepVertexOrder = true;
    const drm_test::PreparedSession s(drm_test::icosphere(3), o);
    NumberedMesh numbered;
    numbered.order = mortonOrder(s.prepared.quantized);
    const Progress none;
    ProgressReporter progress(none);
    Attempt attempt = encodeNumbered(s.session(), numbered, s.prepared.quantized, progress);
    for (size_t v = 0; v < attempt.encoded.vertexOrder.size(); ++v) ASSERT_EQ(attempt.encoded.vertexOrder[v], v);
    EXPECT_FALSE(attempt.vertexOrder.empty());  // the section that restores it
}

TEST(RankedAttempt, WriteAttemptWritesAFileReadFileReadsBack) {
    const drm_test::PreparedSession s(drm_test::icosphere(2), EncodeOptions());
    Attempt attempt = rawAttempt(s);
    const std::vector<uint8_t> geometry = attempt.geometry;
    writeAttempt(attempt, GeometryCoder::Raw, geometry);  // again: the same file
    const FileParts parts = readFile(attempt.encoded.bytes.data(), attempt.encoded.bytes.size());
    EXPECT_EQ(parts.header.geometryCoder, GeometryCoder::Raw);
    EXPECT_EQ(std::vector<uint8_t>(parts.geometry, parts.geometry + parts.geometrySize), geometry);
    EXPECT_EQ(std::vector<uint8_t>(parts.connectivity, parts.connectivity + parts.connectivitySize), attempt.connectivity);
    EXPECT_EQ(attempt.encoded.stats.totalBytes, attempt.encoded.bytes.size());
    EXPECT_EQ(attempt.encoded.stats.geometryBytes, geometry.size());
    EXPECT_EQ(attempt.encoded.stats.headerBytes, parts.headerBytes);
}

TEST(RankedAttempt, RepairsInDecodedOrderFollowTheDecodedFaces) {
    PreparedMesh prepared;
    prepared.repairs.flipped = {1, 0, 0, 1};  // per face of the cut
    prepared.repairs.duplicateOf = {3, 0};
    prepared.repairs.duplicateReversed = {0, 1};
    const std::vector<uint32_t> faceOrder = {2, 3, 0, 1};  // decoded face -> face of the cut
    const Repairs r = repairsInDecodedOrder(prepared, {4, 4, 7}, {1, 1, 2}, faceOrder);
    EXPECT_EQ(r.flipped, (std::vector<uint8_t>{0, 1, 1, 0}));
    EXPECT_EQ(r.duplicateOf, (std::vector<uint32_t>{1, 2}));  // cut faces 3 and 0, decoded as 1 and 2
    EXPECT_EQ(r.duplicateReversed, prepared.repairs.duplicateReversed);
    EXPECT_EQ(r.copyOf, (std::vector<uint32_t>{4, 4, 7}));
    EXPECT_EQ(r.looseTriangles, (std::vector<uint32_t>{1, 1, 2}));
}

}  // namespace
}  // namespace drm
