// Cuts any triangle mesh into a mesh the traversal can code: every edge
// shared by at most two faces of opposite orientation, every vertex the apex
// of a single fan, no face repeating a vertex. The cut is undone exactly by
// the decoder from three lists (the repairs section): which extra vertices
// are copies of which, which faces were turned over, and the faces that
// repeat a vertex, set aside whole.
//
// How: faces are joined across an edge only when exactly two faces share it.
// A breadth-first walk over the joins orients each edge-connected piece like
// its first face; a join that contradicts the walk (a Mobius strip's seam) is
// cut. Around each vertex the faces then fall into fans (corners linked by
// joins); the first fan keeps the vertex, every further fan gets a copy. A
// directed edge that still appears twice (two cut faces that happened to
// keep the same vertices) is resolved by detaching the later face from all
// its neighbours, which gives it copies of its own.
#ifndef DRM_MANIFOLD_CUT_H
#define DRM_MANIFOLD_CUT_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

struct ManifoldCut {
    // The faces that do not repeat a vertex, in input order, each oriented
    // consistently with its piece, over vertexCount + copyOf.size() vertices.
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> inputFace;  // kept face -> input face index
    std::vector<uint8_t> flipped;     // kept face -> 1 if turned over
    // Vertex vertexCount + k is a copy of input vertex copyOf[k].
    std::vector<uint32_t> copyOf;
    // Input faces repeating a vertex, verbatim (3 indices each), and their
    // input indices.
    std::vector<uint32_t> looseTriangles;
    std::vector<uint32_t> looseInputFace;
    // Input faces over the same three vertices as an earlier face: which kept
    // face they repeat, whether they run the other way round, and their
    // input indices. They stay out of the traversal (a doubled face would
    // otherwise cut the surface around it open).
    std::vector<uint32_t> duplicateOf;
    std::vector<uint8_t> duplicateReversed;
    std::vector<uint32_t> duplicateInputFace;
    size_t flippedCount = 0;

    // True when the mesh needed no repair at all (then triangles is the
    // input and the file carries no repairs section).
    bool isIdentity() const {
        return copyOf.empty() && looseTriangles.empty() && duplicateOf.empty() && flippedCount == 0;
    }
};

// triangles holds 3 indices per face, each below vertexCount (checked by
// the caller).
ManifoldCut cutIntoManifold(const std::vector<uint32_t>& triangles, size_t vertexCount);

}  // namespace drm

#endif  // DRM_MANIFOLD_CUT_H
