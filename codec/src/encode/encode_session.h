// What the encoder's attempts at one mesh share: the mesh prepared once
// (grid, quantized positions, the cut into manifold pieces), one attempt's
// numbering of it, and the session that hands both to every attempt.
// Internal to encode/: attempt_plan.h says which attempts are made, in
// which order.
#ifndef DRM_ENCODE_SESSION_H
#define DRM_ENCODE_SESSION_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

#include "common.h"
#include "drmcodec/drmcodec.h"
#include "encode/encoder.h"
#include "mesh/manifold_cut.h"
#include "mesh/mesh_check.h"
#include "mesh/quantize.h"
#include "mesh/repair_section.h"

namespace drm {

// The early connectivity (encodeBeforeVertexSection) holds the traversal's
// tables while the vertex coder holds its own, so the peak memory is about
// their sum: it takes about a third off a large mesh's encoding time for
// a third to a half more peak memory (docs/tuning.md), when the vertex
// section keeps to one thread (below) and the drm tool maps large blocks on
// their own (tools/cli.cpp, mapLargeBlocksApart). Larger meshes code the
// two stages in turn, for memory.
constexpr size_t kEarlyConnectivityUpToVertices = size_t(1) << 22;
// Above this many vertices, a vertex section coded beside the early
// connectivity keeps to one thread: its own second one (the graph's
// halves, the forest built beside the cheapest-first tree) would add its
// tables to the two stages', for no gain in time (docs/tuning.md).
constexpr size_t kSectionThreadsBesideUpToVertices = size_t(1) << 18;

// What every attempt at one mesh shares, and only reads: the grid, the
// quantized input and the input cut into manifold pieces.
struct PreparedMesh {
    Grid grid;
    std::vector<int32_t> quantized;   // input order
    // The faces the traversal codes, over input indices: the cut's, or the
    // input's own when it needed no cut (not copied: 12 bytes a face).
    const std::vector<uint32_t>* triangles = nullptr;
    size_t inputFaces = 0;
    std::vector<uint32_t> inputFace;  // face of triangles -> input face; empty: the same face (no cut)
    // flipped and duplicateOf per face of triangles, and duplicateReversed;
    // each attempt has its own copies and faces repeating a vertex, in its
    // decoded indices (encodeOnce joins them, in decoded face order).
    Repairs repairs;
    bool repaired = false;
    // The input's faces passed topologyProblem as they are (no cut): any
    // renumbering of them passes too, so its table needs no second check.
    bool codableAsGiven = false;
};

// One attempt's numbering: the geometry section, the connectivity's vertex
// order (Morton order or the section's: docs/format.md, "Vertex
// numbering") and the faces renumbered into it, with their topology and
// the predictor. Connectivity is coded over the renumbered faces, because
// ties between equal distances are broken by the indices the decoder will
// see.
// Never copied or moved: topology points into triangles.
struct NumberedMesh {
    NumberedMesh() = default;
    NumberedMesh(const NumberedMesh&) = delete;
    NumberedMesh& operator=(const NumberedMesh&) = delete;

    GeometryCoder geometryCoder = GeometryCoder::SpanningTree;
    std::vector<uint8_t> geometry;    // the geometry section (Refine: the coarse tree alone)
    int lowBits = 0;                  // Refine: the low bits the refinement codes
    std::vector<int32_t> fineDecoded; // Refine: the full grid of the vertices, connectivity order
    std::vector<uint32_t> order;      // connectivity index -> input index
    bool mortonNumbering = true;      // order is Morton order (else the section's: FileHeader)
    std::vector<int32_t> decodedGrid; // decoded order, copies included (Refine: the coarse grid)
    // prepared.triangles over decoded indices; vertices from order.size() on
    // are copies. Only their count is kept, no positions.
    std::vector<uint32_t> triangles;
    size_t vertexCount = 0;
    MeshTopology topology;            // of triangles
    Predictor predictor = Predictor::Midpoint;
    std::vector<uint32_t> copyOf;          // per copy, the decoded index of its original; non-decreasing
    std::vector<uint32_t> looseTriangles;  // the faces repeating a vertex, decoded indices
};

// Where the traversal starts its components (start_triangle.h).
// SmallestVertices: each at its smallest vertex, in increasing order, but
// for the first component if firstVertex names a vertex in a face.
// InputFaces: each at the first face of the input that no earlier
// component reached (the corpus's CAD meshes often list their faces in an
// order the traversal likes: teapot's ranks cost 15 % less so);
// firstVertex is not used.
struct ComponentStarts {
    enum class Order { SmallestVertices, InputFaces } order = Order::SmallestVertices;
    uint32_t firstVertex = kNoVertex;
};

// The first attempt's connectivity, coded while its vertex section is
// (encodeBeforeVertexSection), and the numbering it was coded in.
struct EarlyConnectivity {
    Attempt attempt;
    std::vector<uint32_t> order;  // connectivity index -> input index
    bool certain = false;         // no two points coincide: order is the section's numbering, unchecked
};
// One encoding of one mesh: the input, what is prepared from it once, and
// the options as the caller gave them. Attempts only read it; each attempt
// that differs from the options (another vertex coder, no levers, fewer
// threads) takes that difference as an argument of its own.
struct EncodeSession {
    const Mesh& mesh;
    const PreparedMesh& prepared;
    const ManifoldCut& cut;
    const EncodeOptions& options;
};

// Whether the encoder may run independent parts of its work on a second
// thread (EncodeOptions::threads). The file is the same either way.
inline bool secondThreadAllowed(const EncodeOptions& options) {
    return options.threads >= 2 || (options.threads == 0 && std::thread::hardware_concurrency() > 1);
}
// The threads a search may spread over: FLANN's batch search takes them
// all (every core by default); the grid's splits take two of any count
// above one.
inline int threadsFor(const EncodeOptions& options) {
    if (options.threads != 0) return options.threads;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace drm

#endif  // DRM_ENCODE_SESSION_H
