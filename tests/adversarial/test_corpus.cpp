// Every mesh of the shared corpus (../shared/meshes beside the project,
// MANIFEST.md there lists their defects) round-trips with the default
// options, and carries repairs exactly when findDefects says it needs them.
// Reading them takes about a minute in all (igea has 270k faces).
// Without the corpus these tests are skipped, unless CI=true, when the
// missing corpus is a failure.
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "corpus_files.h"
#include "mesh_compare.h"
#include "mesh_defects.h"
#include "tiny_ply.h"

namespace adversarial {
namespace {

// The corpus files are all binary little-endian PLY with float x, y, z and
// uchar/int face lists, the layout drm_test::readTinyPly reads.
std::vector<std::string> corpusFiles() { return drm_test::plyFilesIn(DRM_SHARED_MESHES_DIR); }

bool runningInCI() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

TEST(Corpus, IsPresent) {
    if (!corpusFiles().empty()) return;
    const std::string where = std::string("no .ply files in ") + DRM_SHARED_MESHES_DIR;
    if (runningInCI()) FAIL() << where << " (CI=true: the corpus is required)";
    GTEST_SKIP() << where;
}

class CorpusMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusMesh, RoundTripsWithTheRepairsItNeeds) {
    const std::string path = std::string(DRM_SHARED_MESHES_DIR) + "/" + GetParam();
    if (!std::filesystem::exists(path)) {
        if (runningInCI()) FAIL() << path << " is missing (CI=true: the corpus is required)";
        GTEST_SKIP() << path << " is missing";
    }
    const drm::Mesh input = drm_test::readTinyPly(path);
    const drm::EncodeOptions options;
    const drm::Encoded encoded = drm::encode(input, options);
    const drm::Decoded decoded = drm::decode(encoded.bytes);
    EXPECT_TRUE(isLosslessRoundTrip(input, options.bits, encoded, decoded));

    const drm::Stats& s = decoded.stats;
    const MeshDefects defects = findDefects(input);
    EXPECT_EQ(s.looseFaces, defects.facesRepeatingAnIndex);
    EXPECT_LE(s.repeatedFaces, defects.facesOverAnEarlierFacesVertices);
    if (defects.any()) {
        EXPECT_GT(s.repairBytes, 0u) << defects.describe();
    } else {
        EXPECT_EQ(s.repairBytes, 0u) << "a clean mesh must cost nothing extra";
        EXPECT_EQ(s.splitVertices + s.flippedFaces + s.repeatedFaces + s.looseFaces, 0u)
            << "split " << s.splitVertices << ", flipped " << s.flippedFaces << " on a clean mesh";
    }
}

// The list is taken when the tests are discovered (at build time).
INSTANTIATE_TEST_SUITE_P(SharedMeshes, CorpusMesh, ::testing::ValuesIn(corpusFiles()),
                         drm_test::testNameOfMeshFile);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusMesh);

}  // namespace
}  // namespace adversarial
