// One stream of distance ranks (encode/rank_stream.h) over a numbered
// mesh: the traversal reaches every face, one component start each, and
// codes T + B - C ranks (T faces, B boundary edges, C components: a rank
// per face but the start triangles, and a rank 0 per boundary edge); the
// faces it rebuilds are the mesh's oriented triangles; every face but a
// start triangle gets its rank; and wherever the components start, the
// same faces come out.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "encode/rank_stream.h"
#include "prepared_session.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

// Boundary edges: directed edges whose twin no face holds.
uint64_t boundaryEdges(const NumberedMesh& n) {
    uint64_t b = 0;
    for (size_t f = 0; f < n.triangles.size() / 3; ++f)
        for (int k = 0; k < 3; ++k)
            b += n.topology.faceOf(n.triangles[3 * f + (k + 1) % 3], n.triangles[3 * f + k]) == kNoIndex ? 1 : 0;
    return b;
}

TEST(RankStream, SmallestVertexOfAFace) {
    const std::vector<uint32_t> t = {5, 2, 9, 7, 8, 3};
    EXPECT_EQ(smallestVertex(t, 0), 2u);
    EXPECT_EQ(smallestVertex(t, 1), 3u);
}

TEST(RankStream, AWholeMeshCodesTPlusBMinusCRanks) {
    const Progress none;
    struct Case {
        const char* name;
        Mesh mesh;
        uint64_t components;
    };
    const Case cases[] = {
        {"icosphere", drm_test::icosphere(3), 1},
        {"mixed", drm_test::mixedMesh(), 2},  // a patch with a hole and a tetrahedron
        {"bunny", drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"), 0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EncodeOptions o;
        const drm_test::PreparedSession s(c.mesh, o);
        ASSERT_FALSE(s.prepared.repaired);
        NumberedMesh numbered;
        drm_test::numberInInputOrder(s, numbered, false);
        for (ComponentStarts::Order order : {ComponentStarts::Order::SmallestVertices, ComponentStarts::Order::InputFaces}) {
            RankStreamFaces whole;
            whole.grid = &numbered.decodedGrid;
            whole.faceCount = numbered.triangles.size() / 3;
            ComponentStarts starts;
            starts.order = order;
            Encoded result;
            result.faceRank.assign(c.mesh.faceCount(), 0);
            ProgressReporter progress(none);
            const CodedRanks coded = codeRanks(whole, s.session(), numbered, Levers(), starts, result, progress, 0, 1);
            EXPECT_TRUE(coded.complete);
            EXPECT_FALSE(coded.bytes.empty());
            if (c.components) EXPECT_EQ(coded.components, c.components);
            const uint64_t T = c.mesh.faceCount(), B = boundaryEdges(numbered), C = coded.components;
            const uint64_t codes = std::accumulate(result.stats.rankHistogram.begin(), result.stats.rankHistogram.end(), uint64_t(0));
            EXPECT_EQ(codes, T + B - C);
            EXPECT_EQ(result.stats.rankHistogram[0], B);
            EXPECT_EQ(drm_test::orientedFaces(coded.triangles), drm_test::orientedFaces(numbered.triangles));
            uint64_t ranked = 0;
            for (uint32_t r : result.faceRank) ranked += r > 0 ? 1 : 0;
            EXPECT_EQ(ranked, T - C);
        }
    }
}

}  // namespace
}  // namespace drm
