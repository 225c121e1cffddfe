// drm::Stats reports the repairs a mesh needed: none at all, and no bytes
// for them, on a clean mesh; vertex copies for non-manifold pieces, flip
// bits for turned-over faces, references for faces over an earlier face's
// vertices, loose faces for faces repeating a vertex. Decoded, repeated
// faces and then loose faces come after the traversal's faces, each group
// in input order (drmcodec.h).
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "adversarial_meshes.h"
#include "adversarial_options.h"
#include "mesh_compare.h"
#include "mesh_defects.h"

namespace adversarial {
namespace {

uint64_t repairCount(const drm::Stats& s) { return s.splitVertices + s.flippedFaces + s.repeatedFaces + s.looseFaces; }

// Canonical faces of the mesh, in input order: those over an earlier face's
// three vertices, and those repeating a vertex.
struct SetAsideFaces {
    std::vector<Triangle> repeated, loose;
};

SetAsideFaces setAsideFaces(const drm::Mesh& mesh) {
    SetAsideFaces faces;
    std::set<Triangle> vertexSets;
    for (size_t c = 0; c < mesh.triangles.size(); c += 3) {
        const Triangle t = {mesh.triangles[c], mesh.triangles[c + 1], mesh.triangles[c + 2]};
        if (repeatsAnIndex(t[0], t[1], t[2])) {
            faces.loose.push_back(canonicalTriangle(t));
            continue;
        }
        Triangle set = t;
        std::sort(set.begin(), set.end());
        if (!vertexSets.insert(set).second) faces.repeated.push_back(canonicalTriangle(t));
    }
    return faces;
}

class RepairStats : public ::testing::TestWithParam<std::tuple<size_t, size_t>> {
protected:
    void SetUp() override {
        encoded_ = drm::encode(mesh().mesh, adversarialOptions()[std::get<1>(GetParam())].options);
        decoded_ = drm::decode(encoded_.bytes);
    }
    const AdversarialMesh& mesh() const { return adversarialMeshes()[std::get<0>(GetParam())]; }

    drm::Encoded encoded_;
    drm::Decoded decoded_;
};

TEST_P(RepairStats, CountsTheRepairsTheMeshNeeds) {
    const drm::Stats& s = encoded_.stats;
    const drm::Stats& d = decoded_.stats;
    EXPECT_EQ(d.repairBytes, s.repairBytes) << "the decoder measures another repairs section";
    EXPECT_EQ(d.splitVertices, s.splitVertices);
    EXPECT_EQ(d.flippedFaces, s.flippedFaces);
    EXPECT_EQ(d.repeatedFaces, s.repeatedFaces);
    EXPECT_EQ(d.looseFaces, s.looseFaces);

    const MeshDefects defects = findDefects(mesh().mesh);
    EXPECT_EQ(s.looseFaces, defects.facesRepeatingAnIndex) << "every face repeating a vertex, and only those";
    EXPECT_LE(s.repeatedFaces, defects.facesOverAnEarlierFacesVertices)
        << "only faces over an earlier face's vertices are repeated faces";
    EXPECT_LE(s.flippedFaces, mesh().mesh.faceCount());
    EXPECT_EQ(s.repairBytes == 0, repairCount(s) == 0)
        << "repairBytes " << s.repairBytes << " with " << repairCount(s) << " repairs";

    switch (mesh().repair) {
    case Repair::None:
        EXPECT_EQ(s.repairBytes, 0u) << "a clean mesh must cost nothing extra";
        EXPECT_EQ(s.splitVertices, 0u);
        EXPECT_EQ(s.flippedFaces, 0u);
        EXPECT_EQ(s.repeatedFaces, 0u);
        EXPECT_EQ(s.looseFaces, 0u);
        break;
    case Repair::SplitVertices:
        EXPECT_GE(s.splitVertices, 1u);
        EXPECT_GT(s.repairBytes, 0u);
        break;
    case Repair::FlipFaces:
        EXPECT_GE(s.flippedFaces, 1u);
        EXPECT_GT(s.repairBytes, 0u);
        break;
    case Repair::RepeatedFaces:
        EXPECT_GE(s.repeatedFaces, 1u);
        EXPECT_GT(s.repairBytes, 0u);
        break;
    case Repair::LooseFaces:
        EXPECT_GE(s.looseFaces, 1u);
        EXPECT_GT(s.repairBytes, 0u);
        break;
    case Repair::Some:
        EXPECT_GE(repairCount(s), 1u);
        EXPECT_GT(s.repairBytes, 0u);
        break;
    }
}

// Decoded, the loose faces come last in input order, the repeated faces
// before them. Which duplicates are coded as repeated faces is the codec's
// choice; when it takes them all, they too must come in input order.
TEST_P(RepairStats, DecodesRepeatedAndLooseFacesLast) {
    const SetAsideFaces input = setAsideFaces(mesh().mesh);
    std::vector<Triangle> expected = input.loose;
    if (decoded_.stats.repeatedFaces == input.repeated.size())
        expected.insert(expected.begin(), input.repeated.begin(), input.repeated.end());
    const std::vector<uint32_t>& t = decoded_.mesh.triangles;
    const std::vector<uint32_t>& order = encoded_.vertexOrder;
    ASSERT_EQ(order.size(), decoded_.mesh.vertexCount());
    ASSERT_LE(expected.size(), t.size() / 3);
    const size_t first = t.size() / 3 - expected.size();
    for (size_t i = 0; i < expected.size(); ++i) {
        const size_t c = 3 * (first + i);
        ASSERT_TRUE(t[c] < order.size() && t[c + 1] < order.size() && t[c + 2] < order.size());
        const Triangle decoded = canonicalTriangle({order[t[c]], order[t[c + 1]], order[t[c + 2]]});
        EXPECT_EQ(decoded, expected[i]) << "decoded face " << first + i << " of the last " << expected.size();
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, RepairStats,
                         ::testing::Combine(::testing::Range<size_t>(0, adversarialMeshes().size()),
                                            ::testing::Range<size_t>(0, adversarialOptions().size())),
                         [](const ::testing::TestParamInfo<std::tuple<size_t, size_t>>& info) {
                             return adversarialMeshes()[std::get<0>(info.param)].name + "__" +
                                    adversarialOptions()[std::get<1>(info.param)].name;
                         });

// The repair each mesh declares is the one its defects call for, as
// findDefects counts them (which the corpus test relies on).
class DeclaredRepair : public ::testing::TestWithParam<size_t> {};

TEST_P(DeclaredRepair, MatchesTheMeshDefects) {
    const AdversarialMesh& m = adversarialMeshes()[GetParam()];
    const MeshDefects defects = findDefects(m.mesh);
    switch (m.repair) {
    case Repair::None:
        EXPECT_FALSE(defects.any()) << defects.describe();
        break;
    case Repair::SplitVertices:
        EXPECT_GT(defects.edgesWithMoreThanTwoFaces + defects.verticesWithSeveralFans, 0u) << defects.describe();
        break;
    case Repair::FlipFaces:
        EXPECT_GT(defects.edgesWithSameDirectionFaces, 0u) << defects.describe();
        break;
    case Repair::RepeatedFaces:
        EXPECT_GT(defects.facesOverAnEarlierFacesVertices, 0u) << defects.describe();
        break;
    case Repair::LooseFaces:
        EXPECT_GT(defects.facesRepeatingAnIndex, 0u) << defects.describe();
        break;
    case Repair::Some:
        EXPECT_TRUE(defects.any()) << defects.describe();
        break;
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, DeclaredRepair, ::testing::Range<size_t>(0, adversarialMeshes().size()),
                         [](const ::testing::TestParamInfo<size_t>& info) { return adversarialMeshes()[info.param].name; });

}  // namespace
}  // namespace adversarial
