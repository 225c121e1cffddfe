// The decoded mesh seen from its corners, for the attribute coders: which
// corner lies across each edge, and which corners share a vertex. Built
// the same way by encoder and decoder from the decoded triangles alone.
//
// Corner c is corner c % 3 of face c / 3; the edge opposite corner c joins
// the face's other two corners. Two corners are opposite when their edges
// are the same undirected edge, shared by exactly those two faces, both
// faces having three distinct vertices: the only edges across which an
// attribute can be predicted or be continuous.
#ifndef DRM_CORNER_TABLE_H
#define DRM_CORNER_TABLE_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common.h"

namespace drm {

constexpr uint32_t kNoCorner = kNoIndex;  // no corner (a boundary edge's opposite)

inline uint32_t nextCorner(uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
inline uint32_t previousCorner(uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

struct CornerTable {
    // opposite[c]: the corner across the edge opposite c, or kNoCorner
    // (empty until addOpposites when built without them).
    std::vector<uint32_t> opposite;
    // The interior edges, each once, as the lower of its two corners, in
    // the order both coders visit them (by that corner).
    std::vector<uint32_t> interiorEdges;
    // Corners of each vertex, in corner order: vertexCorners[cornerStart[v]
    // .. cornerStart[v + 1]).
    std::vector<uint32_t> cornerStart;
    std::vector<uint32_t> vertexCorners;
};

// withOpposites false leaves opposite and interiorEdges empty (the costly
// part, which per-vertex sections with geometric or ring predictions do not
// need); addOpposites fills them later.
CornerTable buildCornerTable(const std::vector<uint32_t>& triangles, size_t vertexCount, bool withOpposites = true);
void addOpposites(CornerTable& table, const std::vector<uint32_t>& triangles);

// The corner of face `face` at vertex v, or kNoCorner.
inline uint32_t cornerAt(const std::vector<uint32_t>& triangles, uint32_t face, uint32_t v) {
    for (uint32_t k = 0; k < 3; ++k)
        if (triangles[3 * size_t(face) + k] == v) return 3 * face + k;
    return kNoCorner;
}

}  // namespace drm

#endif  // DRM_CORNER_TABLE_H
