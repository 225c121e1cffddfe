// A topological connectivity coder with positions in the order it meets
// them: connectivity coder 2, the encoder's per-file alternative for
// meshes the distance ranks code poorly (sliver-rich CAD and STL meshes;
// docs/format.md, "Coder 2: topological (connectivity and geometry
// payloads)").
// `drm-topology-study` prices it against the distance-ranked file.
//
// Why a second coder: a distance rank must name the apex of each triangle
// among all the vertices still admissible, and on CAD meshes the apex of a
// long thin triangle is mostly a vertex not yet in the mesh, far down the
// distance order (method notes, "Connectivity on sliver-rich CAD meshes").
// Here a vertex not yet in the mesh is simply the next one: positions are
// coded as the walk meets vertices (predicted across the open edge, below),
// as Edgebreaker-style coders do, so naming it costs a symbol.
//
// The walk is drm's own (Traversal), depth first: both new edges of a
// triangle go to the front of the deque, the left one first, so the walk
// closes the region it is in before it turns back and the front stays about
// one loop, as in Edgebreaker (with the paper's order, right edges to the
// back, a sixth of tray-bottom's edges find their apex elsewhere on the
// front). Each open edge codes one symbol: boundary, new vertex, the far end
// of the fan at its first or at its second end, or another vertex already
// met, then named by its distance rank from the parallelogram prediction
// among the admissible vertices of the front. A symbol's context: the
// symbol before, the angle the edge makes with each fan end, and how many
// triangles the fuller of its two fans already has (the valence coders'
// lesson: a full fan is about to close).
//
// A new vertex is predicted three ways, the parallelogram across the edge
// and the rim of the fan around either end carried on (around a sliver's
// hub the parallelogram falls near the hub); per class of gate triangle
// (which of its angles is the narrowest) the one of the smallest recent
// error is used. The residual is coded in the frame of the gate triangle
// (normal third, edge first: local_frame.h), where a planar CAD face leaves
// the third component near zero.
#ifndef DRM_TOPOLOGICAL_CODER_H
#define DRM_TOPOLOGICAL_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

class ProgressReporter;

// Where a walk reports how far it is (ticks from `from` to from + span as
// its faces are rebuilt), and learns of a cancel (Error, Cancelled).
struct WalkProgress {
    ProgressReporter* reporter = nullptr;
    double from = 0, span = 0;
};

struct TopologicalStreams {
    std::vector<uint8_t> connectivity;  // symbols, the ranks of other vertices, which vertices are copies
    std::vector<uint8_t> geometry;      // positions, in the order the walk meets them
    bool complete = true;               // false: given up (TopologicalBudget), both empty
};

// How far the passes over the front for apexes elsewhere on it may read in
// all, in front vertices: floor + perFace per face rebuilt. The format's
// bound is the default; the encoder keeps to it (an attempt under a
// giveUpAbove gives up past it, any other throws InvalidInput) and the
// decoder refuses a file past it (Corrupt), so that no file makes decoding
// quadratic. Tests lower it to reach both sides.
struct OtherSearchBound {
    uint64_t floor = uint64_t(1) << 22;
    uint64_t perFace = 4096;
};

// What an encoder comparing coders can tell this one.
struct TopologicalBudget {
    // The mesh passed topologyProblem already (as the caller's cut mesh
    // does): not checked again (the check would take nearly a quarter of
    // the coder's instructions).
    bool meshChecked = false;
    // Give up once a quarter of the faces or more is coded and the bytes so
    // far, scaled to every face, pass this (0: never): the other coder's
    // file is then almost surely the smaller.
    uint64_t giveUpAbove = 0;
    OtherSearchBound search;
    WalkProgress progress;
};

// Where an encoding's bits went (for studies; not stored anywhere).
struct TopologicalStats {
    // Edges by symbol: boundary, new vertex, fan end at the first end, at
    // the second end, another vertex met before.
    uint64_t symbols[5] = {};
    double symbolBits = 0, rankBits = 0;             // connectivity
    double newVertexBits = 0, otherPositionBits = 0;  // geometry: walk's new vertices, starts and isolated ones
    uint64_t frontRead = 0;  // front vertices read for apexes elsewhere on it (OtherSearchBound)
};

// The decoded numbering, as the encoder sees it. Decoded vertices are the
// originals in the order the walk met them (vertices in no face last),
// then the copies, in the order of the vertices they copy (so that a
// repairs section lists their originals in non-decreasing order). Of a
// vertex and its copies, the one the walk meets first is the original.
struct TopologicalLayout {
    std::vector<uint32_t> vertexOf;   // decoded vertex -> the caller's
    std::vector<uint32_t> copyOf;     // per copy (decoded V + k): its original's decoded index
    std::vector<uint32_t> faceOf;     // decoded face -> the caller's
    std::vector<uint32_t> triangles;  // as decoded, over decoded vertices
    uint64_t components = 0;
    uint64_t boundaryEdges = 0;
};

// grid: x, y, z per vertex, each in [0, 2^bits), bits in 1..21; its last
// copyOf.size() vertices are copies of others (a manifold cut's: vertex
// n - copyOf.size() + k of n copies vertex copyOf[k], an original, at the
// same grid point). triangles: a mesh the traversal can take (as
// cutIntoManifold gives it: each edge in at most two faces, of opposite
// orientations; each vertex the centre of one fan; no face repeating a
// vertex). Throws Error on a mesh the walk cannot take, and (InvalidInput)
// on one whose apexes elsewhere on the front need a search past
// budget.search, unless budget.giveUpAbove is set (then it gives up).
TopologicalStreams encodeTopological(const std::vector<int32_t>& grid, int bits, const std::vector<uint32_t>& triangles,
                                     const std::vector<uint32_t>& copyOf, TopologicalLayout* layout = nullptr,
                                     TopologicalStats* stats = nullptr, const TopologicalBudget& budget = TopologicalBudget());

struct TopologicalMesh {
    std::vector<int32_t> grid;        // x, y, z per decoded vertex, copies included
    std::vector<uint32_t> triangles;  // over decoded vertices, as the walk rebuilt them
    std::vector<uint32_t> copyOf;     // per copy: its original's decoded index (the repairs section's list)
    uint64_t components = 0;
    uint64_t boundaryEdges = 0;
};

// vertexCount counts the originals, copyCount the copies after them.
// Throws Error (Corrupt) on streams that name an impossible triangle, run
// out, claim more vertices than their bytes can hold, or search the front
// past `search`; Cancelled where `progress`'s reporter is told to stop.
TopologicalMesh decodeTopological(const uint8_t* connectivity, size_t connectivitySize, const uint8_t* geometry,
                                  size_t geometrySize, size_t vertexCount, size_t copyCount, size_t faceCount, int bits,
                                  const OtherSearchBound& search = OtherSearchBound(),
                                  const WalkProgress& progress = WalkProgress());

}  // namespace drm

#endif  // DRM_TOPOLOGICAL_CODER_H
