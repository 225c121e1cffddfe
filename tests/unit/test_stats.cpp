// stats.h, the one builder of Stats for the encoder, the decoder and
// inspect(): every figure the header and section table give lands in its
// field (checked field by field on a hand-made FileParts, and on a real
// file against the sizes of its sections), and the figures of the
// traversal are counted from the histogram and the repairs.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "container/file_format.h"
#include "drmcodec/drmcodec.h"
#include "mesh/repair_section.h"
#include "stats.h"
#include "test_meshes.h"

namespace drm {
namespace {

TEST(Stats, FromHeaderTakesEveryFieldWhereItBelongs) {
    FileParts parts;
    FileHeader& h = parts.header;
    h.vertexCount = 1001;
    h.faceCount = 1998;
    h.componentCount = 3;
    h.grid.bits = 14;
    h.predictor = Predictor::Parallelogram;
    h.curvature = true;
    h.levers = Levers::none();
    h.levers.gapClosing = true;
    h.geometryCoder = GeometryCoder::Refine;
    h.connectivityCoder = ConnectivityCoder::Topological;
    h.mortonNumbering = false;
    h.twoParts = true;
    h.copyCount = 7;
    parts.headerBytes = 61;
    parts.connectivitySize = 400;
    parts.geometrySize = 1500;
    parts.vertexOrderSize = 20;
    parts.repairsSize = 9;
    parts.attributeBytes = 77;
    parts.attributes.push_back({nullptr, 70});
    Stats s;
    fillStatsFromHeader(s, parts, 2067);
    EXPECT_EQ(s.vertices, 1001u);
    EXPECT_EQ(s.faces, 1998u);
    EXPECT_EQ(s.components, 3u);
    EXPECT_EQ(s.bits, 14);
    EXPECT_EQ(s.predictor, Predictor::Parallelogram);
    EXPECT_TRUE(s.curvature);
    EXPECT_EQ(leversName(s.levers), "gap");
    EXPECT_EQ(s.geometry, GeometryCoder::Refine);
    EXPECT_EQ(s.connectivity, ConnectivityCoder::Topological);
    EXPECT_FALSE(s.mortonNumbering);
    EXPECT_EQ(s.connectivityParts, 2);
    EXPECT_EQ(s.headerBytes, 61u);
    EXPECT_EQ(s.connectivityBytes, 400u);
    EXPECT_EQ(s.geometryBytes, 1500u);
    EXPECT_EQ(s.vertexOrderBytes, 20u);
    EXPECT_EQ(s.repairBytes, 9u);
    EXPECT_EQ(s.splitVertices, 7u);
    EXPECT_EQ(s.attributeBytes, 77u);
    EXPECT_EQ(s.totalBytes, 2067u);
    // Without attribute sections their bytes count nothing, whatever the
    // framing figure says.
    parts.attributes.clear();
    h.twoParts = false;
    fillStatsFromHeader(s, parts, 2067);
    EXPECT_EQ(s.attributeBytes, 0u);
    EXPECT_EQ(s.connectivityParts, 1);
}

TEST(Stats, FromHeaderOfARealFileAddsUpToTheFile) {
    drm::Mesh mesh = drm_test::gridPatch(10, false, 0.2, 5);
    mesh.colors.assign(4 * mesh.vertexCount(), 99);
    EncodeOptions options;
    options.keepVertexOrder = true;
    const Encoded encoded = encode(mesh, options);
    const FileParts parts = readFile(encoded.bytes.data(), encoded.bytes.size());
    Stats s;
    fillStatsFromHeader(s, parts, encoded.bytes.size());
    EXPECT_EQ(s.vertices, mesh.vertexCount());
    EXPECT_EQ(s.faces, mesh.faceCount());
    EXPECT_EQ(s.connectivityBytes, parts.connectivitySize);
    EXPECT_EQ(s.geometryBytes, parts.geometrySize);
    EXPECT_GT(s.vertexOrderBytes, 0u);
    EXPECT_GT(s.attributeBytes, 0u);
    EXPECT_EQ(s.headerBytes + s.connectivityBytes + s.geometryBytes + s.vertexOrderBytes + s.repairBytes +
                  s.attributeBytes,
              s.totalBytes);
    EXPECT_EQ(s.totalBytes, encoded.bytes.size());
    // The encoder's own figures are this builder's.
    EXPECT_EQ(s.headerBytes, encoded.stats.headerBytes);
    EXPECT_EQ(s.attributeBytes, encoded.stats.attributeBytes);
}

TEST(Stats, FromTraversalCountsBoundariesAndRepairs) {
    Stats s;
    Repairs none;
    fillStatsFromTraversal(s, 0, none);  // no histogram: no boundary edges
    EXPECT_EQ(s.boundaryEdges, 0u);
    EXPECT_EQ(s.flippedFaces, 0u);
    EXPECT_EQ(s.repeatedFaces, 0u);
    EXPECT_EQ(s.looseFaces, 0u);
    s.rankHistogram = {12, 500, 40, 3};
    Repairs repairs;
    repairs.flipped = {0, 1, 1, 0, 1};
    repairs.duplicateOf = {4, 2};
    repairs.duplicateReversed = {0, 1};
    repairs.looseTriangles = {0, 0, 1, 2, 3, 3, 5, 5, 5};
    fillStatsFromTraversal(s, 3, repairs);
    EXPECT_EQ(s.boundaryEdges, 12u);  // rank 0 is the boundary code
    EXPECT_EQ(s.refineBits, 3);
    EXPECT_EQ(s.flippedFaces, 3u);
    EXPECT_EQ(s.repeatedFaces, 2u);
    EXPECT_EQ(s.looseFaces, 3u);
}

}  // namespace
}  // namespace drm
