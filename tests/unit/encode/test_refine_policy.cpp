// GeometryCoder::Auto's choice between the spanning tree and refine
// (encode/refine_policy.h): the attempt it keeps decodes to the mesh, is
// never larger than the tree's own attempt, and is the tree's where the
// tree spends few bits a vertex (refine is not tried there).
#include <gtest/gtest.h>

#include <string>

#include "encode/refine_policy.h"
#include "encode/vertex_section.h"
#include "prepared_session.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

TEST(RefinePolicy, TheKeptAttemptIsNoLargerThanTheTrees) {
    const Progress none;
    for (const char* name : {"bunny-lres.ply", "nefertiti.ply", "mech-holes-shark.ply"}) {
        SCOPED_TRACE(name);
        EncodeOptions o;
        o.threads = 1;
        const drm_test::PreparedSession s(drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name), o);
        ProgressReporter progress(none);
        const Attempt chosen = encodeWithChosenGeometry(s.session(), VertexSection(), nullptr, progress);
        drm_test::expectAttemptDecodes(chosen, s);
        VertexSectionPlan tree;
        const Attempt treeOnly = encodeWithGeometry(s.session(), tree, progress);
        EXPECT_LE(chosen.encoded.bytes.size(), treeOnly.encoded.bytes.size());
        const GeometryCoder kept = chosen.header.geometryCoder;
        EXPECT_TRUE(kept == GeometryCoder::SpanningTree || kept == GeometryCoder::Refine || kept == GeometryCoder::Sorted ||
                    kept == GeometryCoder::Raw);
        // Refine only where the tree spends many bits a vertex.
        const double treeBitsPerVertex = 8.0 * double(treeOnly.geometry.size()) / double(s.mesh.vertexCount());
        if (treeBitsPerVertex <= kAutoRefineAboveBitsPerVertex)
            EXPECT_NE(kept, GeometryCoder::Refine) << treeBitsPerVertex << " bits a vertex";
    }
}

TEST(RefinePolicy, ASectionCodedAlreadyIsUsed) {
    EncodeOptions o;
    o.threads = 1;
    const drm_test::PreparedSession s(drm_test::icosphere(3), o);
    VertexSection section = codeVertexSection(s.prepared.quantized, o, GeometryCoder::SpanningTree, 0, nullptr, 1);
    const std::vector<uint8_t> bytes = section.encoding.bytes;
    const Progress none;
    ProgressReporter progress(none);
    const Attempt chosen = encodeWithChosenGeometry(s.session(), std::move(section), nullptr, progress);
    drm_test::expectAttemptDecodes(chosen, s);
    if (chosen.header.geometryCoder == GeometryCoder::SpanningTree) EXPECT_EQ(chosen.geometry, bytes);
}

}  // namespace
}  // namespace drm
