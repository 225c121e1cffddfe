// Which defects a mesh has that a manifold, consistently oriented traversal
// cannot code as they are, counted here without the codec: the tests use it
// to say whether a file must carry repairs (any defect) or not (none).
//   - a face repeating a vertex index;
//   - an edge shared by more than two faces (non-manifold edge);
//   - an edge shared by two faces that run along it the same way
//     (inconsistent orientation, or a duplicated face);
//   - a vertex whose faces form more than one fan, fans being joined across
//     edges with exactly two faces (non-manifold vertex).
// Also counted, but no defect by itself: faces over the same three vertices
// as an earlier face (whatever the orientation of either). A duplicate
// usually makes one of the defects above; only a face and its turned-over
// copy alone (a closed two-face "pillow") make a clean surface.
#ifndef DRM_TEST_ADVERSARIAL_MESH_DEFECTS_H
#define DRM_TEST_ADVERSARIAL_MESH_DEFECTS_H

#include <drmcodec/drmcodec.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace adversarial {

struct MeshDefects {
    size_t facesRepeatingAnIndex = 0;
    size_t facesOverAnEarlierFacesVertices = 0;
    size_t edgesWithMoreThanTwoFaces = 0;
    size_t edgesWithSameDirectionFaces = 0;
    size_t verticesWithSeveralFans = 0;

    bool any() const {
        return facesRepeatingAnIndex + edgesWithMoreThanTwoFaces + edgesWithSameDirectionFaces +
                   verticesWithSeveralFans >
               0;
    }
    std::string describe() const {
        return std::to_string(facesRepeatingAnIndex) + " faces repeating an index, " +
               std::to_string(facesOverAnEarlierFacesVertices) + " faces over an earlier face's vertices, " +
               std::to_string(edgesWithMoreThanTwoFaces) + " edges with more than two faces, " +
               std::to_string(edgesWithSameDirectionFaces) + " edges whose two faces agree in direction, " +
               std::to_string(verticesWithSeveralFans) + " vertices with several fans";
    }
};

// Indices must be in range.
inline MeshDefects findDefects(const drm::Mesh& mesh) {
    const std::vector<uint32_t>& t = mesh.triangles;
    MeshDefects defects;
    // Undirected edge (low, high) -> its faces, and whether each runs
    // along it from low to high.
    struct Side {
        uint32_t face;
        bool lowToHigh;
    };
    std::map<std::pair<uint32_t, uint32_t>, std::vector<Side>> edges;
    std::set<std::array<uint32_t, 3>> vertexSets;
    for (uint32_t f = 0; 3 * size_t(f) < t.size(); ++f) {
        const uint32_t* v = &t[3 * size_t(f)];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
            ++defects.facesRepeatingAnIndex;
            continue;
        }
        std::array<uint32_t, 3> vertexSet = {v[0], v[1], v[2]};
        std::sort(vertexSet.begin(), vertexSet.end());
        defects.facesOverAnEarlierFacesVertices += !vertexSets.insert(vertexSet).second;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = v[k], b = v[(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
        }
    }

    // Union-find over corners; corners of one vertex in two faces across a
    // two-face edge belong to one fan.
    std::vector<uint32_t> parent(t.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t c) {
        while (parent[c] != c) c = parent[c] = parent[parent[c]];
        return c;
    };
    auto cornerOf = [&](uint32_t face, uint32_t vertex) {
        for (uint32_t k = 0; k < 3; ++k)
            if (t[3 * size_t(face) + k] == vertex) return 3 * face + k;
        return 3 * face;  // unreachable: the face has the vertex
    };
    for (const auto& edge : edges) {
        const std::vector<Side>& sides = edge.second;
        if (sides.size() > 2) ++defects.edgesWithMoreThanTwoFaces;
        if (sides.size() != 2) continue;
        if (sides[0].lowToHigh == sides[1].lowToHigh) ++defects.edgesWithSameDirectionFaces;
        for (uint32_t vertex : {edge.first.first, edge.first.second})
            parent[root(cornerOf(sides[0].face, vertex))] = root(cornerOf(sides[1].face, vertex));
    }

    std::vector<std::set<uint32_t>> fans(mesh.vertexCount());
    for (uint32_t f = 0; 3 * size_t(f) < t.size(); ++f) {
        const uint32_t* v = &t[3 * size_t(f)];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
        for (uint32_t k = 0; k < 3; ++k) fans[v[k]].insert(root(3 * f + k));
    }
    for (const auto& vertexFans : fans) defects.verticesWithSeveralFans += vertexFans.size() > 1;
    return defects;
}

}  // namespace adversarial

#endif  // DRM_TEST_ADVERSARIAL_MESH_DEFECTS_H
