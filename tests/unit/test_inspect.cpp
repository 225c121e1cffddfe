// drm::inspect (inspect.cpp) against what decode() reports for the same
// file: every header field and section size, whichever options wrote it.
#include <gtest/gtest.h>

#include <vector>

#include "drmcodec/drmcodec.h"
#include "test_meshes.h"

namespace {

TEST(Inspect, AgreesWithDecodeOnEveryHeaderField) {
    for (int variant = 0; variant < 4; ++variant) {
        drm::Mesh mesh = drm_test::gridPatch(12, variant % 2 == 1, 0.2, 7);
        drm::EncodeOptions options;
        options.keepVertexOrder = variant == 2;
        options.geometry = variant == 3 ? drm::GeometryCoder::Refine : drm::GeometryCoder::SpanningTree;
        if (variant == 1) mesh.colors.assign(4 * mesh.vertexCount(), 200);
        const drm::Encoded encoded = drm::encode(mesh, options);
        const drm::FileInfo info = drm::inspect(encoded.bytes);
        const drm::Stats& d = drm::decode(encoded.bytes).stats;
        const drm::Stats& i = info.stats;
        EXPECT_EQ(info.formatVersion, drm::kFileFormatVersion);
        EXPECT_EQ(info.keepsVertexOrder, options.keepVertexOrder);
        EXPECT_EQ(i.vertices, d.vertices);
        EXPECT_EQ(i.faces, d.faces);
        EXPECT_EQ(i.components, d.components);
        EXPECT_EQ(i.bits, d.bits);
        EXPECT_EQ(i.predictor, d.predictor);
        EXPECT_EQ(i.geometry, d.geometry);
        EXPECT_EQ(i.refineBits, d.refineBits);
        EXPECT_EQ(drm::leversName(i.levers), drm::leversName(d.levers));
        EXPECT_EQ(i.headerBytes, d.headerBytes);
        EXPECT_EQ(i.connectivityBytes, d.connectivityBytes);
        EXPECT_EQ(i.geometryBytes, d.geometryBytes);
        EXPECT_EQ(i.vertexOrderBytes, d.vertexOrderBytes);
        EXPECT_EQ(i.attributeBytes, d.attributeBytes);
        ASSERT_EQ(i.attributeSizes.size(), d.attributeSizes.size());
        for (size_t s = 0; s < i.attributeSizes.size(); ++s) {
            EXPECT_EQ(i.attributeSizes[s].name, d.attributeSizes[s].name);
            EXPECT_EQ(i.attributeSizes[s].bytes, d.attributeSizes[s].bytes);
        }
        EXPECT_EQ(i.totalBytes, encoded.bytes.size());
        EXPECT_TRUE(i.rankHistogram.empty());
    }
}

}  // namespace
