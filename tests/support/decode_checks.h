// What every outcome of drm::decode must satisfy, whatever the input: an
// Error of a kind a decoder may report, with a message, or a mesh whose
// indices all name a vertex. The fuzzer and the robustness tests apply the
// same two checks.
#ifndef DRM_TEST_DECODE_CHECKS_H
#define DRM_TEST_DECODE_CHECKS_H

#include <string>

#include "drmcodec/drmcodec.h"

namespace drm_test {

// The kinds drm::decode may refuse a buffer with (drmcodec.h): damaged or
// foreign data, a version or coder it does not know, or a cancel. Never
// InvalidInput, Io or Internal, and never an empty sentence.
inline bool isDecodeRefusal(const drm::Error& e) {
    const drm::ErrorKind kind = e.kind();
    return (kind == drm::ErrorKind::Corrupt || kind == drm::ErrorKind::Unsupported ||
            kind == drm::ErrorKind::Cancelled) &&
           e.what()[0] != '\0';
}

// "" if the decoded mesh is well formed, else what is wrong with it.
inline std::string decodedMeshProblem(const drm::Decoded& d) {
    const drm::Mesh& m = d.mesh;
    if (m.positions.size() % 3 != 0) return "positions do not hold whole xyz triples";
    if (m.triangles.size() % 3 != 0) return "triangles do not hold whole index triples";
    if (d.quantized.size() != m.positions.size()) return "quantized and positions differ in size";
    const size_t vertices = m.vertexCount();
    for (size_t i = 0; i < m.triangles.size(); ++i)
        if (m.triangles[i] >= vertices)
            return "face " + std::to_string(i / 3) + " refers to vertex " + std::to_string(m.triangles[i]) +
                   " of " + std::to_string(vertices);
    if (d.stats.faces != m.faceCount() || d.stats.vertices != vertices) return "stats disagree with the mesh";
    if (d.faceRank.size() != m.faceCount())
        return "faceRank has " + std::to_string(d.faceRank.size()) + " entries for " + std::to_string(m.faceCount()) +
               " faces";
    return "";
}

}  // namespace drm_test

#endif  // DRM_TEST_DECODE_CHECKS_H
