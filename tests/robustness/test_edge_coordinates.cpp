// Meshes at the edges of what a float can hold, crossed with every option
// set: each is either refused by the encoder with a message naming the
// problem, or decoded back to the encoder's grid points and oriented faces.
// Never a file that the decoder refuses (issue: a box of -2e38 .. 2e38
// once encoded and then would not decode).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "option_sets.h"
#include "test_meshes.h"

namespace {

struct EdgeMesh {
    std::string name;
    drm::Mesh mesh;
    const char* refusal;  // nullptr: must round-trip; else a word the encoder's message must contain
};

// The tetrahedron with its vertices moved to the given points.
drm::Mesh tetrahedronAt(const std::array<std::array<float, 3>, 4>& points) {
    drm::Mesh m = drm_test::tetrahedron();
    m.positions.clear();
    for (const auto& p : points) m.positions.insert(m.positions.end(), p.begin(), p.end());
    return m;
}

std::vector<EdgeMesh> edgeMeshes() {
    const float big = FLT_MAX, tiny = std::numeric_limits<float>::denorm_min();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<EdgeMesh> meshes;
    meshes.push_back({"extent-above-float-max", tetrahedronAt({{{-2e38f, 0, 0}, {2e38f, 0, 0}, {0, 1, 0}, {0, 0, 1}}}), nullptr});
    meshes.push_back({"float-max-every-axis",
                      tetrahedronAt({{{-big, -big, -big}, {big, -big, -big}, {-big, big, -big}, {big, big, big}}}), nullptr});
    meshes.push_back({"float-max-one-corner", tetrahedronAt({{{big, big, big}, {0, 0, 0}, {big, 0, 0}, {0, big, 0}}}), nullptr});
    meshes.push_back({"denormals", tetrahedronAt({{{0, 0, 0}, {tiny, 0, 0}, {0, 2 * tiny, 0}, {0, 0, 3 * tiny}}}), nullptr});
    meshes.push_back({"denormal-and-huge", tetrahedronAt({{{tiny, 0, 0}, {1e38f, 0, 0}, {0, tiny, 0}, {0, 0, -1e38f}}}), nullptr});
    meshes.push_back({"huge-offset-tiny-extent",
                      tetrahedronAt({{{1e7f, 1e7f, 1e7f}, {1e7f + 1, 1e7f, 1e7f}, {1e7f, 1e7f + 1, 1e7f}, {1e7f, 1e7f, 1e7f + 1}}}),
                      nullptr});
    meshes.push_back({"offset-near-float-max",
                      tetrahedronAt({{{3e38f, 3e38f, 3e38f}, {3.1e38f, 3e38f, 3e38f}, {3e38f, 3.1e38f, 3e38f}, {3e38f, 3e38f, 3.1e38f}}}),
                      nullptr});
    // On an axis shorter than the longest, the nearest grid point of a
    // vertex near FLT_MAX can lie past it (a case of the round-trip fuzzer).
    meshes.push_back({"shorter-axis-ends-at-float-max",
                      tetrahedronAt({{{-big, -0.4f * big, 0}, {big, big, 0}, {0, 0.93f * big, 1}, {0, 0.61f * big, -1}}}), nullptr});
    meshes.push_back({"one-repeated-point", tetrahedronAt({{{5, 5, 5}, {5, 5, 5}, {5, 5, 5}, {5, 5, 5}}}), nullptr});
    meshes.push_back({"negative-zero", tetrahedronAt({{{-0.0f, 0, 0}, {0, -0.0f, 0}, {1, 0, -0.0f}, {0, 1, 1}}}), nullptr});
    meshes.push_back({"nan", tetrahedronAt({{{0, 0, 0}, {1, 0, 0}, {0, nan, 0}, {0, 0, 1}}}), "vertex 2"});
    meshes.push_back({"infinity", tetrahedronAt({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -inf}}}), "vertex 3"});
    return meshes;
}

using Faces = std::vector<std::array<uint32_t, 3>>;

// Oriented faces over input vertex indices, each starting at its smallest index, sorted.
Faces canonical(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& toInput) {
    Faces faces;
    for (size_t f = 0; f + 2 < triangles.size(); f += 3) {
        std::array<uint32_t, 3> t = {toInput[triangles[f]], toInput[triangles[f + 1]], toInput[triangles[f + 2]]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        faces.push_back(t);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

TEST(EdgeCoordinates, RefusedWithAMessageOrDecodedExactly) {
    int roundTrips = 0, refusals = 0;
    for (const EdgeMesh& edge : edgeMeshes()) {
        for (const drm_test::NamedOptions& set : drm_test::optionSets()) {
            SCOPED_TRACE(edge.name + " with " + set.name);
            drm::Encoded encoded;
            try {
                encoded = drm::encode(edge.mesh, set.options);
            } catch (const drm::Error& e) {
                ASSERT_NE(edge.refusal, nullptr) << "refused: " << e.what();
                EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
                // The refusal's text says why (e.g. past float's range), for the user: checked too.
                EXPECT_NE(std::string(e.what()).find(edge.refusal), std::string::npos) << e.what();
                ++refusals;
                continue;
            }
            ASSERT_EQ(edge.refusal, nullptr) << "encoded a mesh it must refuse";
            drm::Decoded decoded;
            try {
                decoded = drm::decode(encoded.bytes);
            } catch (const drm::Error& e) {
                FAIL() << "the encoder wrote a file the decoder refuses: " << e.what();
            }
            ASSERT_EQ(decoded.mesh.vertexCount(), edge.mesh.vertexCount());
            for (size_t d = 0; d < decoded.mesh.vertexCount(); ++d)
                for (int k = 0; k < 3; ++k) {
                    ASSERT_EQ(decoded.quantized[3 * d + k], encoded.quantized[3 * encoded.vertexOrder[d] + k]);
                    ASSERT_TRUE(std::isfinite(decoded.mesh.positions[3 * d + k]));
                }
            std::vector<uint32_t> identity(edge.mesh.vertexCount());
            for (uint32_t v = 0; v < identity.size(); ++v) identity[v] = v;
            EXPECT_EQ(canonical(decoded.mesh.triangles, encoded.vertexOrder), canonical(edge.mesh.triangles, identity));
            ++roundTrips;
        }
    }
    EXPECT_GT(roundTrips, 0);
    EXPECT_GT(refusals, 0);
}

// Positions at the grid's far corner come back within one grid step.
TEST(EdgeCoordinates, FloatRangeBoxDecodesNearTheInput) {
    const drm::Mesh mesh = tetrahedronAt({{{-2e38f, 0, 0}, {2e38f, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
    drm::EncodeOptions options;
    options.keepVertexOrder = true;
    const drm::Decoded decoded = drm::decode(drm::encode(mesh, options).bytes);
    ASSERT_EQ(decoded.mesh.positions.size(), mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        EXPECT_LE(std::fabs(double(decoded.mesh.positions[i]) - double(mesh.positions[i])), decoded.grid.step) << i;
}

}  // namespace
