// drm: distance-ranked connectivity compression of triangle meshes.
//
// The public API of the codec library. It is C++14-clean (MeshLab 2020.09
// plugins are built as gnu++14) and holds no I/O: meshes and byte buffers in,
// meshes and byte buffers out. Errors are thrown as drm::Error with a message
// that names the element, option or byte offset at fault.
//
// Method: P. Marais, J. Gain, D. Shreiner, "Distance-Ranked Connectivity
// Compression of Triangle Meshes" (the quantized vertex set is coded first;
// connectivity is the stream of distance ranks of each new triangle's apex).
#ifndef DRM_DRM_H
#define DRM_DRM_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace drm {

// Thrown by every function of the library on bad input, corrupt data or a
// cancelled operation. what() is a complete sentence for the user.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// An indexed triangle mesh: xyz per vertex, three vertex indices per face.
// Faces are oriented: (a, b, c) and (a, c, b) are different triangles.
struct Mesh {
    std::vector<float> positions;     // 3 * vertexCount()
    std::vector<uint32_t> triangles;  // 3 * faceCount()

    size_t vertexCount() const { return positions.size() / 3; }
    size_t faceCount() const { return triangles.size() / 3; }
};

// Which apex predictor the traversal uses (paper, Section 3.2).
enum class Predictor : uint8_t {
    Auto = 0,           // chosen per mesh by the paper's counters
    Parallelogram = 1,
    Midpoint = 2,
};

// How the vertex set is coded (the geometry section).
enum class GeometryCoder : uint8_t {
    Raw = 1,           // every grid coordinate in `bits` bits; keeps the input order
    SpanningTree = 2,  // predictive coding along a nearest-neighbour spanning tree
                       // (the encoder falls back to raw where that is smaller)
    Refine = 3,        // the coarse grid (low bits dropped) by the spanning tree, the
                       // connectivity ranked on it, then the low bits predicted across
                       // the decoded triangles (the encoder falls back to the spanning
                       // tree where that is smaller)
};

const char* geometryCoderName(GeometryCoder g);
// Parses "raw", "tree", "refine"; throws Error otherwise.
GeometryCoder parseGeometryCoder(const std::string& name);

const char* predictorName(Predictor p);
// Parses "auto", "parallelogram", "midpoint"; throws Error otherwise.
Predictor parsePredictor(const std::string& name);

// Progress callback: fraction of the work done in [0, 1], and a short label
// of the current stage. Return false to cancel (the call then throws Error).
using Progress = std::function<bool(double fraction, const char* stage)>;

// Additions to the paper's method, each decoder-reproducible and recorded in
// the file. All on by default; all off gives the paper's method as published.
struct Levers {
    // Candidates that cannot close the triangle for topological reasons
    // (the edge's opposite vertex, vertices whose new edges would reuse a
    // rebuilt directed edge or a coded boundary) are not ranked.
    bool topologicalFilter = true;
    // When an end of the edge has a narrow gap left in its fan (under 60
    // degrees), the vertex closing that gap gets rank 1.
    bool gapClosing = true;
    // Ranks are coded in contexts bucketed by how clear-cut the nearest
    // candidate is (ratio of the two nearest candidate distances).
    bool confidenceContext = true;
    // The four nearest candidates are ranked by the angle they subtend over
    // the edge, largest first (the apex of a Delaunay-like triangulation
    // sees the edge under the largest angle), those behind the edge last;
    // the rest by distance. With confidence contexts, whether this order
    // and the distance order agree on rank 1 doubles the contexts.
    bool angleOrder = true;

    static Levers none() { return Levers{false, false, false, false}; }
};

// "all", "none", or a comma-separated list of filter, gap, context, angle.
// Throws Error on anything else.
Levers parseLevers(const std::string& list);
// The inverse: "all", "none" or the list of those on.
std::string leversName(const Levers& levers);

struct EncodeOptions {
    int bits = 12;                          // quantization bits per axis, 1..21
    Predictor predictor = Predictor::Auto;
    bool curvature = false;                 // the paper's curvature correction
    GeometryCoder geometry = GeometryCoder::SpanningTree;
    // With GeometryCoder::Refine: how many low bits the refinement codes
    // (1..8, below `bits`); 0 lets the encoder try 1, 2, ... while the file
    // shrinks, and the spanning tree alone, and keep the smallest.
    int refineBits = 0;
    // Store the permutation back to the input vertex order (a fourth
    // section), so decoded vertices keep their input indices.
    bool keepVertexOrder = false;
    Levers levers;
    // Below 20000 faces, also encode with no levers and keep the smaller
    // file: on tiny regular meshes (a 288-vertex torus) learning the levers'
    // contexts can cost a byte or two more than it saves.
    bool tryWithoutLevers = true;
    Progress progress;                      // may be empty
};

// What a .drm file holds, measured. Byte counts are exact sizes of the file's
// parts: connectivityBytes is the rank stream alone (as the paper counts it),
// totalBytes the whole file.
struct Stats {
    uint64_t vertices = 0;
    uint64_t faces = 0;
    uint64_t components = 0;       // start triangles (edge-connected pieces)
    uint64_t boundaryEdges = 0;    // rank-0 codes
    int bits = 0;
    Predictor predictor = Predictor::Midpoint;  // the one used (never Auto)
    bool curvature = false;
    Levers levers;
    GeometryCoder geometry = GeometryCoder::SpanningTree;
    int refineBits = 0;             // low bits coded by the refinement (GeometryCoder::Refine)
    uint64_t headerBytes = 0;
    uint64_t connectivityBytes = 0;
    uint64_t geometryBytes = 0;
    uint64_t vertexOrderBytes = 0;  // 0 unless the file keeps the input vertex order
    uint64_t totalBytes = 0;
    // What it took to code a mesh that is not a manifold, consistently
    // oriented surface of distinct triangles (all 0 for one that is): the
    // repairs section's size, the vertex copies that cut non-manifold edges
    // and vertices apart, the faces coded turned over, the faces over the
    // same three vertices as an earlier face, coded as a reference to it
    // (only in a mesh that needs repairs: two faces over the same vertices
    // in opposite directions and nothing else are a clean closed surface),
    // and the faces repeating a vertex index (stored whole).
    uint64_t repairBytes = 0;
    uint64_t splitVertices = 0;
    uint64_t flippedFaces = 0;
    uint64_t repeatedFaces = 0;
    uint64_t looseFaces = 0;
    // rankHistogram[r] = number of rank codes equal to r (r = 0: boundary edge).
    std::vector<uint64_t> rankHistogram;

    double connectivityBitsPerVertex() const;
    double geometryBitsPerVertex() const;
    double totalBitsPerVertex() const;
};

// "" for a mesh that needed no repair, otherwise e.g. "12 vertex copies,
// 3 faces turned over, 1 face repeating a vertex (45 bytes)".
std::string describeRepairs(const Stats& stats);

// Quantization grid: grid coordinate q of axis k stands for
// origin[k] + q * step. One cubic step over the bounding box:
// step = largest extent / (2^bits - 1).
struct Grid {
    double origin[3] = {0, 0, 0};
    double step = 1;
    int bits = 12;
};

struct Encoded {
    std::vector<uint8_t> bytes;      // the .drm file
    Stats stats;
    Grid grid;
    // Quantized input positions (3 per vertex, input vertex order).
    std::vector<int32_t> quantized;
    // vertexOrder[i] = input vertex index of decoded vertex i. The geometry
    // coder chooses the decoded order; the raw coder and keepVertexOrder
    // give the input order (identity).
    std::vector<uint32_t> vertexOrder;
    // For each input face, the rank code that created it (>= 1), or 0 for a
    // component's start triangle, which is stored in the header, not ranked,
    // and for faces repeating a vertex or another face, which are not ranked.
    std::vector<uint32_t> faceRank;
};

// Decoded faces come in traversal order, then the faces that repeat an
// earlier face's vertices, then the faces repeating a vertex index (both in
// input order); each face keeps its orientation, not necessarily which
// corner comes first.
struct Decoded {
    Mesh mesh;                       // dequantized positions, decoded faces
    std::vector<int32_t> quantized;  // grid coordinates, 3 per vertex
    Grid grid;
    Stats stats;
    // For each decoded face, the rank code that created it (0 for a
    // component's start triangle), as in Encoded::faceRank.
    std::vector<uint32_t> faceRank;
};

// Encodes a mesh. Any triangle mesh is accepted: non-manifold edges and
// vertices, inconsistent orientation, non-orientable surfaces, duplicated
// faces, faces repeating a vertex and coincident vertices are all coded so
// that decode() gives back the same oriented triangles over the same
// vertices (Stats counts the repairs). Throws Error, naming the first
// offending element, when the mesh cannot be represented (no vertices, NaN
// or infinite coordinates, index out of range) or when options are out of
// range.
Encoded encode(const Mesh& mesh, const EncodeOptions& options = EncodeOptions());

// Decodes a .drm buffer. Throws Error naming what is wrong (and where) for
// truncated, corrupt or foreign data; never crashes or reads out of bounds.
Decoded decode(const uint8_t* data, size_t size, const Progress& progress = Progress());
inline Decoded decode(const std::vector<uint8_t>& bytes, const Progress& progress = Progress()) {
    return decode(bytes.data(), bytes.size(), progress);
}

// Quantizes positions onto the grid encode() would use for these options.
// Throws Error on empty input or non-finite coordinates.
Grid makeGrid(const std::vector<float>& positions, int bits);
std::vector<int32_t> quantize(const std::vector<float>& positions, const Grid& grid);

// The library's version string, e.g. "0.1.0".
const char* version();

}  // namespace drm

#endif  // DRM_DRM_H
