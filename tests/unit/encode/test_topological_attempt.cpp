// The topological coder's attempt (encode/topological_attempt.h): hubs are
// found where the faces at each vertex, squared and summed, pass the floor
// (a fan around one vertex, not an ordinary mesh); the attempt's file
// decodes to the mesh, repairs and a kept vertex order included, with no
// ranks; and a rival file too small to beat makes it give up.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

#include "encode/topological_attempt.h"
#include "prepared_session.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

TEST(TopologicalAttempt, HubsAreVerticesOfVeryManyFaces) {
    EXPECT_TRUE(hasHubs(drm_test::fan(3000)));
    EXPECT_FALSE(hasHubs(drm_test::fan(40)));
    EXPECT_FALSE(hasHubs(drm_test::icosphere(4)));
    EXPECT_FALSE(hasHubs(drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply")));
}

TEST(TopologicalAttempt, ItsFileDecodesToTheMesh) {
    const Progress none;
    for (bool keepOrder : {false, true})
        for (const Mesh& m : {drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"),
                              drm_test::meshNeedingRepairs(), drm_test::mixedMesh()}) {
            EncodeOptions o;
            o.keepVertexOrder = keepOrder;
            const drm_test::PreparedSession s(m, o);
            ProgressReporter progress(none);
            const std::optional<Attempt> attempt = encodeTopologically(s.session(), true, kNoRivalFile, progress);
            ASSERT_TRUE(attempt.has_value());
            EXPECT_EQ(attempt->header.connectivityCoder, ConnectivityCoder::Topological);
            EXPECT_EQ(attempt->header.hasRepairs, s.prepared.repaired);
            EXPECT_EQ(attempt->encoded.faceRank, std::vector<uint32_t>(m.faceCount(), 0));  // no ranks
            drm_test::expectAttemptDecodes(*attempt, s);
            if (keepOrder)
                for (size_t v = 0; v < attempt->encoded.vertexOrder.size(); ++v)
                    ASSERT_EQ(attempt->encoded.vertexOrder[v], v);
        }
}

TEST(TopologicalAttempt, ARivalTooSmallToBeatMakesItGiveUp) {
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    const drm_test::PreparedSession s(bunny, EncodeOptions());
    const Progress none;
    ProgressReporter progress(none);
    EXPECT_FALSE(encodeTopologically(s.session(), false, 100, progress).has_value());
    const std::optional<Attempt> unbounded = encodeTopologically(s.session(), false, 0, progress);
    ASSERT_TRUE(unbounded.has_value());
    EXPECT_GT(unbounded->encoded.bytes.size(), 100u);
}

}  // namespace
}  // namespace drm
