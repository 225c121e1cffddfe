// Either spatial index gives the same file and the same decoded mesh, byte
// for byte: each mesh is encoded with the grid and with FLANN's kd-tree (the
// rank search, size correction and curvature searches of the traversal and
// the geometry tree's neighbour graph all switch), the two files compared,
// and the file decoded with each index, the two meshes compared.
//
// The small meshes run under every option set; tests/data's meshes under a
// few; the shared corpus (../shared/meshes beside the project, 64 meshes,
// with the default options, one ctest test per mesh. Without the corpus
// those are skipped. crank and cycloidal take about 10 s together and check
// the grid's hierarchy of cells (the size step's wide balls: FLANN's index
// never takes that path) where it is used most.
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "option_sets.h"
#include "corpus_files.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace {

drm::EncodeOptions withIndex(drm::EncodeOptions options, drm::NeighbourIndex index) {
    options.index = index;
    return options;
}

drm::Decoded decodeWith(const std::vector<uint8_t>& bytes, drm::NeighbourIndex index) {
    drm::DecodeOptions options;
    options.index = index;
    return drm::decode(bytes.data(), bytes.size(), options);
}

// Encodes with each index, compares the files, decodes with each, compares
// the meshes; also against the default options' file (Auto).
void expectIndexesAgree(const drm::Mesh& mesh, const drm::EncodeOptions& options) {
    const drm::Encoded grid = drm::encode(mesh, withIndex(options, drm::NeighbourIndex::Grid));
    const drm::Encoded flann = drm::encode(mesh, withIndex(options, drm::NeighbourIndex::Flann));
    ASSERT_EQ(grid.bytes, flann.bytes) << "the two indexes wrote different files";
    EXPECT_EQ(grid.vertexOrder, flann.vertexOrder);
    EXPECT_EQ(grid.faceRank, flann.faceRank);
    const drm::Decoded byGrid = decodeWith(grid.bytes, drm::NeighbourIndex::Grid);
    const drm::Decoded byFlann = decodeWith(grid.bytes, drm::NeighbourIndex::Flann);
    EXPECT_EQ(byGrid.quantized, byFlann.quantized);
    EXPECT_EQ(byGrid.mesh.positions, byFlann.mesh.positions);
    EXPECT_EQ(byGrid.mesh.triangles, byFlann.mesh.triangles) << "the two indexes decoded different faces";
    EXPECT_EQ(byGrid.faceRank, byFlann.faceRank);
    EXPECT_EQ(byGrid.mesh.triangles.size(), mesh.triangles.size());
}

TEST(IndexAgreement, SmallMeshesUnderEveryOptionSet) {
    std::vector<drm_test::NamedMesh> meshes = drm_test::smallMeshes();
    meshes.push_back({"mixed", drm_test::mixedMesh()});
    meshes.push_back({"needing-repairs", drm_test::meshNeedingRepairs()});
    for (const drm_test::NamedMesh& m : meshes)
        for (const drm_test::NamedOptions& o : drm_test::optionSets()) {
            SCOPED_TRACE(m.name + " with " + o.name);
            expectIndexesAgree(m.mesh, o.options);
        }
}

TEST(IndexAgreement, TestDataMeshes) {
    const std::vector<drm_test::NamedMesh> meshes = drm_test::readPlyDirectory(DRM_TEST_DATA_DIR);
    ASSERT_FALSE(meshes.empty()) << "no meshes read from " << DRM_TEST_DATA_DIR;
    std::vector<drm_test::NamedOptions> sets;
    for (const drm_test::NamedOptions& o : drm_test::optionSets())
        if (o.name == "default" || o.name == "bits21" || o.name == "midpoint-curvature" || o.name == "no-levers")
            sets.push_back(o);
    drm::EncodeOptions refine;
    refine.geometry = drm::GeometryCoder::Refine;
    sets.push_back({"refine", refine});
    sets.push_back({"as-the-cli-does", drm::EncodeOptions()});  // with the retry without levers
    for (const drm_test::NamedMesh& m : meshes)
        for (const drm_test::NamedOptions& o : sets) {
            SCOPED_TRACE(m.name + " with " + o.name);
            expectIndexesAgree(m.mesh, o.options);
        }
}

std::vector<std::string> corpusFiles() { return drm_test::plyFilesIn(DRM_SHARED_MESHES_DIR); }

class CorpusMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusMesh, SameFileAndMeshWithEitherIndex) {
    const std::string path = std::string(DRM_SHARED_MESHES_DIR) + "/" + GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
    expectIndexesAgree(drm_test::readTinyPly(path), drm::EncodeOptions());
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, CorpusMesh, ::testing::ValuesIn(corpusFiles()),
                         drm_test::testNameOfMeshFile);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusMesh);

}  // namespace
