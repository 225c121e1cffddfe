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
#ifndef DRMCODEC_DRMCODEC_H
#define DRMCODEC_DRMCODEC_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// Everything declared here is the library's API, exported from
// libdrmcodec.so; the codec's internals are built hidden.
#if defined(__GNUC__)
#pragma GCC visibility push(default)
#endif

namespace drm {

// What kind of failure an Error reports (docs/library.md lists which
// functions throw which).
enum class ErrorKind : uint8_t {
    InvalidInput = 0,  // the caller's mesh, options or names cannot be coded as given
    Corrupt = 1,       // the data is not a well-formed .drm file: truncated, damaged or foreign
    Unsupported = 2,   // a well-formed .drm file using a version or coder this library does not know
    Cancelled = 3,     // the progress callback returned false
    Io = 4,            // reading or writing a file failed (thrown by the tools and adapters, never by the codec)
    Internal = 5,      // a bug: the codec's own consistency check failed
};
// "invalid input", "corrupt", "unsupported", "cancelled", "i/o", "internal".
const char* errorKindName(ErrorKind kind);

// Thrown by every function of the library on bad input, corrupt data or a
// cancelled operation. what() is a complete sentence for the user; kind()
// says which of the failures above it is, for programs.
class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    // An error of kind InvalidInput.
    explicit Error(const std::string& message) : Error(ErrorKind::InvalidInput, message) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

// Limits and names, written once here and used by the library, the `drm`
// tool, the MeshLab plugins and the docs.
constexpr int kMinQuantizationBits = 1;      // EncodeOptions::bits
constexpr int kMaxQuantizationBits = 21;     // keeps squared fixed-point distances within int64
constexpr int kDefaultQuantizationBits = 12; // the paper's setting
// EncodeOptions::refineBits: a file holds 1..kMaxRefineBits low bits (always
// fewer than the quantization bits); 0 lets the encoder try
// 1..kMaxTriedRefineBits and the spanning tree alone.
constexpr int kMaxRefineBits = 8;
constexpr int kMaxTriedRefineBits = 5;
// What GeometryCoder::Auto (the default) does, stated here because `drm
// help encode` and the docs quote it: where the tree costs more than
// kAutoRefineAboveBitsPerVertex, refine is also tried with each of
// kAutoRefineLowBits, and kept where the file is at least
// kAutoRefineMinimumGainPercent smaller (refine decodes 20-30 % slower;
// under 8,192 vertices, tried where an estimate, within its slack,
// promises 1 % and kept wherever smaller; under 1,000, tried where it may
// be smaller at all and kept wherever smaller). docs/tuning.md gives the
// measurements behind the three values.
constexpr double kAutoRefineAboveBitsPerVertex = 11.0;
constexpr int kAutoRefineLowBits[] = {4, 2};
constexpr int kAutoRefineMinimumGainPercent = 3;
// EncodeOptions::normalBits and uvBits.
constexpr int kMinNormalBits = 4;
constexpr int kMaxNormalBits = 16;
constexpr int kDefaultNormalBits = 10;   // every normal within 0.2 degrees
constexpr int kMinUvBits = 1;
constexpr int kMaxUvBits = 24;
constexpr int kDefaultUvBits = 12;
// The .drm format version this library writes and the only one it reads:
// files of earlier, pre-release versions are refused (ErrorKind::Unsupported)
// with a message naming their version.
constexpr int kFileFormatVersion = 13;

// An indexed triangle mesh: xyz per vertex, three vertex indices per face.
// Faces are oriented: (a, b, c) and (a, c, b) are different triangles.
//
// Every attribute array is optional: empty means the mesh does not carry
// it; otherwise it holds exactly the size given (encode() refuses any other
// size). Per-corner arrays follow the faces: corner k of face f is entry
// 3 * f + k. docs/format.md says how each is coded and what comes back.
struct Mesh {
    std::vector<float> positions;     // 3 * vertexCount()
    std::vector<uint32_t> triangles;  // 3 * faceCount()

    // Per vertex.
    std::vector<uint8_t> colors;      // 4 per vertex: red, green, blue, alpha (exact)
    std::vector<float> normals;       // 3 per vertex (quantized: EncodeOptions::normalBits)
    std::vector<float> texCoords;     // 2 per vertex: u, v (quantized: EncodeOptions::uvBits)
    std::vector<float> quality;       // 1 per vertex (exact, bit for bit)
    // Per corner (wedge): values that differ between the faces around a
    // vertex, such as texture coordinates across a seam.
    std::vector<float> cornerTexCoords;  // 6 per face: u, v of each corner
    std::vector<float> cornerNormals;    // 9 per face: xyz of each corner
    // Per face.
    std::vector<uint8_t> faceColors;     // 4 per face: red, green, blue, alpha (exact)
    std::vector<float> faceQuality;      // 1 per face (exact, bit for bit)
    std::vector<uint32_t> faceMaterial;  // 1 per face: index into materials
    std::vector<uint32_t> faceTexture;   // 1 per face: index into textures (MeshLab's wedge texture index)
    // Names, kept as given.
    std::vector<std::string> materials;  // material names (OBJ usemtl)
    std::vector<std::string> textures;   // texture file names (PLY TextureFile, MeshLab's texture list)
    // Other named strings a file format needs back, e.g. "obj.mtllib" (the
    // material library's file name) and "obj.mtl" (its text).
    std::vector<std::pair<std::string, std::string>> metadata;

    size_t vertexCount() const { return positions.size() / 3; }
    size_t faceCount() const { return triangles.size() / 3; }
    // True if any attribute array, name list or metadata entry is non-empty.
    bool hasAttributes() const;
};

// The attributes a file can carry, as bits of EncodeOptions::attributes.
enum AttributeBits : uint32_t {
    kAttrColors = 1u << 0,
    kAttrNormals = 1u << 1,
    kAttrTexCoords = 1u << 2,
    kAttrQuality = 1u << 3,
    kAttrCornerTexCoords = 1u << 4,
    kAttrCornerNormals = 1u << 5,
    kAttrFaceColors = 1u << 6,
    kAttrFaceQuality = 1u << 7,
    kAttrFaceMaterial = 1u << 8,  // with the material names
    kAttrFaceTexture = 1u << 9,   // with the texture names
    kAttrMetadata = 1u << 10,
    kAttrAll = (1u << 11) - 1,
};
// "colors,normals,texcoords,quality,corner-texcoords,corner-normals,
// face-colors,face-quality,materials,textures,metadata" (those set), "all" or
// "none"; parseAttributes accepts those names and "all"/"none" and throws
// Error on anything else.
std::string attributesName(uint32_t bits);
uint32_t parseAttributes(const std::string& list);
// The attributes kept by the section Stats::attributeSizes lists under
// `sectionName`: the attribute of that name, the face materials for
// "material names", the face textures for "texture names"; 0 for a name it
// does not know.
uint32_t sectionAttributes(const std::string& sectionName);
// The attributes a mesh carries, as AttributeBits.
uint32_t attributesOf(const Mesh& mesh);

// Which apex predictor the traversal uses (paper, Section 3.2).
enum class Predictor : uint8_t {
    Auto = 0,           // chosen per mesh by the paper's counters
    Parallelogram = 1,
    Midpoint = 2,
};

// How the vertex set is coded (the geometry section).
enum class GeometryCoder : uint8_t {
    Auto = 0,          // an option only, never stored: the tree, and on meshes where
                       // the tree spends many bits per vertex also refine (the
                       // smallest file wins)
    Raw = 1,           // every grid coordinate in `bits` bits; keeps the input order
    SpanningTree = 2,  // predictive coding along a nearest-neighbour spanning tree
                       // (the encoder falls back to sorted, or raw, where that is smaller)
    Refine = 3,        // the coarse grid (low bits dropped) by the spanning tree, the
                       // connectivity ranked on it, then the low bits predicted across
                       // the decoded triangles (the encoder falls back to the spanning
                       // tree where that is smaller)
    Sorted = 4,        // the points in Morton order, each as its gap from the one before:
                       // for scattered points that predict no better than nothing
                       // (the encoder falls back to raw where that is smaller)
};

// How the connectivity is coded (the connectivity section).
enum class ConnectivityCoder : uint8_t {
    Auto = 0,         // an option only, never stored: the distance ranks, and the
                      // topological coder too unless an option only the ranks have
                      // is set (EncodeOptions::connectivity); the smaller file wins
    Ranks = 1,        // the paper's distance ranks over the vertex set coded first
    Topological = 2,  // each triangle's apex named by topology (a new
                      // vertex, a fan's far end, or another front vertex by rank),
                      // positions coded in the order the walk meets them; no ranks
};
const char* connectivityCoderName(ConnectivityCoder c);
// Parses "auto", "ranks", "topological"; throws Error otherwise.
ConnectivityCoder parseConnectivityCoder(const std::string& name);

const char* geometryCoderName(GeometryCoder g);
// Parses "auto", "raw", "tree", "refine", "sorted"; throws Error otherwise.
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
    // The edge's two front neighbours (the far ends of the open
    // fans at its ends, the vertices gap closing looks at) may be ranked
    // right after rank 1, the rest following in the order above. Whether
    // they are follows which order would have coded the recent apexes in
    // fewer bits, which encoder and decoder both keep count of (sliver-rich
    // CAD meshes gain, smooth scans would lose). With confidence contexts,
    // edges ranked in the front order have contexts of their own.
    bool frontNeighbours = true;
    // Whether an edge is a boundary edge (rank 0) is coded as a
    // yes or no of its own, before any rank, in contexts of what the
    // decoder sees around the edge: whether the size step found a vertex
    // ahead of it (in its first ball, a wider one, or none), how many of
    // the fans at its ends end on a coded boundary, and whether the edge
    // before was a boundary edge. Meshes with borders and holes gain
    // (scans, terrains); closed ones pay a few bytes.
    bool boundaryFlag = true;

    static Levers none() { return Levers{false, false, false, false, false, false}; }
};

// The levers' names in parseLevers lists, in Levers' field order:
// leverName(0) = "filter", 1 "gap", 2 "context", 3 "angle", 4 "front",
// 5 "boundary" (nullptr past them).
constexpr int kLeverCount = 6;
const char* leverName(int lever);

// "all", "none", or a comma-separated list of filter, gap, context, angle, front, boundary.
// Throws Error on anything else.
Levers parseLevers(const std::string& list);
// The inverse: "all", "none" or the list of those on.
std::string leversName(const Levers& levers);

// Which spatial index answers the codec's neighbour searches: the grid of
// cells, or FLANN's kd-tree. Both decide ranks by the same exact integer
// distances, so files and decoded meshes are identical byte for byte;
// only speed differs. Auto takes the faster for each search (the
// traversal's, the geometry tree's neighbour graph).
enum class NeighbourIndex : uint8_t { Auto = 0, Grid = 1, Flann = 2 };

struct EncodeOptions {
    int bits = kDefaultQuantizationBits;    // quantization bits per axis, kMin..kMaxQuantizationBits
    Predictor predictor = Predictor::Auto;
    bool curvature = false;                 // the paper's curvature correction
    GeometryCoder geometry = GeometryCoder::Auto;
    // With GeometryCoder::Refine: how many low bits the refinement codes
    // (1..kMaxRefineBits, below `bits`); 0 lets the encoder try
    // 1..kMaxTriedRefineBits and the spanning tree alone, and keep the smallest.
    // Auto takes its own (kAutoRefineLowBits) and ignores this.
    int refineBits = 0;
    // Store the permutation back to the input vertex order (a fourth
    // section), so decoded vertices keep their input indices.
    bool keepVertexOrder = false;
    Levers levers;
    // Which of the mesh's attributes the file keeps (AttributeBits); those
    // not kept are simply left out.
    uint32_t attributes = kAttrAll;
    // Normals: octahedral quantization with this many bits per coordinate
    // (kMinNormalBits..kMaxNormalBits). 10 keeps every normal within 0.2 degrees.
    int normalBits = kDefaultNormalBits;
    // Texture coordinates: a square grid over their range with 2^uvBits - 1
    // steps across the wider axis (kMinUvBits..kMaxUvBits).
    int uvBits = kDefaultUvBits;
    // Meshes exported with a vertex per corner (every face on its own
    // vertices, positions repeated): Weld::Auto merges vertices on the same
    // grid point for the connectivity when at least a third of the vertices
    // repeat another's grid point and the mesh carries per-vertex
    // attributes; their values then become per-corner values. The decoded
    // mesh has one vertex per distinct (grid point, attribute values), so
    // every corner comes back with its attributes. Off never welds (each
    // vertex is kept), On always does.
    enum class Weld : uint8_t { Auto = 0, Off = 1, On = 2 };
    Weld weld = Weld::Auto;
    // Decode the file just written and compare it with the input (grid
    // points, oriented faces, every corner's attributes within their
    // quantization) before returning; a mismatch throws Error. Costs about
    // one decode (roughly half the encoding time again).
    bool verify = false;
    // Below 4096 faces, also encode with no levers and keep the smaller
    // file: on tiny regular meshes (a 288-vertex torus) learning the levers'
    // contexts can cost a byte or two more than it saves.
    bool tryWithoutLevers = true;
    // Where the traversal starts each component changes every rank after
    // it. Off: each component at its smallest vertex. On (the default):
    // below 20000 faces also from one other first vertex and in the
    // input's face order, keeping the smallest file (0.7 % smaller on the
    // corpus in geometric mean; 1.4 to 2 times the encoding time on such
    // meshes), each over both vertex numberings (Morton order
    // and the vertex coder's: Stats::mortonNumbering). Larger meshes start
    // at their smallest vertices in Morton numbering either way.
    bool searchStarts = true;
    NeighbourIndex index = NeighbourIndex::Auto;  // never changes the file
    // Threads for independent parts of one mesh's encoding (the vertex
    // section beside the mesh checks and, up to 4,194,304 vertices, the
    // connectivity (over 262,144 with the vertex section then on one
    // thread); the neighbour graph in two halves, the
    // spanning forest beside the cheapest-first tree, refine's estimates
    // and, up to 262,144 vertices, its attempts beside the tree's attempt,
    // below 20000 faces every other start
    // vertex tried): 1 keeps everything on the calling thread,
    // 2 or more allows a second (briefly a third: the two estimates, the
    // vertex coder's split beside the topology check, the start vertices
    // tried beside the vertex section), 0 (the default) is 2
    // where the machine has more than one core, else 1; FLANN's neighbour
    // graph takes this many threads (0: every core). Never changes the file.
    // A program encoding several meshes at once, one per core, passes 1.
    int threads = 0;
    // The connectivity in two parts that decode on two threads at once
    // (docs/format.md, "Two connectivity parts"): 0 (the default) splits
    // meshes whose traversal codes 32,768 faces or more in Morton
    // numbering, unless the shortest seam has more edges than 0.9 % of
    // the faces (0.06 to 0.44 % larger files on the corpus, decoded in
    // about 0.7 of the wall time on two cores); 1 never splits; 2 always
    // does where the mesh has two vertices and a face (a small mesh pays
    // for the seam: for tests).
    int connectivityParts = 0;
    // Ranks codes the paper's distance ranks (every face gets a rank code:
    // Encoded::faceRank); Topological the connectivity by topology and the
    // positions in the order it meets them (docs/format.md, "Coder 2:
    // topological (connectivity and geometry payloads)"); Auto codes the
    // ranks, then the topological coder, which gives up once it would be
    // 5 % larger, and keeps the smaller file. Auto keeps to the ranks when
    // an option only they have is set (geometry, predictor, curvature,
    // levers other than all, parts); Topological refuses a geometry coder
    // other than Auto.
    ConnectivityCoder connectivity = ConnectivityCoder::Auto;
    Progress progress;                      // may be empty
};

// What a .drm file holds, measured. Byte counts are exact sizes of the file's
// parts: connectivityBytes is the connectivity section, the rank stream (as
// the paper counts it) and the start triangles coded in it;
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
    // The connectivity's vertex numbering, which is also the decoded
    // vertex order (without keepVertexOrder): Morton order of the grid
    // points, or the geometry coder's own order (the raw coder's, and small
    // meshes' where it codes smaller).
    bool mortonNumbering = false;
    // The connectivity in two parts that decode side by side
    // (EncodeOptions::connectivityParts), else 1.
    int connectivityParts = 1;
    // Ranks, or Topological (then no face has a rank: faceRank
    // is all 0, the rank histogram empty, and `geometry` means nothing).
    ConnectivityCoder connectivity = ConnectivityCoder::Ranks;
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
    // Attribute sections, one entry per section in file order: its name (as
    // attributesName gives it, e.g. "normals", or "material names", "texture
    // names": sectionAttributes says what each keeps) and its payload size.
    struct AttributeSize {
        std::string name;
        uint64_t bytes = 0;
    };
    std::vector<AttributeSize> attributeSizes;
    uint64_t attributeBytes = 0;    // all attribute sections, framing included
    uint64_t weldedVertices = 0;    // input vertices merged into another (Weld)
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
    // vertexOrder[i] = input vertex index of decoded vertex i. The decoded
    // order is Morton order of the grid points, or the geometry coder's
    // (Stats::mortonNumbering); the raw coder and keepVertexOrder give the
    // input order (identity).
    std::vector<uint32_t> vertexOrder;
    // For each input face, the rank code that created it (>= 1), or 0 for a
    // component's start triangle, which is stored as vertex gaps, not ranked,
    // and for faces repeating a vertex or another face, which are not ranked.
    std::vector<uint32_t> faceRank;
    // faceOrder[i] = input face that decoded face i is, and faceRotation[i]
    // the corner of that input face the decoded face starts at (0..2).
    std::vector<uint32_t> faceOrder;
    std::vector<uint8_t> faceRotation;
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
struct DecodeOptions {
    NeighbourIndex index = NeighbourIndex::Auto;  // never changes the decoded mesh
    // Threads for a file whose connectivity comes in two parts:
    // 1 decodes them in turn on the calling thread, 2 or more the second
    // beside the first, 0 (the default) is 2 where the machine has more
    // than one core. Never changes the decoded mesh.
    int threads = 0;
    Progress progress;                            // may be empty
};
Decoded decode(const uint8_t* data, size_t size, const DecodeOptions& options);
inline Decoded decode(const std::vector<uint8_t>& bytes, const Progress& progress = Progress()) {
    return decode(bytes.data(), bytes.size(), progress);
}

// What a .drm file's header and section table say, read without decoding
// anything (a few microseconds on any file). inspect() checks what it reads
// as decode() does (signature, version, lengths, checksums, header fields)
// and throws Error (Corrupt or Unsupported) on the same files.
struct FileInfo {
    int formatVersion = 0;
    // Filled from the header and the section table: vertices (those the
    // file stores; a welded mesh decodes to more, see decode()'s Stats),
    // faces, components, bits, predictor, curvature, levers, geometry,
    // refineBits, every *Bytes field, splitVertices, attributeSizes and
    // attributeBytes. Left 0 or empty, because only decoding tells them:
    // boundaryEdges, rankHistogram, flippedFaces, repeatedFaces,
    // looseFaces, weldedVertices.
    Stats stats;
    bool keepsVertexOrder = false;
    bool hasRepairs = false;
};
FileInfo inspect(const uint8_t* data, size_t size);
inline FileInfo inspect(const std::vector<uint8_t>& bytes) { return inspect(bytes.data(), bytes.size()); }

// Quantizes positions onto the grid encode() would use for these options.
// Throws Error on empty input or non-finite coordinates.
Grid makeGrid(const std::vector<float>& positions, int bits);
std::vector<int32_t> quantize(const std::vector<float>& positions, const Grid& grid);

// The largest angle, in radians, between a unit normal and its decoded
// value at the given normal bits (octahedral quantization).
double maxNormalError(int normalBits);

// The library's version string, e.g. "0.1.0".
const char* version();

}  // namespace drm

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif  // DRMCODEC_DRMCODEC_H
