// Checks that a mesh is one the traversal can code as it is, and builds the
// directed-edge table the encoder uses to find the true apex across an edge.
#ifndef DRM_MESH_CHECK_H
#define DRM_MESH_CHECK_H

#include <cstdint>
#include <string>

#include "drmcodec/drmcodec.h"
#include <vector>

namespace drm {

struct MeshTopology {
    const std::vector<uint32_t>* triangles = nullptr;

    // The face that holds the directed edge (a, b), kNoIndex if none.
    uint32_t faceOf(uint32_t a, uint32_t b) const;
    // The vertex c such that (b, a, c) is a face, i.e. the apex of the
    // triangle on the other side of the directed edge (a, b); kNoVertex on a
    // boundary. *face receives that face's index.
    uint32_t apexAcross(uint32_t a, uint32_t b, uint32_t* face) const;

    // Each vertex's outgoing directed edges, by far end, in one array:
    // those of a are out[start[a] .. start[a + 1]). Read in vertex order,
    // as the traversal mostly reads them, they lie together (a hash table
    // of the edges would send every look-up to a random place, a cache miss
    // on a large mesh), and they take 52 bytes a vertex where such a table
    // takes 144.
    struct Outgoing {
        uint32_t to, face;
    };
    std::vector<uint32_t> start;
    std::vector<Outgoing> out;
};

// Throws Error naming the first face with an index out of range, or if the
// arrays are malformed or too large.
void checkIndices(const Mesh& mesh);
// The same over bare faces, for a mesh the encoder keeps without positions
// (3 floats per vertex it would only count).
void checkIndices(const std::vector<uint32_t>& triangles, size_t vertexCount);

// Throws Error naming the first offending element if the mesh has an index
// out of range, a face repeating a vertex, a directed edge used twice (a
// non-manifold edge or neighbours with opposite orientation) or a vertex whose
// faces form more than one fan (a non-manifold vertex).
MeshTopology checkMesh(const Mesh& mesh);

// The same test without throwing, for a caller that only needs the answer:
// "" if the traversal can code the mesh as it is (*topology then holds its
// directed-edge table), otherwise the message checkMesh would throw.
// Indices must already be in range (checkIndices).
std::string topologyProblem(const Mesh& mesh, MeshTopology* topology);
// Only the table, no check: for triangles known to pass topologyProblem
// (the same faces under other vertex numbers, say). Indices in range.
void buildTopology(const std::vector<uint32_t>& triangles, size_t vertexCount, MeshTopology* topology);
std::string topologyProblem(const std::vector<uint32_t>& triangles, size_t vertexCount, MeshTopology* topology);

}  // namespace drm

#endif  // DRM_MESH_CHECK_H
