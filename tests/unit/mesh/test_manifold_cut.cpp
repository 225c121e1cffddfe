// The manifold cut (mesh/manifold_cut.h) against its promises, on meshes
// with every defect it handles (tests/data, the repairs test mesh, and
// small hand-made cases): the kept faces form a mesh the traversal can
// code as it is; every input face is kept (as itself, copies mapped back
// and turned back over), repeated (named with the kept face it repeats and
// whether it runs the other way) or set aside whole (it repeats a vertex),
// exactly once; and a mesh that needs nothing is left as it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "mesh/manifold_cut.h"
#include "mesh/mesh_check.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

std::array<uint32_t, 3> rotatedToSmallest(uint32_t a, uint32_t b, uint32_t c) {
    std::array<uint32_t, 3> t = {a, b, c};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

void expectCutKeepsItsPromises(const std::vector<uint32_t>& input, size_t vertexCount) {
    const ManifoldCut cut = cutIntoManifold(input, vertexCount);
    const size_t inputFaces = input.size() / 3, kept = cut.triangles.size() / 3;
    const size_t total = vertexCount + cut.copyOf.size();
    // A mesh the traversal takes as it is.
    MeshTopology topology;
    EXPECT_EQ(topologyProblem(cut.triangles, total, &topology), "");
    for (uint32_t c : cut.copyOf) ASSERT_LT(c, vertexCount);
    ASSERT_EQ(cut.inputFace.size(), kept);
    ASSERT_EQ(cut.flipped.size(), kept);
    EXPECT_EQ(cut.flippedCount, size_t(std::count(cut.flipped.begin(), cut.flipped.end(), 1)));
    std::vector<int> accounted(inputFaces, 0);
    auto original = [&](uint32_t v) { return v < vertexCount ? v : cut.copyOf[v - vertexCount]; };
    std::vector<std::array<uint32_t, 3>> keptInInput(kept);
    for (size_t f = 0; f < kept; ++f) {
        uint32_t a = original(cut.triangles[3 * f]), b = original(cut.triangles[3 * f + 1]),
                 c = original(cut.triangles[3 * f + 2]);
        if (cut.flipped[f]) std::swap(b, c);
        const uint32_t g = cut.inputFace[f];
        ASSERT_LT(g, inputFaces);
        if (f > 0) ASSERT_LT(cut.inputFace[f - 1], g) << "kept faces in input order";
        EXPECT_EQ(rotatedToSmallest(a, b, c), rotatedToSmallest(input[3 * g], input[3 * g + 1], input[3 * g + 2]))
            << "kept face " << f;
        keptInInput[f] = {a, b, c};
        ++accounted[g];
    }
    ASSERT_EQ(cut.looseTriangles.size(), 3 * cut.looseInputFace.size());
    for (size_t i = 0; i < cut.looseInputFace.size(); ++i) {
        const uint32_t g = cut.looseInputFace[i];
        const uint32_t* t = &cut.looseTriangles[3 * i];
        EXPECT_TRUE(std::equal(t, t + 3, &input[3 * g])) << "set aside verbatim";
        EXPECT_TRUE(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) << "repeats a vertex";
        ++accounted[g];
    }
    ASSERT_EQ(cut.duplicateOf.size(), cut.duplicateInputFace.size());
    ASSERT_EQ(cut.duplicateReversed.size(), cut.duplicateInputFace.size());
    for (size_t i = 0; i < cut.duplicateInputFace.size(); ++i) {
        const uint32_t g = cut.duplicateInputFace[i], f = cut.duplicateOf[i];
        ASSERT_LT(f, kept);
        std::array<uint32_t, 3> repeated = keptInInput[f];
        if (cut.duplicateReversed[i]) std::swap(repeated[1], repeated[2]);
        EXPECT_EQ(rotatedToSmallest(repeated[0], repeated[1], repeated[2]),
                  rotatedToSmallest(input[3 * g], input[3 * g + 1], input[3 * g + 2]))
            << "repeated face " << i;
        ++accounted[g];
    }
    for (size_t g = 0; g < inputFaces; ++g) ASSERT_EQ(accounted[g], 1) << "input face " << g;
}

TEST(ManifoldCut, AMeshNeedingNothingIsLeftAsItIs) {
    for (const Mesh& m : {drm_test::icosphere(2), drm_test::gridPatch(8, true), drm_test::mixedMesh()}) {
        const ManifoldCut cut = cutIntoManifold(m.triangles, m.vertexCount());
        EXPECT_TRUE(cut.isIdentity());
        EXPECT_EQ(cut.triangles, m.triangles);
        for (size_t f = 0; f < cut.inputFace.size(); ++f) EXPECT_EQ(cut.inputFace[f], f);
        expectCutKeepsItsPromises(m.triangles, m.vertexCount());
    }
}

TEST(ManifoldCut, EachDefectIsRepairedItsOwnWay) {
    // Two triangles sharing the edge 1-2 in the same direction: the second
    // is turned over.
    {
        const std::vector<uint32_t> t = {0, 1, 2, 3, 1, 2};
        const ManifoldCut cut = cutIntoManifold(t, 4);
        EXPECT_EQ(cut.flippedCount, 1u);
        EXPECT_EQ(cut.flipped, (std::vector<uint8_t>{0, 1}));
        EXPECT_TRUE(cut.copyOf.empty());
        expectCutKeepsItsPromises(t, 4);
    }
    // A bowtie: two fans at vertex 0, the second gets a copy of it.
    {
        const std::vector<uint32_t> t = {0, 1, 2, 0, 3, 4};
        const ManifoldCut cut = cutIntoManifold(t, 5);
        EXPECT_EQ(cut.copyOf, std::vector<uint32_t>{0});
        EXPECT_EQ(cut.flippedCount, 0u);
        expectCutKeepsItsPromises(t, 5);
    }
    // A fin: three faces on the edge 0-1.
    {
        const std::vector<uint32_t> t = {0, 1, 2, 1, 0, 3, 0, 1, 4};
        const ManifoldCut cut = cutIntoManifold(t, 5);
        EXPECT_FALSE(cut.copyOf.empty());
        expectCutKeepsItsPromises(t, 5);
    }
    // A face repeating a vertex is set aside; a doubled face repeats one.
    {
        const std::vector<uint32_t> t = {0, 1, 2, 2, 1, 3, 1, 1, 3, 0, 1, 2, 2, 3, 1};
        const ManifoldCut cut = cutIntoManifold(t, 4);
        EXPECT_EQ(cut.looseInputFace, std::vector<uint32_t>{2});
        ASSERT_EQ(cut.duplicateInputFace, (std::vector<uint32_t>{3, 4}));
        EXPECT_EQ(cut.duplicateOf, (std::vector<uint32_t>{0, 1}));
        EXPECT_EQ(cut.duplicateReversed, (std::vector<uint8_t>{0, 1}));
        expectCutKeepsItsPromises(t, 4);
    }
    // A Moebius strip: no orientation fits every face, a join is cut.
    {
        std::vector<uint32_t> t;
        const uint32_t n = 6;  // quads around the strip, vertices i (top) and n + i (bottom)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = i, b = n + i;
            uint32_t c = i + 1, d = n + i + 1;
            if (i + 1 == n) c = n, d = 0;  // the half twist: top meets bottom
            t.insert(t.end(), {a, b, d, a, d, c});
        }
        const ManifoldCut cut = cutIntoManifold(t, 2 * n);
        EXPECT_FALSE(cut.isIdentity());
        expectCutKeepsItsPromises(t, 2 * n);
    }
}

TEST(ManifoldCut, MeshesWithEveryDefect) {
    const Mesh repairs = drm_test::meshNeedingRepairs();
    expectCutKeepsItsPromises(repairs.triangles, repairs.vertexCount());
    EXPECT_FALSE(cutIntoManifold(repairs.triangles, repairs.vertexCount()).isIdentity());
    for (const char* name : {"fins-and-bowtie.ply", "soup.ply", "star-cgal.ply", "blobby-3cc.ply"}) {
        SCOPED_TRACE(name);
        const Mesh m = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name);
        expectCutKeepsItsPromises(m.triangles, m.vertexCount());
    }
}

}  // namespace
}  // namespace drm
