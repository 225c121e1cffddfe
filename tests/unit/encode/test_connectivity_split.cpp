// Where a numbered mesh splits into format 11's two connectivity parts
// (encode/connectivity_split.h): a split is asked for or chosen by size;
// the split leaves 45 to 55 % of the faces in part 1 where any index does
// (faces go by their smallest vertex), hands part 2 its own vertices'
// points, and keeps in part 2 exactly the vertices whose part 2 faces form
// more than one fan; the two rank streams then code every face once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "connectivity/connectivity_parts.h"
#include "encode/connectivity_split.h"
#include "encode/rank_stream.h"
#include "prepared_session.h"
#include "spatial/morton_order.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

Mesh bunny() { return drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"); }

TEST(ConnectivitySplit, AskedForOrChosenBySize) {
    const drm_test::PreparedSession s(bunny(), EncodeOptions());
    NumberedMesh morton;
    drm_test::numberInInputOrder(s, morton, true);
    EncodeOptions o;
    o.connectivityParts = 2;
    EXPECT_TRUE(maySplitConnectivity(morton, o));
    o.connectivityParts = 1;
    EXPECT_FALSE(maySplitConnectivity(morton, o));
    o.connectivityParts = 0;  // by size: bunny is below the size that splits
    EXPECT_EQ(maySplitConnectivity(morton, o), morton.triangles.size() / 3 >= kTwoPartsFromFaces);
    NumberedMesh section;
    drm_test::numberInInputOrder(s, section, false);
    EXPECT_FALSE(maySplitConnectivity(section, o)) << "only a mesh numbered in Morton order splits by size";
    NumberedMesh empty;
    o.connectivityParts = 2;
    EXPECT_FALSE(maySplitConnectivity(empty, o));
}

TEST(ConnectivitySplit, TheSplitAndPartTwosVertices) {
    const drm_test::PreparedSession s(bunny(), EncodeOptions());
    NumberedMesh numbered;
    numbered.order = mortonOrder(s.prepared.quantized);  // vertices near in space are near in number
    numbered.mortonNumbering = true;
    numbered.decodedGrid.resize(s.prepared.quantized.size());
    std::vector<uint32_t> decodedOf(numbered.order.size());
    for (size_t d = 0; d < numbered.order.size(); ++d) {
        decodedOf[numbered.order[d]] = uint32_t(d);
        for (int k = 0; k < 3; ++k) numbered.decodedGrid[3 * d + k] = s.prepared.quantized[3 * size_t(numbered.order[d]) + k];
    }
    numbered.triangles = s.mesh.triangles;
    for (uint32_t& v : numbered.triangles) v = decodedOf[v];
    numbered.vertexCount = numbered.order.size();
    buildTopology(numbered.triangles, numbered.vertexCount, &numbered.topology);
    SplitFaces parts;
    ASSERT_TRUE(splitFaces(numbered, true, parts));
    const size_t faces = numbered.triangles.size() / 3;
    size_t below = 0;
    for (size_t f = 0; f < faces; ++f) below += smallestVertex(numbered.triangles, uint32_t(f)) < parts.split ? 1 : 0;
    EXPECT_EQ(parts.firstFaces, below);
    EXPECT_GE(double(below), 0.45 * double(faces));
    EXPECT_LE(double(below), 0.55 * double(faces));
    EXPECT_EQ(parts.secondGrid,
              std::vector<int32_t>(numbered.decodedGrid.begin() + 3 * size_t(parts.split), numbered.decodedGrid.end()));
    // Kept: part 2 vertices with two open fans or more in part 2's faces,
    // counted here by the faces around each vertex joined across edges.
    auto inSecond = [&](uint32_t f) { return f != kNoIndex && smallestVertex(numbered.triangles, f) >= parts.split; };
    std::vector<uint32_t> kept;
    for (uint32_t v = parts.split; v < numbered.vertexCount; ++v) {
        std::vector<uint32_t> around;
        for (uint32_t e = numbered.topology.start[v]; e < numbered.topology.start[v + 1]; ++e)
            if (inSecond(numbered.topology.out[e].face)) around.push_back(numbered.topology.out[e].face);
        // Fans: union the faces at v that share an edge at v.
        std::vector<uint32_t> fan(around.size());
        std::iota(fan.begin(), fan.end(), 0u);
        std::function<uint32_t(uint32_t)> root = [&](uint32_t i) { return fan[i] == i ? i : fan[i] = root(fan[i]); };
        for (size_t i = 0; i < around.size(); ++i)
            for (size_t j = 0; j < around.size(); ++j) {
                int shared = 0;
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        shared += numbered.triangles[3 * around[i] + a] == numbered.triangles[3 * around[j] + b] ? 1 : 0;
                if (i != j && shared == 2) fan[root(uint32_t(i))] = root(uint32_t(j));
            }
        size_t fans = 0;
        for (size_t i = 0; i < around.size(); ++i) fans += root(uint32_t(i)) == i ? 1 : 0;
        if (fans >= 2) kept.push_back(v - parts.split);
    }
    EXPECT_EQ(parts.keptInSecond, kept);
}

}  // namespace
}  // namespace drm
