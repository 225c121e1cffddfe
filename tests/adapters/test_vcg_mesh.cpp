// toVcg/fromVcg keep order, and fromVcg leaves out what MeshLab deleted.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/rank_palette.h>
#include <drm_vcg/vcg_mesh.h>

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace {

drm::Mesh square() {
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 9, 9, 9};
    mesh.triangles = {0, 1, 2, 0, 2, 3};
    return mesh;
}

TEST(VcgMesh, RoundTripKeepsVerticesFacesAndCorners) {
    drm::vcgio::VcgMesh vcgMesh;
    drm::vcgio::toVcg(square(), vcgMesh);
    EXPECT_EQ(vcgMesh.vn, 5);
    EXPECT_EQ(vcgMesh.fn, 2);
    const drm::Mesh back = drm::vcgio::fromVcg(vcgMesh);
    EXPECT_EQ(back.positions, square().positions);
    EXPECT_EQ(back.triangles, square().triangles);
}

TEST(VcgMesh, FromVcgSkipsDeletedElementsAndRenumbers) {
    drm::vcgio::VcgMesh vcgMesh;
    drm::vcgio::toVcg(square(), vcgMesh);
    vcg::tri::Allocator<drm::vcgio::VcgMesh>::DeleteFace(vcgMesh, vcgMesh.face[0]);
    vcg::tri::Allocator<drm::vcgio::VcgMesh>::DeleteVertex(vcgMesh, vcgMesh.vert[1]);
    const drm::Mesh back = drm::vcgio::fromVcg(vcgMesh);
    EXPECT_EQ(back.vertexCount(), 4u);
    EXPECT_EQ(back.triangles, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(back.positions[3], 1.0f);  // old vertex 2 is now vertex 1
    EXPECT_EQ(back.positions[4], 1.0f);
}

TEST(VcgMesh, FromVcgRefusesFacesOnDeletedVertices) {
    drm::vcgio::VcgMesh vcgMesh;
    drm::vcgio::toVcg(square(), vcgMesh);
    vcg::tri::Allocator<drm::vcgio::VcgMesh>::DeleteVertex(vcgMesh, vcgMesh.vert[1]);
    EXPECT_THROW(drm::vcgio::fromVcg(vcgMesh), drm::Error);
}

TEST(VcgMesh, ToVcgRefusesIndicesOutOfRange) {
    drm::Mesh mesh = square();
    mesh.triangles.back() = 5;
    drm::vcgio::VcgMesh vcgMesh;
    EXPECT_THROW(drm::vcgio::toVcg(mesh, vcgMesh), drm::Error);
}

TEST(RankPalette, BucketsAreDistinctAndNamed) {
    EXPECT_EQ(drm::vcgio::rankBucket(0), 0);
    EXPECT_EQ(drm::vcgio::rankBucket(3), 3);
    EXPECT_EQ(drm::vcgio::rankBucket(4), 4);
    EXPECT_EQ(drm::vcgio::rankBucket(1000), 4);
    std::set<std::tuple<int, int, int>> colours;
    std::set<std::string> names;
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket) {
        const drm::vcgio::RankColour c = drm::vcgio::rankBucketColour(bucket);
        colours.insert(std::make_tuple(c.r, c.g, c.b));
        names.insert(drm::vcgio::rankBucketName(bucket));
    }
    EXPECT_EQ(colours.size(), size_t(drm::vcgio::kRankBucketCount));
    EXPECT_EQ(names.size(), size_t(drm::vcgio::kRankBucketCount));
    EXPECT_EQ(std::string(drm::vcgio::rankBucketName(4)), "rank 4+");
}

TEST(RankPalette, BucketsAreClampedAndRanksBucketed) {
    EXPECT_EQ(&drm::vcgio::rankPaletteEntry(-3), &drm::vcgio::rankPaletteEntry(0));
    EXPECT_EQ(&drm::vcgio::rankPaletteEntry(drm::vcgio::kRankBucketCount + 7), &drm::vcgio::rankPaletteEntry(drm::vcgio::kRankBucketCount - 1));
    std::set<std::string> labels;
    for (int b = 0; b < drm::vcgio::kRankBucketCount; ++b) EXPECT_TRUE(labels.insert(drm::vcgio::rankPaletteEntry(b).label).second);
    EXPECT_EQ(drm::vcgio::rankBucket(0), 0);
    EXPECT_EQ(drm::vcgio::rankBucket(3), 3);
    EXPECT_EQ(drm::vcgio::rankBucket(4), 4);
    EXPECT_EQ(drm::vcgio::rankBucket(4000000000u), 4);
}

}  // namespace
