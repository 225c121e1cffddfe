// One thread or two, the encoder writes the same file (EncodeOptions::
// threads): the vertex section coded beside the topology check, the
// neighbour graph split between threads, the spanning forest built beside
// the cheapest-first tree, and refine's estimates run beside the tree's
// attempt, and refine's attempts beside it, must each come out as they do
// one after the other.
//
// Meshes built in code large enough that every split is taken (16,384
// vertices and more; one over 2^18, where the vertex section coded beside
// the connectivity keeps to one thread), one of them coarse enough on its
// grid that refine's estimates run; tests/data's meshes under the option
// sets that take the other paths (refine with its low bits searched or
// given, the tree, raw); and the shared corpus (../shared/meshes beside
// the project, one ctest test per mesh; skipped without it).
#include <drmcodec/drmcodec.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "corpus_files.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace {

drm::Encoded encodeOn(const drm::Mesh& mesh, drm::EncodeOptions options, int threads) {
    options.threads = threads;
    return drm::encode(mesh, options);
}

void expectThreadsAgree(const drm::Mesh& mesh, const drm::EncodeOptions& options) {
    const drm::Encoded one = encodeOn(mesh, options, 1);
    const drm::Encoded two = encodeOn(mesh, options, 2);
    ASSERT_EQ(one.bytes, two.bytes) << "one thread and two wrote different files";
    EXPECT_EQ(one.vertexOrder, two.vertexOrder);
    EXPECT_EQ(one.faceRank, two.faceRank);
    const drm::Decoded decoded = drm::decode(two.bytes.data(), two.bytes.size());
    EXPECT_EQ(decoded.mesh.triangles.size(), mesh.triangles.size());
}

TEST(ThreadAgreement, LargeMeshesTakeEverySplit) {
    // 40,962 vertices: the neighbour graph and the spanning forest split.
    expectThreadsAgree(drm_test::icosphere(6), drm::EncodeOptions());
    // 22,801 vertices at 16 bits: the tree spends over 11 bits a vertex, so
    // refine's two estimates run beside the tree's attempt.
    const drm::Mesh jittered = drm_test::gridPatch(150, false, 0.24, 9);
    drm::EncodeOptions fine;
    fine.bits = 16;
    const drm::Encoded tree = encodeOn(jittered, fine, 1);
    ASSERT_GT(8.0 * double(tree.stats.geometryBytes) / double(tree.stats.vertices), drm::kAutoRefineAboveBitsPerVertex)
        << "the estimates would not run";
    expectThreadsAgree(jittered, fine);
    // 655,362 vertices, over 2^18: the connectivity is coded beside a
    // vertex section kept to one thread.
    expectThreadsAgree(drm_test::icosphere(8), drm::EncodeOptions());
}

TEST(ThreadAgreement, TestDataMeshesUnderEveryGeometryCoder) {
    const std::vector<drm_test::NamedMesh> meshes = drm_test::readPlyDirectory(DRM_TEST_DATA_DIR);
    ASSERT_FALSE(meshes.empty()) << "no meshes read from " << DRM_TEST_DATA_DIR;
    std::vector<std::pair<std::string, drm::EncodeOptions>> sets(5);
    sets[0].first = "default";
    sets[1].first = "refine, low bits searched";
    sets[1].second.geometry = drm::GeometryCoder::Refine;
    sets[2].first = "refine, 3 low bits";
    sets[2].second.geometry = drm::GeometryCoder::Refine;
    sets[2].second.refineBits = 3;
    sets[3].first = "tree";
    sets[3].second.geometry = drm::GeometryCoder::SpanningTree;
    sets[4].first = "raw";
    sets[4].second.geometry = drm::GeometryCoder::Raw;
    for (const drm_test::NamedMesh& m : meshes)
        for (const auto& set : sets) {
            SCOPED_TRACE(m.name + " with " + set.first);
            expectThreadsAgree(m.mesh, set.second);
        }
}

// Two copies of one sphere, one on the other's points: every point is on a
// grid point twice, and the vertex coder reaches many pairs in the other
// order than the input's. The numbering still takes each pair in input
// order (encode/vertex_section.cpp, connectivityOrder), so the
// connectivity ranked beside the vertex set, in the Morton order of the
// input, is the one kept: one ranking pass, where ranking in the vertex
// coder's order would take a second. (The mesh has 163,840 faces and its tree stays under 11 bits a
// vertex: no other attempt, each of which would rank again, is made.)
TEST(ThreadAgreement, PointsOnOneGridPointAreRankedOnce) {
    drm::Mesh mesh = drm_test::icosphere(6);
    const size_t n = mesh.vertexCount(), corners = mesh.triangles.size();
    const std::vector<float> firstCopy = mesh.positions;
    mesh.positions.insert(mesh.positions.end(), firstCopy.begin(), firstCopy.end());
    for (size_t c = 0; c < corners; ++c) mesh.triangles.push_back(mesh.triangles[c] + uint32_t(n));
    drm::EncodeOptions options;
    options.threads = 2;
    int rankingPasses = 0;
    std::string last;
    options.progress = [&](double, const char* stage) {
        if (std::string(stage) == "ranking" && last != "ranking") ++rankingPasses;
        last = stage;
        return true;
    };
    const drm::Encoded encoded = drm::encode(mesh, options);
    EXPECT_EQ(rankingPasses, 1);
    EXPECT_EQ(drm::decode(encoded.bytes.data(), encoded.bytes.size()).mesh.triangles.size(), mesh.triangles.size());
    options.progress = nullptr;
    expectThreadsAgree(mesh, options);
}

// A cancel while the vertex coder runs on the second thread (the progress
// callback refuses the cut, which the calling thread makes meanwhile) ends
// the encoding with Cancelled, after the thread is done; the same options
// without the cancel still encode.
TEST(ThreadAgreement, ACancelWhileTheSecondThreadRunsIsReported) {
    drm::Mesh mesh = drm_test::icosphere(6);  // 40,962 vertices: every split is taken
    for (int k = 0; k < 3; ++k) mesh.triangles.push_back(mesh.triangles[k]);  // a repeated face: a cut
    drm::EncodeOptions options;
    options.threads = 2;
    bool cutSeen = false;
    options.progress = [&](double, const char* stage) {
        if (std::string(stage).find("cutting") == std::string::npos) return true;
        cutSeen = true;
        return false;
    };
    try {
        drm::encode(mesh, options);
        ADD_FAILURE() << "the encoding was not cancelled";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Cancelled) << e.what();
    }
    EXPECT_TRUE(cutSeen);
    options.progress = nullptr;
    const drm::Encoded encoded = drm::encode(mesh, options);
    EXPECT_EQ(drm::decode(encoded.bytes.data(), encoded.bytes.size()).mesh.triangles.size(), mesh.triangles.size());
}

// Refine's attempts run beside the tree's (a mesh of tests/data where
// refine wins, mech-holes-shark: 2 low bits). A cancel is reported as
// Cancelled whether it comes before any thread starts (the first ranking, of the
// connectivity coded beside the vertex section) or while the estimates
// and attempts beside run (the last ranking this thread reports, in the
// tree's attempt): a thread left waiting on the tree's total would hang
// the encoding, an exception escaping one would end the process. The
// same options then encode the mesh with refine, as on one thread.
TEST(ThreadAgreement, ACancelWhileRefineIsTriedBesideIsReported) {
    const std::vector<drm_test::NamedMesh> meshes = drm_test::readPlyDirectory(DRM_TEST_DATA_DIR);
    const auto shark = std::find_if(meshes.begin(), meshes.end(), [](const drm_test::NamedMesh& m) {
        return m.name.find("mech-holes-shark") != std::string::npos;
    });
    ASSERT_NE(shark, meshes.end()) << "mech-holes-shark.ply is missing from " << DRM_TEST_DATA_DIR;
    drm::EncodeOptions options;
    options.threads = 2;
    int rankings = 0;
    options.progress = [&](double, const char* stage) {
        rankings += std::string(stage) == "ranking";
        return true;
    };
    const drm::Encoded two = drm::encode(shark->mesh, options);
    EXPECT_EQ(two.stats.geometry, drm::GeometryCoder::Refine);
    ASSERT_GT(rankings, 1);
    for (const int cancelAt : {1, rankings}) {
        SCOPED_TRACE("cancelled at ranking " + std::to_string(cancelAt) + " of " + std::to_string(rankings));
        int seen = 0;
        options.progress = [&](double, const char* stage) {
            seen += std::string(stage) == "ranking";
            return seen != cancelAt;
        };
        try {
            drm::encode(shark->mesh, options);
            ADD_FAILURE() << "the encoding was not cancelled";
        } catch (const drm::Error& e) {
            EXPECT_EQ(e.kind(), drm::ErrorKind::Cancelled) << e.what();
        }
        EXPECT_EQ(seen, cancelAt);
    }
    options.progress = nullptr;
    EXPECT_EQ(encodeOn(shark->mesh, options, 1).bytes, two.bytes);
}

std::vector<std::string> corpusFiles() { return drm_test::plyFilesIn(DRM_SHARED_MESHES_DIR); }

class CorpusMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusMesh, SameFileOnOneThreadOrTwo) {
    const std::string path = std::string(DRM_SHARED_MESHES_DIR) + "/" + GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
    expectThreadsAgree(drm_test::readTinyPly(path), drm::EncodeOptions());
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, CorpusMesh, ::testing::ValuesIn(corpusFiles()),
                         drm_test::testNameOfMeshFile);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusMesh);

}  // namespace
