// Every mesh in tests/data survives encode + decode up to quantization, and
// the file's statistics agree with counts taken from the input itself.
// The checks here are written from the API's promises, not taken from the
// codec or the tool, so a shared mistake cannot hide.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <string>
#include <vector>

namespace {

std::vector<std::string> testMeshPaths() {
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(DRM_TEST_DATA_DIR))
        if (entry.is_regular_file() && drm::vcgio::isMeshFileName(entry.path().string()))
            paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::string testNameOf(const std::string& path) {
    std::string name = std::filesystem::path(path).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

using Triangle = std::array<uint32_t, 3>;

// The smallest rotation of an oriented triangle (well defined also for
// faces such as (a, a, b)).
Triangle rotatedToSmallest(const Triangle& t) {
    return std::min({t, Triangle{t[1], t[2], t[0]}, Triangle{t[2], t[0], t[1]}});
}

std::multiset<Triangle> orientedTriangles(const std::vector<uint32_t>& corners,
                                          const std::vector<uint32_t>* renumber = nullptr) {
    std::multiset<Triangle> triangles;
    for (size_t c = 0; c + 2 < corners.size(); c += 3) {
        Triangle t = {corners[c], corners[c + 1], corners[c + 2]};
        if (renumber)
            for (uint32_t& v : t) v = (*renumber)[v];
        triangles.insert(rotatedToSmallest(t));
    }
    return triangles;
}

// Directed edges whose reverse no face uses: the boundary of a consistently
// oriented manifold mesh.
uint64_t countBoundaryEdges(const drm::Mesh& mesh) {
    std::set<std::pair<uint32_t, uint32_t>> directed;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            directed.insert({mesh.triangles[3 * f + k], mesh.triangles[3 * f + (k + 1) % 3]});
    uint64_t boundary = 0;
    for (const auto& edge : directed)
        if (!directed.count({edge.second, edge.first})) ++boundary;
    return boundary;
}

// Each test mesh with each connectivity coder: the smaller file (auto),
// the distance ranks, and the topological coder.
class RoundTrip : public ::testing::TestWithParam<std::tuple<std::string, drm::ConnectivityCoder>> {
protected:
    void SetUp() override {
        input_ = drm::vcgio::loadMesh(std::get<0>(GetParam())).mesh;
        drm::EncodeOptions options;
        options.connectivity = std::get<1>(GetParam());
        encoded_ = drm::encode(input_, options);
        decoded_ = drm::decode(encoded_.bytes);
    }

    drm::Mesh input_;
    drm::Encoded encoded_;
    drm::Decoded decoded_;
};

TEST_P(RoundTrip, KeepsEveryVertexOnItsGridPoint) {
    const size_t vertexCount = input_.vertexCount();
    ASSERT_EQ(decoded_.mesh.vertexCount(), vertexCount);
    ASSERT_EQ(decoded_.quantized.size(), 3 * vertexCount);

    // vertexOrder must be a permutation of the input's vertices.
    ASSERT_EQ(encoded_.vertexOrder.size(), vertexCount);
    std::vector<uint32_t> sorted = encoded_.vertexOrder;
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint32_t> identity(vertexCount);
    std::iota(identity.begin(), identity.end(), 0u);
    ASSERT_EQ(sorted, identity) << "vertexOrder is not a permutation";

    const drm::Grid grid = drm::makeGrid(input_.positions, 12);
    const std::vector<int32_t> expected = drm::quantize(input_.positions, grid);
    size_t wrongGridPoints = 0, farPositions = 0;
    // Decoded positions are origin + q * step rounded to float: within half a
    // step of the input, plus float rounding of coordinates of this size.
    double largest = 0;
    for (float x : input_.positions) largest = std::max(largest, double(std::fabs(x)));
    const double tolerance = 0.5 * grid.step + 4.0 * FLT_EPSILON * (largest + grid.step * 4096.0);
    for (size_t i = 0; i < vertexCount; ++i) {
        const size_t original = encoded_.vertexOrder[i];
        for (int k = 0; k < 3; ++k) {
            if (decoded_.quantized[3 * i + k] != expected[3 * original + k]) ++wrongGridPoints;
            const double error = std::fabs(double(decoded_.mesh.positions[3 * i + k]) -
                                           double(input_.positions[3 * original + k]));
            if (error > tolerance) ++farPositions;
        }
    }
    EXPECT_EQ(wrongGridPoints, 0u) << "coordinates not on the input's grid point";
    EXPECT_EQ(farPositions, 0u) << "coordinates further than half a step from the input";
}

TEST_P(RoundTrip, KeepsEveryOrientedTriangle) {
    ASSERT_EQ(decoded_.mesh.faceCount(), input_.faceCount());
    for (uint32_t v : decoded_.mesh.triangles) ASSERT_LT(v, encoded_.vertexOrder.size());
    const auto before = orientedTriangles(input_.triangles);
    const auto after = orientedTriangles(decoded_.mesh.triangles, &encoded_.vertexOrder);
    EXPECT_TRUE(before == after) << "the decoded triangles differ from the input's";
}

TEST_P(RoundTrip, StatisticsAgreeWithTheInput) {
    const drm::Stats& stats = decoded_.stats;
    EXPECT_EQ(stats.vertices, input_.vertexCount());
    EXPECT_EQ(stats.faces, input_.faceCount());
    EXPECT_EQ(stats.totalBytes, encoded_.bytes.size());
    // A mesh cut into manifold pieces (fins-and-bowtie) has the cut's
    // boundary edges besides its own.
    if (stats.repairBytes == 0) EXPECT_EQ(stats.boundaryEdges, countBoundaryEdges(input_));
    else EXPECT_GT(stats.boundaryEdges, countBoundaryEdges(input_));
    EXPECT_EQ(encoded_.stats.connectivity, stats.connectivity);
    if (stats.connectivity == drm::ConnectivityCoder::Topological) {
        // No ranks: every face's code is 0, and there is no histogram.
        EXPECT_TRUE(stats.rankHistogram.empty());
        EXPECT_EQ(encoded_.stats.boundaryEdges, stats.boundaryEdges);
        EXPECT_EQ(encoded_.stats.connectivityBytes, stats.connectivityBytes);
        EXPECT_EQ(std::count(encoded_.faceRank.begin(), encoded_.faceRank.end(), 0u), std::ptrdiff_t(input_.faceCount()));
        return;
    }
    // One rank code per face except the start triangles, plus one rank-0
    // code per boundary edge.
    const uint64_t codes = std::accumulate(stats.rankHistogram.begin(), stats.rankHistogram.end(), uint64_t(0));
    EXPECT_EQ(codes, stats.faces - stats.components + stats.boundaryEdges);
    ASSERT_FALSE(stats.rankHistogram.empty());
    EXPECT_EQ(stats.rankHistogram[0], stats.boundaryEdges);
    // The decoder measures the same file the encoder wrote.
    EXPECT_EQ(encoded_.stats.totalBytes, stats.totalBytes);
    EXPECT_EQ(encoded_.stats.connectivityBytes, stats.connectivityBytes);
    EXPECT_EQ(encoded_.stats.rankHistogram, stats.rankHistogram);
    // faceRank: one entry per input face, zero exactly for start triangles.
    ASSERT_EQ(encoded_.faceRank.size(), input_.faceCount());
    EXPECT_EQ(uint64_t(std::count(encoded_.faceRank.begin(), encoded_.faceRank.end(), 0u)), stats.components);
}

INSTANTIATE_TEST_SUITE_P(TestData, RoundTrip,
                         ::testing::Combine(::testing::ValuesIn(testMeshPaths()),
                                            ::testing::Values(drm::ConnectivityCoder::Auto, drm::ConnectivityCoder::Ranks,
                                                              drm::ConnectivityCoder::Topological)),
                         [](const ::testing::TestParamInfo<std::tuple<std::string, drm::ConnectivityCoder>>& info) {
                             return testNameOf(std::get<0>(info.param)) + "_" +
                                    drm::connectivityCoderName(std::get<1>(info.param));
                         });

TEST(RoundTripData, FindsTheTestMeshes) { EXPECT_GE(testMeshPaths().size(), 8u); }

// A regular 24 x 12 torus: every apex is the nearest candidate, so its
// connectivity should cost next to nothing.
TEST(RoundTripTorus, RegularTorusCodesNearZeroBitsPerVertex) {
    const drm::Mesh torus = drm::vcgio::loadMesh(std::string(DRM_TEST_DATA_DIR) + "/torus.ply").mesh;
    const drm::Encoded encoded = drm::encode(torus);
    EXPECT_LT(encoded.stats.connectivityBitsPerVertex(), 0.3);
}

}  // namespace
