// An EncodeSession over a mesh, prepared as encodeConnectivity prepares
// it (grid, quantized positions, the cut into manifold pieces where the
// mesh needs one), for the tests of the encoder's attempts, which take a
// session rather than a mesh; and the check that an attempt's file
// decodes to the mesh.
#ifndef DRM_TEST_PREPARED_SESSION_H
#define DRM_TEST_PREPARED_SESSION_H

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "encode/encoder.h"
#include "encode/encode_session.h"
#include "mesh/manifold_cut.h"
#include "mesh/mesh_check.h"
#include "mesh/quantize.h"

namespace drm_test {

struct PreparedSession {
    drm::Mesh mesh;
    drm::EncodeOptions options;
    drm::PreparedMesh prepared;
    drm::ManifoldCut cut;

    PreparedSession(const drm::Mesh& m, const drm::EncodeOptions& o) : mesh(m), options(o) {
        prepared.grid = drm::makeGrid(mesh.positions, options.bits);
        prepared.quantized = drm::quantize(mesh.positions, prepared.grid);
        drm::MeshTopology asGiven;
        const bool needsCut = !drm::topologyProblem(mesh, &asGiven).empty();
        if (needsCut) cut = drm::cutIntoManifold(mesh.triangles, mesh.vertexCount());
        prepared.triangles = needsCut ? &cut.triangles : &mesh.triangles;
        prepared.codableAsGiven = !needsCut;
        prepared.inputFaces = mesh.faceCount();
        prepared.repaired = !cut.isIdentity();
        prepared.inputFace = cut.inputFace;
        prepared.repairs.flipped = cut.flipped;
        prepared.repairs.duplicateOf = cut.duplicateOf;
        prepared.repairs.duplicateReversed = cut.duplicateReversed;
    }
    PreparedSession(const PreparedSession&) = delete;
    PreparedSession& operator=(const PreparedSession&) = delete;

    drm::EncodeSession session() const { return drm::EncodeSession{mesh, prepared, cut, options}; }
};

// A mesh that needs no cut, numbered in its own order for the
// connectivity (NumberedMesh as encodeNumbered fills it, without copies):
// for the tests of what codes a numbered mesh.
inline void numberInInputOrder(const PreparedSession& s, drm::NumberedMesh& numbered, bool mortonNumbering) {
    numbered.order.resize(s.mesh.vertexCount());
    for (size_t v = 0; v < numbered.order.size(); ++v) numbered.order[v] = uint32_t(v);
    numbered.mortonNumbering = mortonNumbering;
    numbered.decodedGrid = s.prepared.quantized;
    numbered.triangles = *s.prepared.triangles;
    numbered.vertexCount = s.mesh.vertexCount();
    drm::buildTopology(numbered.triangles, numbered.vertexCount, &numbered.topology);
    numbered.predictor = drm::Predictor::Midpoint;
}

// The oriented triangles, each rotated to start at its smallest vertex, sorted.
inline std::vector<std::array<uint32_t, 3>> orientedFaces(const std::vector<uint32_t>& t) {
    std::vector<std::array<uint32_t, 3>> faces;
    for (size_t f = 0; f + 2 < t.size(); f += 3) {
        std::array<uint32_t, 3> a = {t[f], t[f + 1], t[f + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        faces.push_back(a);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

// The attempt's file decodes to the faces it says the decoder gives back,
// over the input's grid points (through its vertex order), and those are
// the input's oriented triangles.
inline void expectAttemptDecodes(const drm::Attempt& attempt, const PreparedSession& s) {
    const drm::Decoded d = drm::decode(attempt.encoded.bytes);
    EXPECT_EQ(d.mesh.triangles, attempt.decodedTriangles);
    const std::vector<uint32_t>& order = attempt.encoded.vertexOrder;
    ASSERT_EQ(d.quantized.size(), 3 * order.size());
    for (size_t v = 0; v < order.size(); ++v)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(d.quantized[3 * v + k], s.prepared.quantized[3 * size_t(order[v]) + k]);
    std::vector<uint32_t> faces = d.mesh.triangles;
    for (uint32_t& v : faces) v = order[v];
    EXPECT_EQ(orientedFaces(faces), orientedFaces(s.mesh.triangles));
}

}  // namespace drm_test

#endif  // DRM_TEST_PREPARED_SESSION_H
