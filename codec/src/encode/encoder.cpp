// Encoder (paper, Table 1): quantize, check, choose the predictor, then walk
// the shared traversal with the true apex of every open edge and code its
// distance rank.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <cmath>
#include <cstdint>
#include <functional>
#include <future>
#include <optional>
#include <string>
#include <thread>

#include "concurrency.h"
#include "connectivity/connectivity_parts.h"
#include "encode/encoder.h"
#include "container/file_format.h"
#include "geometry/geometry_coders.h"
#include "mesh/manifold_cut.h"
#include "spatial/morton.h"
#include "spatial/morton_order.h"
#include "mesh/mesh_check.h"
#include "connectivity/ranked/edge_model.h"
#include "connectivity/ranked/predictor_selection.h"
#include "progress.h"
#include "mesh/quantize.h"
#include "entropy/rank_coder.h"
#include "mesh/repair_section.h"
#include "geometry/tree/spanning_tree.h"
#include "connectivity/topological/topological_coder.h"
#include "connectivity/traversal.h"
#include "mesh/vertex_order.h"
#include "spatial/spatial_index.h"
#include "connectivity/start_triangle.h"
#include "stats.h"

namespace drm {

namespace {

// Below this many faces the paper's method (no levers) is tried too, and
// kept where smaller: on meshes of a few hundred to 1,536 faces (torus,
// sphere, eight) the levers' contexts see too few codes to learn. From
// 4,096 faces, where the confidence contexts split finer
// (kFineBucketsFromFaces, edge_model.cpp), it never won on the corpus: its
// connectivity took 1.03 to 7.2 times the levers' on every mesh from 3,417
// to 19,994 faces (torus-2k 39 bytes against 38, else 1.2 times or more),
// so the attempt (one in six of such a mesh's connectivity attempts) is
// not made.
constexpr size_t kTryWithoutLeversBelowFaces = 4096;
// Below this many faces, the traversal is also started from
// kFirstVerticesTried - 1 other vertices, at the first multiples of
// 1 / kFirstVerticesSpread of the numbering, and in the input's order
// (encodeWithGeometry). Measured on the corpus, whole file in geometric
// mean against format 7: 0.9941 with the input's order alone, 0.9927 with
// one other vertex, 0.9919 with three, 0.9916 with seven; the corpus took
// 7 %, 9 % and 20 % more encoding time for them. Three were tried until
// the twenty-fifth session; one, a quarter of the way, now: the corpus's
// files 111 bytes larger in all (ten grow, couplingdown the most, by 0.38 %;
// with the vertex half way instead, turbine would grow by 0.54 %), its
// encoding 10 % less CPU, small meshes' 15 to 36 % (docs/speed.md).
constexpr size_t kTryStartsBelowFaces = 20000;
constexpr size_t kFirstVerticesTried = 2;
constexpr size_t kFirstVerticesSpread = 4;
// The early connectivity (encodeBeforeVertexSection) holds the traversal's
// tables while the vertex coder holds its own, so the peak memory is about
// their sum. On igea subdivided once (537,374 vertices) it takes the
// encoding from 2.6 to 1.6-1.8 s of wall time, the peak from 140 to 188-196
// MiB (367 to 382 bytes a vertex; issue 13's goal: under 400) when the
// vertex section keeps to one thread (below) and the drm tool maps large
// blocks on their own (tools/cli.cpp, mapLargeBlocksApart). On igea
// subdivided twice (2,149,490 vertices) it takes the encoding from 11.7-12.2
// to 7.9-8.0 s, the peak from 479 to 728 MiB (355 bytes a vertex); larger
// meshes code the two stages in turn, for memory. (Until the numbering put
// points on one grid point in input order, connectivityOrder, igea x16's
// early connectivity was coded in vain and then again: 14.5 s.)
constexpr size_t kEarlyConnectivityUpToVertices = size_t(1) << 22;
// Above this many vertices, a vertex section coded beside the early
// connectivity keeps to one thread: its own second one (the graph's
// halves, the forest built beside the cheapest-first tree) added its tables
// to the two stages' (igea x4: 197-207 MiB and 1.8-2.1 s, against 191-199
// MiB and 1.6-1.8 s, blocks of 4 MiB and more mapped apart).
constexpr size_t kSectionThreadsBesideUpToVertices = size_t(1) << 18;
// Up to this many vertices, refine's attempts run beside the tree's, each
// after its estimate on that estimate's thread: the three attempts are
// held at once (on larger meshes they come one after the other, as
// before).
constexpr size_t kRefineAttemptsBesideUpToVertices = size_t(1) << 18;
// An attempt beside is made at once where its estimate would be worth it
// against a file this many times the tree's vertex section (the
// connectivity and the rest: 1.02 to 1.33 on the corpus's meshes that
// try refine, cycloidal 1.57, star-cgal's 14 vertices 2.3);
// else it waits for the tree's attempt to tell its total.
constexpr double kSureTreeTotal = 1.2;
// Below this many faces, the connectivity is also coded over the vertex
// section's order (formats 1 to 8; kFlagSectionNumbering) besides Morton
// order, and the smaller file kept. Regular meshes break their many ties
// between equal distances better in the tree's order, a walk over the
// surface: torus-2k's connectivity took 57 bytes in Morton order, 38 in
// the tree's.
constexpr size_t kTrySectionNumberingBelowFaces = 20000;
// The topological attempt (ConnectivityCoder::Auto) gives up when its
// projected size passes the ranks' file by this factor.
constexpr double kTopologicalGiveUp = 1.05;
// Hubs: the distance ranks' searches around a vertex of d faces cost about
// d^2 in all (its neighbours lie about it at like distances), so that a
// disc of 4,000 triangles fanned around its centre took 1.5 s to encode,
// 10,000 of them 5.8 s; the topological coder takes 0.02 s. Where the faces
// at each vertex, squared and summed, pass this floor and this much a face,
// Auto codes topologically alone (the ranks only if that cannot be coded).
// Ordinary meshes sum about 18 a face (valence 6); the corpus's most, crank
// (a vertex of 132 faces), stays far below.
constexpr uint64_t kHubWorkFloor = uint64_t(1) << 22;
constexpr uint64_t kHubWorkPerFace = 64;

// Whether a mesh has hubs enough for the ranks to take quadratic time
// (kHubWorkFloor). Indices in range (checkIndices).
bool hasHubs(const Mesh& mesh) {
    std::vector<uint32_t> facesAt(mesh.vertexCount(), 0);
    for (uint32_t v : mesh.triangles) ++facesAt[v];
    uint64_t work = 0;
    for (uint32_t d : facesAt) work += uint64_t(d) * d;
    return work > kHubWorkFloor + kHubWorkPerFace * uint64_t(mesh.faceCount());
}

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
// order (Morton order or the section's, format 9) and the faces renumbered
// into it, with their topology and the predictor. Connectivity is coded
// over the renumbered faces, because ties between equal distances are
// broken by the indices the decoder will see.
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
// component reached, as formats 1 to 7 did (the corpus's CAD meshes often
// list their faces in an order the traversal likes: teapot's ranks cost
// 15 % less so); firstVertex is not used.
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

// Writes the attempt's file with the given vertex section. An attempt
// whose section is not coded yet (encodeBeforeVertexSection; lowBits 0, so
// no second pass) is written with an empty one, then again once it is:
// attempts over the same vertex section differ only in their other parts,
// so the smaller of two files is the same either way.
void writeAttempt(Attempt& attempt, GeometryCoder coder, std::vector<uint8_t> geometry) {
    attempt.header.geometryCoder = coder;
    attempt.geometry = std::move(geometry);
    FileParts written;
    attempt.encoded.bytes = writeFile(attempt.header, attempt.connectivity, attempt.geometry, attempt.vertexOrder,
                                      attempt.repairs, {}, &written);
    fillStatsFromHeader(attempt.encoded.stats, written, attempt.encoded.bytes.size());
}

// The faces one rank stream codes: a whole mesh's, or one of format 11's
// two parts (connectivity_parts.h). Both parts read the numbered mesh's
// faces and topology, passing over the other part's faces (copies of them
// cost igea x4's encoding 50 MiB at its peak); part 2 numbers its vertices
// from the split on.
struct RankStreamFaces {
    enum class Part { Whole, First, Second } part = Part::Whole;
    const std::vector<int32_t>* grid = nullptr;  // x, y, z of the stream's vertices
    uint32_t split = 0;                          // parts: where part 2's vertices begin
    size_t faceCount = 0;                        // the stream's
    const std::vector<uint32_t>* kept = nullptr;  // part 2: its vertices never culled
};
struct CodedRanks {
    bool complete = true;  // a part may leave faces no start reaches (below)
    std::vector<uint8_t> bytes;
    uint64_t components = 0;
    std::vector<uint32_t> faceOrder;  // numbered faces in decoded order (when the mesh was repaired)
    std::vector<uint32_t> triangles;  // as decoded, over the stream's vertices
};

// The smallest vertex of numbered face f: below the split, the face is part 1's.
uint32_t smallestVertex(const std::vector<uint32_t>& t, uint32_t f) {
    return std::min({t[3 * size_t(f)], t[3 * size_t(f) + 1], t[3 * size_t(f) + 2]});
}

// Walks the traversal over s's faces with their true apexes and codes each
// edge's rank (paper, Table 1). Ranks and the rank histogram go into result.
CodedRanks codeRanks(const RankStreamFaces& s, const PreparedMesh& prepared, const NumberedMesh& numbered,
                     const EncodeOptions& options, const ComponentStarts& starts, Encoded& result,
                     ProgressReporter& progress, double progressFrom, double progressSpan) {
    using Part = RankStreamFaces::Part;
    CodedRanks out;
    const MeshTopology& topology = numbered.topology;
    const std::vector<uint32_t>& t = numbered.triangles;
    const std::vector<int32_t>& grid = *s.grid;
    const size_t faceCount = s.faceCount;
    const size_t traversalVertices = grid.size() / 3;
    const uint32_t offset = s.part == Part::Second ? s.split : 0;  // numbered index of the stream's vertex 0
    auto inStream = [&](uint32_t face) {
        return s.part == Part::Whole || (smallestVertex(t, face) < s.split) == (s.part == Part::First);
    };
    Stats& stats = result.stats;
    const std::unique_ptr<SpatialIndex> candidates = makeSpatialIndex(grid, options.index, IndexRole::Traversal);
    Traversal traversal(traversalVertices, faceCount, candidates.get());
    EdgeModel model(grid, options.bits - numbered.lowBits, numbered.predictor, options.curvature, options.levers,
                    faceCount, *candidates, traversal);
    if (s.part == Part::First) {
        model.setSeam(s.split);
        for (size_t v = s.split; v < traversalVertices; ++v) traversal.keepVertex(uint32_t(v));
    }
    if (s.part == Part::Second) {
        for (uint32_t v : *s.kept) traversal.keepVertex(v);
        model.setFirstPartBelowKey(mortonKeyOf(grid.data()));
    }
    RankEncoder coder(model.contextCount(), model.boundaryFlags());

    if (prepared.repaired) out.faceOrder.reserve(faceCount);
    size_t attachedCount = 0;
    StartCursor cursor(traversal);
    uint32_t lastStart = 0;
    auto codeComponentFrom = [&](uint32_t v, uint32_t givenFace) {
        // givenFace, or of the faces at v the one whose other two vertices
        // cost the fewest bits; rotated to begin at v, orientation kept.
        uint32_t f = 0, second = 0, third = 0;
        int fewestBits = 1 << 30;
        const uint32_t at = v + offset;
        for (uint32_t e = topology.start[at]; e < topology.start[at + 1]; ++e) {
            const uint32_t face = topology.out[e].face;
            if ((givenFace != kNoIndex && face != givenFace) || !inStream(face)) continue;
            const uint32_t b = topology.out[e].to - offset;
            // The face's third vertex: its three are distinct, so the xor
            // of all three, less v and b.
            const uint32_t c = (t[3 * size_t(face)] ^ t[3 * size_t(face) + 1] ^ t[3 * size_t(face) + 2] ^ at ^ (b + offset)) - offset;
            const int bits = bitLength(uint64_t(startGap(v, b, traversalVertices)) + 1) +
                             bitLength(uint64_t(startGap(v, c, traversalVertices)) + 1);
            if (bits < fewestBits) {
                fewestBits = bits;
                f = face;
                second = b;
                third = c;
            }
        }
        const uint32_t from = cursor.at(lastStart);
        coder.putStartGap(StartField::Skipped, uint32_t((uint64_t(v) + traversalVertices - from) % traversalVertices));
        coder.putStartGap(StartField::Second, startGap(v, second, traversalVertices));
        coder.putStartGap(StartField::Third, startGap(v, third, traversalVertices));
        lastStart = v;
        ++out.components;
        ++attachedCount;
        if (prepared.repaired) out.faceOrder.push_back(f);
        traversal.startComponent(v, second, third);
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            uint32_t face = 0;
            uint32_t apex = topology.apexAcross(edge.vi + offset, edge.vj + offset, &face);
            if (apex != kNoVertex && !inStream(face)) apex = kNoVertex;  // the other part's: the seam
            if (apex != kNoVertex) apex -= offset;
            uint32_t rank = 0;
            // With boundary flags a boundary edge's rank 0 is the flag alone:
            // its candidates and context are not worked out (as decoding).
            const EdgeForecast& forecast = model.forecastBoundary(edge);
            if (apex != kNoVertex || !model.boundaryFlags()) model.forecastRank(edge);
            const int context = forecast.context, boundaryClass = forecast.boundaryClass;
            if (apex == kNoVertex) {
                traversal.closeAsBoundary(edge);
            } else {
                if (!model.admissible(apex, edge))
                    throw Error(ErrorKind::Internal, "internal error: the apex of face " + std::to_string(face) +
                                " is not a candidate; the file would not decode");
                rank = model.rankOf(apex, edge);
                model.resolved(apex);
                traversal.attachApex(edge, apex);
                if (prepared.repaired) out.faceOrder.push_back(face);
                result.faceRank[prepared.inputFace.empty() ? face : prepared.inputFace[face]] = rank;
                ++attachedCount;
            }
            coder.put(rank, context, boundaryClass);
            if (rank >= stats.rankHistogram.size()) stats.rankHistogram.resize(size_t(rank) + 1, 0);
            ++stats.rankHistogram[rank];
            progress.tick(progressFrom + progressSpan * double(attachedCount) / double(faceCount));
        }
    };
    auto startsAComponent = [&](uint32_t v) {
        if (traversal.isTouched(v)) return false;
        for (uint32_t e = topology.start[v + offset]; e < topology.start[v + offset + 1]; ++e)
            if (inStream(topology.out[e].face)) return true;
        return false;
    };
    if (starts.order == ComponentStarts::Order::InputFaces) {
        for (size_t f = 0; f < t.size() / 3; ++f)
            if (inStream(uint32_t(f)) && !traversal.isTouched(t[3 * f] - offset)) codeComponentFrom(t[3 * f] - offset, uint32_t(f));
    } else if (starts.firstVertex != kNoVertex && startsAComponent(starts.firstVertex)) {
        codeComponentFrom(starts.firstVertex, kNoIndex);
    }
    for (uint32_t v = 0; v < traversalVertices; ++v)
        if (startsAComponent(v)) codeComponentFrom(v, kNoIndex);

    if (attachedCount != faceCount) {
        // A part-2 component whose every vertex is kept and was reached
        // from other components (a triangle bordered by the seam on all
        // sides, touching the rest at its corners) has no untouched vertex
        // to start from: the caller codes the mesh in one part instead.
        // Part 1 cannot: each of its components has a vertex below the
        // split, whose faces are all part 1's, in one fan.
        if (s.part == Part::Second) {
            out.complete = false;
            return out;
        }
        throw Error(ErrorKind::Internal, "internal error: the traversal reached " + std::to_string(attachedCount) + " of " +
                    std::to_string(faceCount) + " faces");
    }
    out.bytes = coder.finish();
    out.triangles = traversal.takeTriangles();
    return out;
}

// Format 11: whether this attempt may split its connectivity in two parts
// (splitFaces has the last word).
bool maySplitConnectivity(const NumberedMesh& numbered, const EncodeOptions& options) {
    const size_t faces = numbered.triangles.size() / 3;
    if (numbered.vertexCount < 2 || faces == 0) return false;
    if (options.connectivityParts == 2) return true;
    return options.connectivityParts == 0 && numbered.mortonNumbering && faces >= kTwoPartsFromFaces;
}
// Unless asked for two parts whatever they cost, a mesh whose shortest seam
// has more edges than this share of its faces stays whole. The split costs
// a mesh 0.06 to 0.44 % of its file where the seam is shorter (21 corpus
// meshes: about 100 bytes for the second part's tables learning anew, and
// its edges coded as boundary edges on both sides); the CAD meshes cycloidal
// (1.8 % of its faces, 2.3 % larger) and octopus (1.0 %, 0.54 %) stay whole.
constexpr double kLongestSeamPerFace = 0.009;

// Where format 11 splits the numbered vertices: of the indices that leave
// 45 to 55 % of the faces in the first part, the one with the fewest seam
// edges (each is coded as a boundary edge in both parts), the one nearest
// the middle of equals. On a mesh of several pieces the seam can then run
// between them.
//
// An edge (u, w) between faces whose smallest vertices are a <= b lies on
// the seam of a split at m when a < m <= b (its faces fall in different
// parts; both of its ends are then from m on, since b <= min(u, w)): so
// every split's seam is counted at once, from a difference array.
struct Split {
    uint32_t at = 1;
    int64_t seamEdges = 0;
    bool even = true;  // 45 to 55 % of the faces in part 1
};
Split splitIndex(const NumberedMesh& numbered, const std::vector<uint32_t>& smallest) {
    const size_t faces = smallest.size(), n = numbered.vertexCount;
    const MeshTopology& topology = numbered.topology;
    std::vector<int64_t> below(n + 1, 0), seamChange(n + 2, 0);
    for (uint32_t v : smallest) ++below[v + 1];
    for (size_t i = 1; i <= n; ++i) below[i] += below[i - 1];  // faces whose smallest vertex lies below i
    // Each interior edge once, from the side where it runs up (a boundary
    // edge, met from one side only, is on no seam), in vertex order: the
    // edge back is then looked up among near vertices' edges.
    for (uint32_t u = 0; u < n; ++u)
        for (uint32_t e = topology.start[u]; e < topology.start[u + 1]; ++e) {
            const uint32_t w = topology.out[e].to, f = topology.out[e].face;
            if (u > w) continue;
            const uint32_t other = topology.faceOf(w, u);
            if (other == kNoIndex) continue;
            const uint32_t a = std::min(smallest[f], smallest[other]), b = std::max(smallest[f], smallest[other]);
            ++seamChange[a + 1];  // on the seam for m in a + 1 .. b
            --seamChange[b + 1];
        }
    uint32_t best = 0;
    int64_t bestSeam = INT64_MAX, seam = 0;
    double bestOff = 1;
    for (size_t m = 1; m < n; ++m) {
        seam += seamChange[m];
        const double off = std::abs(double(below[m]) / double(faces) - 0.5);
        if (off > 0.05) continue;
        if (seam < bestSeam || (seam == bestSeam && off < bestOff)) {
            best = uint32_t(m);
            bestSeam = seam;
            bestOff = off;
        }
    }
    if (best != 0) return {best, bestSeam};
    // No index splits the faces that evenly (a few huge fans): the median.
    Split median;
    median.even = false;
    seam = 0;
    for (median.at = 1; median.at < n - 1 && 2 * size_t(below[median.at]) < faces; ++median.at) seam += seamChange[median.at];
    median.seamEdges = seam + seamChange[median.at];
    return median;
}

// Format 11's two parts of the numbered mesh's faces (connectivity_parts.h):
// where they split, part 2's vertices, and those of them never culled.
struct SplitFaces {
    uint32_t split = 0;
    size_t firstFaces = 0;
    std::vector<int32_t> secondGrid;
    std::vector<uint32_t> keptInSecond;
};
bool splitFaces(const NumberedMesh& numbered, bool whateverItCosts, SplitFaces& parts) {
    const std::vector<uint32_t>& t = numbered.triangles;
    const size_t faces = t.size() / 3, n = numbered.vertexCount;
    std::vector<uint32_t> smallest(faces);
    for (size_t f = 0; f < faces; ++f) smallest[f] = smallestVertex(t, uint32_t(f));
    const Split at = splitIndex(numbered, smallest);
    if (!whateverItCosts && (!at.even || double(at.seamEdges) > kLongestSeamPerFace * double(faces)))
        return false;  // a long seam, or parts too uneven to gain much from a second thread
    for (uint32_t v : smallest) parts.firstFaces += v < at.at ? 1 : 0;
    const uint32_t m = parts.split = at.at;
    parts.secondGrid.assign(numbered.decodedGrid.begin() + 3 * size_t(m), numbered.decodedGrid.end());
    // Part 2's vertices with two fans or more: as many of their part 2
    // edges out without a part 2 face on the other side (each fan that is
    // not closed ends on one).
    const MeshTopology& topology = numbered.topology;
    auto inSecond = [&](uint32_t face) { return face != kNoIndex && smallest[face] >= m; };
    for (size_t v = m; v < n; ++v) {
        int open = 0;
        for (uint32_t e = topology.start[v]; e < topology.start[v + 1]; ++e)
            if (inSecond(topology.out[e].face) && !inSecond(topology.faceOf(topology.out[e].to, uint32_t(v)))) ++open;
        if (open >= 2) parts.keptInSecond.push_back(uint32_t(v - m));
    }
    return true;
}

// The attempt's quantized and vertexOrder are left empty: only the attempt
// kept gets them, by move (encodeWithGeometry, encodeConnectivity).
// The repairs as the section stores them and undoCut replays them: an
// attempt's copies and faces repeating a vertex (in its decoded indices),
// the cut's flips and repeated faces in decoded face order (faceOrder:
// decoded face -> face of prepared.triangles).
Repairs repairsInDecodedOrder(const PreparedMesh& prepared, std::vector<uint32_t> copyOf, std::vector<uint32_t> looseTriangles,
                              const std::vector<uint32_t>& faceOrder) {
    Repairs out = prepared.repairs;
    out.copyOf = std::move(copyOf);
    out.looseTriangles = std::move(looseTriangles);
    std::vector<uint32_t> positionOf(faceOrder.size());
    for (size_t i = 0; i < faceOrder.size(); ++i) {
        out.flipped[i] = prepared.repairs.flipped[faceOrder[i]];
        positionOf[faceOrder[i]] = uint32_t(i);
    }
    for (uint32_t& face : out.duplicateOf) face = positionOf[face];
    return out;
}

Attempt encodeOnce(const PreparedMesh& prepared, const NumberedMesh& numbered, const EncodeOptions& options,
                   ProgressReporter& progress, const ComponentStarts& starts = ComponentStarts()) {
    Attempt attempt;
    Encoded& result = attempt.encoded;
    result.grid = prepared.grid;
    const size_t faceCount = numbered.triangles.size() / 3;
    const size_t looseCount = numbered.looseTriangles.size() / 3;
    const size_t duplicateCount = prepared.repairs.duplicateOf.size();

    FileHeader header;
    header.vertexCount = numbered.order.size();
    header.faceCount = faceCount + looseCount + duplicateCount;
    header.hasRepairs = prepared.repaired;
    header.copyCount = numbered.copyOf.size();
    header.grid = result.grid;
    header.predictor = numbered.predictor;
    header.geometryCoder = numbered.geometryCoder;
    header.keepsVertexOrder = options.keepVertexOrder;
    header.mortonNumbering = numbered.mortonNumbering;
    header.curvature = options.curvature;
    header.levers = options.levers;
    Stats& stats = result.stats;

    result.faceRank.assign(prepared.inputFaces, 0);
    progress.stage("ranking", 0.05);
    // The faces as the decoder will see them: only repairs refer to them.
    std::vector<uint32_t> decodedFaceOrder;
    std::vector<uint32_t> decodedTriangles;
    std::vector<uint8_t> connectivity;
    SplitFaces split;
    auto codeWhole = [&] {
        RankStreamFaces whole;
        whole.grid = &numbered.decodedGrid;
        whole.faceCount = faceCount;
        CodedRanks coded = codeRanks(whole, prepared, numbered, options, starts, result, progress, 0.05, 0.9);
        header.componentCount = coded.components;
        connectivity = std::move(coded.bytes);
        decodedFaceOrder = std::move(coded.faceOrder);
        decodedTriangles = std::move(coded.triangles);
    };
    if (!maySplitConnectivity(numbered, options) || !splitFaces(numbered, options.connectivityParts == 2, split)) {
        codeWhole();
    } else {
        using Part = RankStreamFaces::Part;
        RankStreamFaces first, second;
        first.part = Part::First;
        first.grid = &numbered.decodedGrid;
        first.split = split.split;
        first.faceCount = split.firstFaces;
        second.part = Part::Second;
        second.grid = &split.secondGrid;
        second.split = split.split;
        second.faceCount = faceCount - split.firstFaces;
        second.kept = &split.keptInSecond;
        const double share = double(split.firstFaces) / double(faceCount);
        const ComponentStarts smallest;
        CodedRanks a = codeRanks(first, prepared, numbered, options, smallest, result, progress, 0.05, 0.9 * share);
        CodedRanks b = codeRanks(second, prepared, numbered, options, smallest, result, progress, 0.05 + 0.9 * share,
                                 0.9 * (1 - share));
        if (!b.complete) {  // as if never split
            result.faceRank.assign(prepared.inputFaces, 0);
            stats.rankHistogram.clear();
            codeWhole();
        } else {
            ConnectivityParts layout;
            layout.split = split.split;
            layout.firstComponents = a.components;
            layout.firstFaces = split.firstFaces;
            layout.keptInSecond = std::move(split.keptInSecond);
            connectivity = writeConnectivityParts(layout, a.bytes, b.bytes);
            header.componentCount = a.components + b.components;
            header.twoParts = true;
            decodedFaceOrder = std::move(a.faceOrder);
            decodedFaceOrder.insert(decodedFaceOrder.end(), b.faceOrder.begin(), b.faceOrder.end());
            decodedTriangles = std::move(a.triangles);
            decodedTriangles.reserve(3 * faceCount);
            for (uint32_t v : b.triangles) decodedTriangles.push_back(v + split.split);
        }
    }
    progress.stage("writing", 0.95);
    const std::vector<uint8_t> vertexOrder =
        options.keepVertexOrder ? encodeVertexOrder(numbered.order) : std::vector<uint8_t>();
    // None for a mesh that needed none.
    Repairs inDecodedOrder;
    std::vector<uint8_t> repairs;
    if (prepared.repaired) {
        inDecodedOrder = repairsInDecodedOrder(prepared, numbered.copyOf, numbered.looseTriangles, decodedFaceOrder);
        repairs = encodeRepairs(inDecodedOrder, header.vertexCount);
    }
    std::vector<uint8_t> secondPass;
    const GeometryCoderEntry& geometryCoder = *geometryCoderOf(numbered.geometryCoder);
    if (geometryCoder.encodeAfterConnectivity) {
        // Refine's low bits, predicted across the triangles as the decoder
        // rebuilds them (vertex copies stand for their originals).
        std::vector<uint32_t> triangles = decodedTriangles;
        for (uint32_t& v : triangles)
            if (v >= header.vertexCount) v = numbered.copyOf[v - header.vertexCount];
        secondPass = geometryCoder.encodeAfterConnectivity(numbered.geometry, numbered.fineDecoded, numbered.lowBits,
                                                           triangles);
    }
    // The faces as the decoder will give them back (the traversal's own,
    // or the two parts' joined; moved, not copied: 12 bytes a face).
    attempt.decodedTriangles = std::move(decodedTriangles);
    if (prepared.repaired) undoCut(attempt.decodedTriangles, inDecodedOrder, size_t(header.vertexCount));
    if (options.keepVertexOrder)
        for (uint32_t& v : attempt.decodedTriangles) v = numbered.order[v];
    attempt.header = header;
    attempt.connectivity = std::move(connectivity);
    attempt.vertexOrder = vertexOrder;
    attempt.repairs = repairs;
    fillStatsFromTraversal(stats, numbered.lowBits, inDecodedOrder);
    writeAttempt(attempt, numbered.geometryCoder,
                 geometryCoder.encodeAfterConnectivity ? std::move(secondPass) : numbered.geometry);
    return attempt;
}

// Whether the encoder may run independent parts of its work on a second
// thread (EncodeOptions::threads). The file is the same either way.
bool secondThreadAllowed(const EncodeOptions& options) {
    return options.threads >= 2 || (options.threads == 0 && std::thread::hardware_concurrency() > 1);
}
// The threads a search may spread over: FLANN's batch search takes them all
// (every core by default, as before the encoder had threads of its own);
// the grid's splits take two of any count above one.
int threadsFor(const EncodeOptions& options) {
    if (options.threads != 0) return options.threads;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

// From this many vertices, refine's estimates give their coarse tree up
// where it clearly cannot pay (TreeBudget, refineGeometryEstimate): on
// smaller meshes they cost less, and there the extrapolation from the
// first vertices strays further (from 8,192 vertices on the corpus, at
// most mannequin's, 11,703 vertices, with 4 low bits: 1.6 % of the full
// tree's section above the end's figure at 4/16, 2.4 % at 3/16).
constexpr size_t kEstimateBudgetFromVertices = 8192;
// Larger meshes' estimates are not budgeted: the rival's figures (and a
// copy of the tree's section) would add to the encoder's peak memory, the
// vertex section being coded beside the early connectivity there
// (kSectionThreadsBesideUpToVertices).
constexpr size_t kEstimateBudgetUpToVertices = kSectionThreadsBesideUpToVertices;

// The full grid's cheapest-first tree (choices as flags, the frame on, over
// the 4 nearest) as refine's estimates measure themselves against it: what
// each vertex cost when picked, and its section's size in bits.
struct TreeRival {
    std::vector<float> pickBits;
    double bits = 0;
};

// The vertex section of one attempt: the coder asked for, or its fallback
// where that is no larger. `rival`: set by codeVertexSection where refine's
// estimates will follow (the tree asked for by Auto, over
// kAutoRefineAboveBitsPerVertex, on a mesh of kEstimateBudgetFromVertices
// to kEstimateBudgetUpToVertices).
struct VertexSection {
    const GeometryCoderEntry* coder = nullptr;
    GeometryEncoding encoding;
    TreeRival rival;
};

// `asked` is Refine exactly when lowBits > 0 (encodeConnectivity).
// `trials` (may be null): what an earlier call worked out on the same grid
// (refineGeometryEstimate's trees).
VertexSection codeVertexSection(const std::vector<int32_t>& quantized, const EncodeOptions& options,
                                GeometryCoder asked, int lowBits, GeometryTreeTrials* trials) {
    const std::vector<int32_t> coarse = lowBits > 0 ? coarsenGrid(quantized, lowBits) : std::vector<int32_t>();
    const std::vector<int32_t>& vertexGrid = lowBits > 0 ? coarse : quantized;
    VertexSection section;
    section.coder = geometryCoderOf(asked);
    // The tree's trials are kept here only where refine's estimates may
    // want a rival: a section returned from them is copied, not moved.
    const size_t vertexCount = vertexGrid.size() / 3;
    GeometryTreeTrials treeTrials;
    const bool rivalWanted = !trials && options.geometry == GeometryCoder::Auto && asked == GeometryCoder::SpanningTree &&
                             lowBits == 0 && vertexCount >= kEstimateBudgetFromVertices &&
                             vertexCount <= kEstimateBudgetUpToVertices;
    if (rivalWanted) {
        treeTrials.keepPickBits = true;
        trials = &treeTrials;
    }
    section.encoding = section.coder->encode(vertexGrid, options.bits - lowBits, options.index, trials, threadsFor(options));
    if (rivalWanted && 8.0 * double(section.encoding.bytes.size()) > kAutoRefineAboveBitsPerVertex * double(vertexCount)) {
        // The tree over the 4 nearest, choices as flags, the frame on: the estimates' own coding.
        const auto bits = treeTrials.pickBits.find(treeBitsKey(0, true, true));
        const auto coded = treeTrials.coded.find(sectionKey(true, 0, true, true));
        if (bits != treeTrials.pickBits.end() && coded != treeTrials.coded.end() && !coded->second.bytes.empty()) {
            section.rival.pickBits = std::move(bits->second);
            section.rival.bits = 8.0 * double(coded->second.bytes.size());
        }
    }
    // Scattered points (a soup of random triangles) predict no better
    // from their neighbours than from nothing: each fallback in turn is
    // kept where its section is no larger.
    const size_t vertices = std::max<size_t>(1, vertexGrid.size() / 3);
    for (const GeometryCoderEntry* fallback = section.coder->fallback; fallback; fallback = fallback->fallback) {
        if (8.0 * double(section.encoding.bytes.size()) < fallback->triedFromBitsPerVertex * double(vertices)) continue;
        GeometryEncoding alternative = fallback->encode(vertexGrid, options.bits - lowBits, options.index, nullptr, 1);
        if (alternative.bytes.size() <= section.encoding.bytes.size()) {
            section.coder = fallback;
            section.encoding = std::move(alternative);
        }
    }
    return section;
}

// Format 9's numbering of the vertices for the connectivity (morton_order.h):
// sectionOrder (decoded index -> input index) sorted stably by the Morton
// keys of the points of vertexGrid (input order). Returns connectivity
// index -> input index.
//
// Points on one grid point keep the section's order among themselves. The
// vertex coder lists them in whatever order its tree reached them, but
// being one point, which of them sits at which place of the section
// changes none of its bytes: so they are first put in input order there
// (sectionOrder is rewritten). The numbering is then the Morton order of
// the input, the one encodeBeforeVertexSection guesses before the section
// exists, and its connectivity is kept. Before, a single such pair
// reached in the other order made the guess wrong and the connectivity
// was coded twice (igea x16: 284 more points than grid points at 12 bits).
std::vector<uint32_t> connectivityOrder(const std::vector<int32_t>& vertexGrid, std::vector<uint32_t>& sectionOrder) {
    std::vector<int32_t> inSectionOrder(3 * sectionOrder.size());
    for (size_t d = 0; d < sectionOrder.size(); ++d)
        for (int k = 0; k < 3; ++k) inSectionOrder[3 * d + k] = vertexGrid[3 * size_t(sectionOrder[d]) + k];
    const std::vector<uint32_t> sorted = mortonOrder(inSectionOrder);
    auto samePoint = [&](uint32_t d, uint32_t e) {
        return inSectionOrder[3 * size_t(d)] == inSectionOrder[3 * size_t(e)] &&
               inSectionOrder[3 * size_t(d) + 1] == inSectionOrder[3 * size_t(e) + 1] &&
               inSectionOrder[3 * size_t(d) + 2] == inSectionOrder[3 * size_t(e) + 2];
    };
    std::vector<uint32_t> inputs;
    for (size_t i = 0; i < sorted.size();) {
        size_t end = i + 1;
        while (end < sorted.size() && samePoint(sorted[i], sorted[end])) ++end;
        if (end - i > 1) {
            // One point: its places in the section (sorted[i..end), in
            // increasing order, the sort being stable) take its vertices in
            // input order.
            inputs.clear();
            for (size_t j = i; j < end; ++j) inputs.push_back(sectionOrder[sorted[j]]);
            std::sort(inputs.begin(), inputs.end());
            for (size_t j = i; j < end; ++j) sectionOrder[sorted[j]] = inputs[j - i];
        }
        i = end;
    }
    std::vector<uint32_t> order(sorted.size());
    for (size_t i = 0; i < sorted.size(); ++i) order[i] = sectionOrder[sorted[i]];
    return order;
}

// Numbers the cut mesh in numbered.order (connectivity index -> input
// index; the caller sets it and the vertex section's fields), over the
// points of vertexGrid (input order), and encodes the connectivity from
// every start tried, and without levers where that is tried.
Attempt encodeNumbered(const Mesh& mesh, const PreparedMesh& prepared, const ManifoldCut& cut,
                       const EncodeOptions& options, NumberedMesh& numbered, const std::vector<int32_t>& vertexGrid,
                       ProgressReporter& progress) {
    const size_t copies = cut.copyOf.size();
    numbered.vertexCount = mesh.vertexCount() + copies;
    {
        // Decoded indices: the connectivity's numbering, then the copies in the
        // cut's order (each at its original's position). Freed once the faces
        // are renumbered (4 bytes a vertex at the traversal's peak).
        std::vector<uint32_t> decodedIndex(numbered.vertexCount);
        numbered.decodedGrid.resize(3 * decodedIndex.size());
        for (size_t d = 0; d < numbered.order.size(); ++d) {
            decodedIndex[numbered.order[d]] = uint32_t(d);
            for (int k = 0; k < 3; ++k) numbered.decodedGrid[3 * d + k] = vertexGrid[3 * size_t(numbered.order[d]) + k];
        }
        // Copies are numbered in the decoded order of their originals, so the
        // repairs section can list the originals as small differences.
        std::vector<uint32_t> copiesByOriginal(copies);
        for (size_t c = 0; c < copies; ++c) copiesByOriginal[c] = uint32_t(c);
        std::stable_sort(copiesByOriginal.begin(), copiesByOriginal.end(), [&](uint32_t x, uint32_t y) {
            return decodedIndex[cut.copyOf[x]] < decodedIndex[cut.copyOf[y]];
        });
        numbered.copyOf.resize(copies);
        for (size_t r = 0; r < copies; ++r) {
            const uint32_t c = copiesByOriginal[r], original = cut.copyOf[c];
            const size_t d = mesh.vertexCount() + r;
            decodedIndex[mesh.vertexCount() + c] = uint32_t(d);
            numbered.copyOf[r] = decodedIndex[original];
            for (int k = 0; k < 3; ++k) numbered.decodedGrid[3 * d + k] = vertexGrid[3 * size_t(original) + k];
        }
        numbered.looseTriangles.resize(cut.looseTriangles.size());
        for (size_t c = 0; c < cut.looseTriangles.size(); ++c)
            numbered.looseTriangles[c] = decodedIndex[cut.looseTriangles[c]];
        const std::vector<uint32_t>& triangles = *prepared.triangles;
        numbered.triangles.resize(triangles.size());
        for (size_t c = 0; c < triangles.size(); ++c) numbered.triangles[c] = decodedIndex[triangles[c]];
    }
    {
        checkIndices(numbered.triangles, numbered.vertexCount);
        if (prepared.codableAsGiven) {
            // Renumbered faces of a mesh that passed: the check would find
            // nothing (igea's encode 5.98 G -> 5.84 G instructions without it).
            buildTopology(numbered.triangles, numbered.vertexCount, &numbered.topology);
        } else {
            const std::string problem = topologyProblem(numbered.triangles, numbered.vertexCount, &numbered.topology);
            if (!problem.empty())
                throw Error(ErrorKind::Internal,
                            "internal error: the mesh cut into manifold pieces is still not codable: " + problem);
        }
    }

    numbered.predictor = options.predictor;
    if (numbered.predictor == Predictor::Auto) {
        progress.stage("choosing predictor", 0.04);
        numbered.predictor =
            countPredictorVotes(numbered.triangles, numbered.vertexCount, numbered.topology, numbered.decodedGrid).winner();
    }
    // Where the traversal starts changes every rank after it: over 11
    // start vertices block's connectivity took 374 to 418 bytes, fandisk's
    // 380 to 427, bunny's 2071 to 2121. Small meshes try several starts.
    std::vector<ComponentStarts> startsToTry(1);
    const size_t faces = numbered.triangles.size() / 3;
    if (options.searchStarts && faces < kTryStartsBelowFaces) {
        // First vertices spread over the numbering, each moved on to the
        // next vertex in a face; none tried twice, nor the default's.
        const std::vector<uint32_t>& edgesFrom = numbered.topology.start;
        auto inAFace = [&](size_t v) { return edgesFrom[v] != edgesFrom[v + 1]; };
        std::vector<uint32_t> tried;
        for (size_t k = 0; k < kFirstVerticesTried; ++k) {
            size_t v = k * numbered.vertexCount / kFirstVerticesSpread;
            while (v < numbered.vertexCount && !inAFace(v)) ++v;
            if (v == numbered.vertexCount || std::find(tried.begin(), tried.end(), uint32_t(v)) != tried.end()) continue;
            tried.push_back(uint32_t(v));
            if (k > 0) startsToTry.push_back({ComponentStarts::Order::SmallestVertices, uint32_t(v)});
        }
        startsToTry.push_back({ComponentStarts::Order::InputFaces, kNoVertex});
    }
    // The attempts only read what they share: with a second thread it
    // takes every other start. Each thread keeps its smallest attempt, the
    // first of equals; of the two the smaller is kept, the earlier start of
    // equals: the attempt the loop over the starts in turn keeps.
    struct Kept {
        Attempt attempt;
        size_t start = SIZE_MAX;
    };
    auto tryStarts = [&](size_t first, size_t step, ProgressReporter& reporter) {
        Kept kept;
        for (size_t k = first; k < startsToTry.size(); k += step) {
            Attempt attempt = encodeOnce(prepared, numbered, options, reporter, startsToTry[k]);
            if (kept.start == SIZE_MAX || attempt.encoded.bytes.size() < kept.attempt.encoded.bytes.size())
                kept = {std::move(attempt), k};
        }
        return kept;
    };
    const Progress silent;  // the second thread's attempts report nothing
    ProgressReporter quiet(silent);
    std::future<Kept> beside;  // declared after what the thread reads: destroyed (and waited for) first
    const size_t step = startsToTry.size() > 1 && secondThreadAllowed(options) ? 2 : 1;
    if (step == 2) beside = startBeside([&] { return tryStarts(1, 2, quiet); });
    Kept here = tryStarts(0, step, progress);
    if (beside.valid()) {
        Kept other = beside.get();
        const size_t a = here.attempt.encoded.bytes.size(), b = other.attempt.encoded.bytes.size();
        if (b < a || (b == a && other.start < here.start)) here = std::move(other);
    }
    Attempt best = std::move(here.attempt);
    const ComponentStarts bestStarts = startsToTry[here.start];
    const bool anyLever = options.levers.topologicalFilter || options.levers.gapClosing ||
                          options.levers.confidenceContext || options.levers.angleOrder ||
                          options.levers.frontNeighbours || options.levers.boundaryFlag;
    if (options.tryWithoutLevers && anyLever && faces < kTryWithoutLeversBelowFaces) {
        EncodeOptions plain = options;
        plain.levers = Levers::none();
        Attempt alternative = encodeOnce(prepared, numbered, plain, progress, bestStarts);
        if (alternative.encoded.bytes.size() < best.encoded.bytes.size()) best = std::move(alternative);
    }
    best.encoded.vertexOrder = std::move(numbered.order);
    if (options.keepVertexOrder)
        for (size_t v = 0; v < best.encoded.vertexOrder.size(); ++v) best.encoded.vertexOrder[v] = uint32_t(v);
    return best;
}

// Codes the vertex set with the given coder (lowBits > 0: Refine), numbers
// the cut mesh for the connectivity and encodes it.
// `trials` (may be null): what an earlier call worked out on the same grid
// (refineGeometryEstimate's trees). `given` (may be null): the vertex
// section already coded for this attempt (codeVertexSection), taken.
// `early` (may be null; lowBits 0 only): the connectivity coded before the
// vertex section was (encodeBeforeVertexSection); its attempt is taken
// where its numbering is the section's, and freed either way.
Attempt encodeWithGeometry(const Mesh& mesh, const PreparedMesh& prepared, const ManifoldCut& cut,
                           const EncodeOptions& options, int lowBits, ProgressReporter& progress,
                           GeometryTreeTrials* trials = nullptr, VertexSection* given = nullptr,
                           EarlyConnectivity* early = nullptr) {
    progress.stage("coding vertices", 0.01);
    VertexSection section =
        given ? std::move(*given) : codeVertexSection(prepared.quantized, options, options.geometry, lowBits, trials);
    const std::vector<int32_t> coarse = lowBits > 0 ? coarsenGrid(prepared.quantized, lowBits) : std::vector<int32_t>();
    const std::vector<int32_t>& vertexGrid = lowBits > 0 ? coarse : prepared.quantized;
    // Small meshes also try the section's numbering (see kTrySectionNumberingBelowFaces).
    const bool trySectionNumbering = options.searchStarts && prepared.triangles->size() / 3 < kTrySectionNumberingBelowFaces;
    auto encodeInOrder = [&](std::vector<uint32_t> order, bool morton) {
        NumberedMesh numbered;
        numbered.lowBits = lowBits;
        numbered.geometryCoder = section.coder->id;
        numbered.geometry = trySectionNumbering ? section.encoding.bytes : std::move(section.encoding.bytes);
        numbered.order = std::move(order);
        numbered.mortonNumbering = morton;
        if (lowBits > 0) {
            numbered.fineDecoded.resize(3 * numbered.order.size());
            for (size_t d = 0; d < numbered.order.size(); ++d)
                for (int k = 0; k < 3; ++k)
                    numbered.fineDecoded[3 * d + k] = prepared.quantized[3 * size_t(numbered.order[d]) + k];
        }
        return encodeNumbered(mesh, prepared, cut, options, numbered, vertexGrid, progress);
    };
    if (section.coder->keepsInputOrder) {
        if (early) *early = EarlyConnectivity();
        return encodeInOrder(std::move(section.encoding.order), false);
    }
    Attempt best;
    // The early attempt's numbering is the one this section gives: wherever
    // no two points coincide, certainly; elsewhere connectivityOrder makes
    // it so, and the comparison is a safeguard.
    std::vector<uint32_t> order;
    if (!early || !early->certain) order = connectivityOrder(vertexGrid, section.encoding.order);
    if (early && (early->certain || early->order == order)) {
        writeAttempt(early->attempt, section.coder->id, section.encoding.bytes);
        best = std::move(early->attempt);
        order = std::move(early->order);
    } else {
        best = encodeInOrder(order, true);
    }
    if (early) *early = EarlyConnectivity();
    // Sorted points come in Morton order already: nothing else to try.
    if (trySectionNumbering && order != section.encoding.order) {
        Attempt alternative = encodeInOrder(std::move(section.encoding.order), false);
        if (alternative.encoded.bytes.size() < best.encoded.bytes.size()) best = std::move(alternative);
    }
    return best;
}

// The first attempt's connectivity, coded before its vertex section
// (encodeConnectivity) in the numbering that section will most likely give:
// Morton order (format 9), points on one grid point in input order. Where
// no two points coincide, that is certain; elsewhere connectivityOrder
// puts such points in input order too, and encodeWithGeometry compares the
// two numberings before it keeps the attempt.
// The file is written with an empty vertex section until encodeWithGeometry
// adds the section.
EarlyConnectivity encodeBeforeVertexSection(const Mesh& mesh, const PreparedMesh& prepared, const ManifoldCut& cut,
                                            const EncodeOptions& options, ProgressReporter& progress) {
    EarlyConnectivity early;
    early.order = mortonOrder(prepared.quantized);
    early.certain = !hasCoincidentPoints(prepared.quantized, early.order);
    NumberedMesh numbered;
    numbered.order = early.order;
    early.attempt = encodeNumbered(mesh, prepared, cut, options, numbered, prepared.quantized, progress);
    return early;
}

// GeometryCoder::Auto: the tree, and where it spends more than
// kAutoRefineAboveBitsPerVertex also refine with kAutoRefineLowBits (drm.h);
// refine is kept where its file is at least kAutoRefineMinimumGainPercent
// smaller, since it decodes 20-30 % slower (a second pass over the
// triangles, ranks on a coarser grid). Measured on the corpus at 12 bits:
// refine never wins where the tree is cheap (scans sampled finer than the
// grid: bunny, igea, fandisk grow by 5-60 %); where it wins, 4 low bits is
// nearly always best (armadillo -14 %, dinosaur -12 %, horse-lres -7 %) and
// 2 the rest (genus3 -11 %); trying 1..5 finds little more for three times
// the work.
constexpr double kRefineMinimumGain = kAutoRefineMinimumGainPercent / 100.0;
// Meshes this small decode in well under a millisecond either way: refine
// is tried and kept wherever it is smaller (star-cgal, 14 vertices: 125
// bytes with refine against the tree's 128, 2.3 % smaller).
constexpr size_t kRefineAnyGainBelowVertices = 1000;
// Below this many vertices, meshes decode in a few milliseconds either
// way: a refine attempt is made where its estimate, within its slack
// (kRefineEstimateSlack), promises a 1 % smaller file, and kept wherever it
// is smaller (mech-holes-shark, 5,246 vertices:
// 8,605 bytes with refine against the tree's 8,819, 2.4 % smaller, decoded
// in 34.4 ms of CPU against 32.2, whole process). Until the twenty-fourth
// session both asked 3 % here too; the tree's neighbour counts then took
// mech-holes-shark's tree within 3 % of refine, and its file would have
// grown. An estimate promising any gain at all would make attempts that
// lose (blobby: encoding twice as long, the same file).
constexpr size_t kRefineSmallMeshBelowVertices = 8192;
constexpr double kRefineSmallMeshEstimatedGain = 0.01;

// Where the coarse grid leaves nearest neighbours at most this many coarse
// steps apart (the spacing the geometry tree measures), the connectivity
// ranked on it costs at least kCrowdedConnectivityGrowth bits per vertex
// more than on the full grid: neighbours crowd into ties. Measured on the
// corpus at 12 bits with 4 low bits (coarse spacing 1.4 to 2.8): 0.85
// (horse-lres) to 1.37 (dinosaur-24k) bits per vertex more; with 2 low bits
// the spacing is 6 or more and the growth under 0.05. A refine attempt whose
// vertex bits cannot pay for that growth as well is not made (feline: the
// estimate saved 1.05 bits per vertex, the connectivity grew by 1.26).
constexpr double kCrowdedCoarseSpacing = 3.0;
constexpr double kCrowdedConnectivityGrowth = 0.6;

// The estimate codes one coarse tree where the attempt keeps the smallest
// of several, so it may come out a little over the attempt's vertex bits
// (genus3 with 2 low bits at format 7: estimate 9109 bytes, attempt 8981,
// 1.4 % over): an attempt is made where the estimate misses the gain asked
// by no more than this share of the tree's geometry.
constexpr double kRefineEstimateSlack = 0.015;

// Refine's vertex bits without the traversal: the low bits predicted
// across the input's triangles (the traversal rebuilds them in another
// order, which changes the refinement's size little), and the tree over the
// coarse grid. Decides whether a whole refine attempt is worth making; the
// tree it grows and codes is left in `trials` for that attempt. One tree
// only, the cheapest-first with its choices as flags: refine's own coarse
// tree takes the smallest of several (encodeRefineCoarse), which the
// estimate leaves to the attempt, so it may come out a little over the
// attempt's figure (kRefineEstimateSlack: genus3 with 2 low bits, 1.4 %
// at format 7). It spares a second tree on the coarse grid wherever refine
// is not tried (venus, feline with 2 low bits).
// Past skipAbove the exact figure does not matter (the caller skips the
// attempt): SIZE_MAX is returned as soon as the estimate must exceed it.
//
// The refinement comes first, over the input's numbering (it visits the
// vertices as the triangles reach them, then those in no triangle in index
// order: numbered in the coarse tree's order, as until the twenty-fifth
// session, it took the same bytes on every corpus mesh), so that the
// coarse tree knows the room left to it. With a rival (the full grid's
// tree, TreeRival), the coarse tree is then given up once it clearly
// cannot fit the room budgetAbove leaves (TreeBudget): until then venus
// grew both coarse trees to the end for estimates that missed by 6 and
// 11 %. Where the tree is not given up the estimate is the same figure.
// budgetAbove is the same bound whatever the threads (the estimates
// beside the tree's attempt know no looser one), so that which trees are
// given up, and so the file, does not depend on them.
//
// How far the coarse tree's extrapolated section may run over its room
// before it is given up, as a share of the rival's section. On the
// corpus's meshes of 8,192 vertices or more, from 4/16 of the vertices on,
// the extrapolation came within 1.6 % of the end's figure where it was
// above it (mannequin with 4 low bits; dinosaur-24k with 2, 1.5 %); the
// trees given up (venus, nefertiti-50k, tower-holes, pinocchio,
// dragon-res3, falconstatue-boundary, cycloidal, chinese-dragon-10k,
// rocker-arm, venus-lres, both low-bit counts each) ran 4.0 to 39 % over
// at 4/16; feline's, whose estimates miss by less, are grown to the end.
constexpr double kEstimateGiveUpMargin = 0.03;
size_t refineGeometryEstimate(const std::vector<int32_t>& quantized, const std::vector<uint32_t>& triangles, int bits,
                              int lowBits, NeighbourIndex index, GeometryTreeTrials& trials, double skipAbove,
                              double budgetAbove, const TreeRival* rival) {
    if (skipAbove < 0) return SIZE_MAX;
    const Refinement refinement =
        encodeRefinement(quantized, lowBits, triangles, skipAbove < double(SIZE_MAX / 2) ? size_t(skipAbove) : SIZE_MAX);
    if (refinement.overBudget) return SIZE_MAX;
    const double room = skipAbove - double(refinement.bytes.size());
    TreeBudget budget;
    const bool budgeted = rival && !rival->pickBits.empty();
    if (budgeted) {
        budget.rivalPickBits = &rival->pickBits;
        budget.rivalBits = rival->bits;
        budget.bits = 8.0 * (budgetAbove - double(refinement.bytes.size()));
        budget.margin = kEstimateGiveUpMargin * rival->bits;
    }
    // The attempt grows its own trees on these trials, unbudgeted.
    const BudgetScope scope(trials, budgeted ? &budget : nullptr);
    const GeometryEncoding tree =
        encodeGeometryTree(coarsenGrid(quantized, lowBits), bits - lowBits, index, GeometryTree::CheapestFirst,
                           ChoiceCoding::Flags, FrameUse::On, &trials);
    if (tree.bytes.empty() || double(tree.bytes.size()) > room) return SIZE_MAX;
    return tree.bytes.size() + refinement.bytes.size();
}

// `section`: the tree's vertex section on the full grid when the caller
// has coded it already (encodeConnectivity), else coded here.
// `early` (may be null): the tree attempt's connectivity, coded before its
// section (encodeBeforeVertexSection).
Attempt encodeWithChosenGeometry(const Mesh& mesh, const PreparedMesh& prepared, const ManifoldCut& cut,
                                 const EncodeOptions& options, ProgressReporter& progress, VertexSection section,
                                 EarlyConnectivity* early) {
    EncodeOptions tree = options;
    tree.geometry = GeometryCoder::SpanningTree;
    if (!section.coder) section = codeVertexSection(prepared.quantized, options, tree.geometry, 0, nullptr);
    const size_t treeGeometry = section.encoding.bytes.size();
    const double treeBits = 8.0 * double(treeGeometry) / double(std::max<size_t>(1, mesh.vertexCount()));
    if (treeBits <= kAutoRefineAboveBitsPerVertex)
        return encodeWithGeometry(mesh, prepared, cut, tree, 0, progress, nullptr, &section, early);
    const double slack = kRefineEstimateSlack * double(treeGeometry);
    // The gain asked of an estimate before its attempt is made, and of an
    // attempt made before it is kept.
    const double minimumGain = mesh.vertexCount() < kRefineAnyGainBelowVertices      ? 0.0
                               : mesh.vertexCount() < kRefineSmallMeshBelowVertices ? kRefineSmallMeshEstimatedGain
                                                                                     : kRefineMinimumGain;
    const double keptGain = mesh.vertexCount() < kRefineSmallMeshBelowVertices ? 0.0 : minimumGain;
    // Refine's estimates (refineGeometryEstimate), one per low-bit count:
    // they need the tree's vertex section only, not its attempt, so they
    // may run beside it.
    struct Estimate {
        int lowBits = 0;
        GeometryTreeTrials trials;
        size_t bytes = SIZE_MAX;
        double growth = 0.0;              // the connectivity's growth on a crowded coarse grid, in bytes
        std::optional<Attempt> attempt;  // made beside the tree's attempt
        std::exception_ptr failure;      // what that attempt threw, reported only where it is kept
    };
    std::vector<Estimate> estimates;
    for (int lowBits : kAutoRefineLowBits)
        if (lowBits < options.bits) {
            estimates.emplace_back();
            estimates.back().lowBits = lowBits;
        }
    // The connectivity only grows on a coarser grid (more near ties), so
    // refine can win only where its vertex bits alone save the gain asked
    // of it: the estimate spares the whole attempt elsewhere (venus,
    // casting, anchor). It stops as soon as it must exceed skipAbove.
    // The rival the estimates' coarse trees measure themselves against
    // (held apart: the section itself goes to the tree's attempt).
    const TreeRival rival = std::move(section.rival);
    auto estimate = [&](Estimate& e, double treeTotal) {
        const double skipAbove = double(treeGeometry) + slack - minimumGain * treeTotal;
        const double budgetAbove = double(treeGeometry) + slack - minimumGain * double(treeGeometry);
        e.bytes = refineGeometryEstimate(prepared.quantized, mesh.triangles, options.bits, e.lowBits, options.index,
                                         e.trials, skipAbove, budgetAbove, &rival);
        e.growth = e.trials.nearest && e.trials.nearest->spacing <= kCrowdedCoarseSpacing
                       ? kCrowdedConnectivityGrowth * double(mesh.vertexCount()) / 8.0
                       : 0.0;
    };
    // Whether the estimate is worth an attempt against a file of treeTotal
    // bytes: every attempt made saves at least the gain asked, by the
    // estimate, within its slack.
    auto promising = [&](const Estimate& e, double treeTotal) {
        return e.bytes != SIZE_MAX && double(treeGeometry) + slack - double(e.bytes) - e.growth >= minimumGain * treeTotal;
    };
    EncodeOptions refine = options;
    refine.geometry = GeometryCoder::Refine;
    const bool attemptsBeside = mesh.vertexCount() <= kRefineAttemptsBesideUpToVertices;
    // Set when this function leaves, the tree's attempt having thrown (a
    // cancel, an error) or every thread being done: an attempt beside
    // still running then stops at its next report (as Cancelled, which
    // nobody reads) instead of being waited for to its end.
    std::atomic<bool> leaving{false};
    std::vector<std::future<void>> estimating;  // declared after what the threads read: destroyed (and waited for) first
    // The tree attempt's total, for attempts that wait for it; declared
    // after the threads' futures, so that an exception breaks the promise
    // (waking them) before the futures wait for them.
    std::promise<size_t> treeTotalGiven;
    const std::shared_future<size_t> treeTotalKnown = treeTotalGiven.get_future().share();
    struct RaiseOnExit {
        std::atomic<bool>& flag;
        ~RaiseOnExit() { flag = true; }
    } raiseOnExit{leaving};  // declared last: raised first
    if (secondThreadAllowed(options)) {
        // Beside the attempt, whose total is not known yet, the estimates
        // stop at the looser bound a file no larger than its vertex section
        // gives: one stopped there would stop at the attempt's bound too,
        // and one not stopped gives the same figure, which the test below
        // holds to the attempt's bound. The files are the same. Each on a
        // thread of its own: together they take about twice the attempt's
        // time (venus), so on two cores the three end sooner than the
        // estimates one after the other beside it.
        // An estimate promising against that looser bound goes on to its
        // attempt on the same thread (each attempt is the same whenever it
        // is made): the test below keeps it only where the attempt's bound
        // would have made it. Before, the attempts came one after the other
        // once the tree's was done (armadillo-43k, whole process: 1.16 s
        // then, 0.80 s now; docs/speed.md).
        estimating.reserve(estimates.size());  // a push_back that threw would wait on a thread waiting here
        for (Estimate& each : estimates) {
            Estimate* e = &each;
            estimating.push_back(startBeside([&, e, treeGeometry, treeTotalKnown] {
                estimate(*e, double(treeGeometry));
                if (!attemptsBeside || !promising(*e, double(treeGeometry))) return;
                // Promising against any file up to kSureTreeTotal times the
                // tree's section: made at once. Less clearly: made once the
                // tree's attempt tells its total, and only where the test
                // below will keep it (camel's estimate with 2 low bits).
                if (!promising(*e, kSureTreeTotal * double(treeGeometry)) &&
                    !promising(*e, double(treeTotalKnown.get())))
                    return;
                const Progress untilLeaving = [&leaving](double, const char*) { return !leaving.load(); };
                ProgressReporter quiet(untilLeaving);  // shows nothing
                // An attempt made at once may be one the test below drops
                // (the tree's total past kSureTreeTotal times its section):
                // what it throws (out of memory) is kept for the test, and
                // reported only if the attempt is.
                try {
                    e->attempt = encodeWithGeometry(mesh, prepared, cut, refine, e->lowBits, quiet, &e->trials);
                } catch (...) {
                    e->failure = std::current_exception();
                }
                e->trials = GeometryTreeTrials();
            }));
        }
    }
    Attempt best = encodeWithGeometry(mesh, prepared, cut, tree, 0, progress, nullptr, &section, early);
    const size_t treeTotal = best.encoded.bytes.size();
    treeTotalGiven.set_value(treeTotal);
    // The attempts beside report nothing: waiting for them, this thread
    // reports, so that the bar moves and a cancel is seen (it raises
    // `leaving` on the way out, and they stop).
    for (std::future<void>& running : estimating) {
        while (running.wait_for(std::chrono::milliseconds(20)) == std::future_status::timeout)
            progress.stage("trying refine", 0.95);
        running.get();
    }
    if (estimating.empty())
        for (Estimate& e : estimates) estimate(e, double(treeTotal));
    const double worthIt = (1.0 - keptGain) * double(treeTotal);
    for (Estimate& e : estimates) {
        // The estimate's trees serve its own attempt only: freed after it
        // (the estimates ran together, so each one's are held till here).
        GeometryTreeTrials trials = std::move(e.trials);
        std::optional<Attempt> made = std::move(e.attempt);
        e.attempt.reset();
        if (!promising(e, double(treeTotal))) continue;
        if (e.failure) std::rethrow_exception(e.failure);
        Attempt refined =
            made ? std::move(*made) : encodeWithGeometry(mesh, prepared, cut, refine, e.lowBits, progress, &trials);
        if (double(refined.encoded.bytes.size()) <= worthIt && refined.encoded.bytes.size() < best.encoded.bytes.size())
            best = std::move(refined);
    }
    return best;
}

// Format 13: the mesh by the topological coder (topological_coder.h): the
// connectivity named by topology, the positions in the order the walk
// meets them. The repairs and vertex order sections are as for ranks.
// giveUpAbove (0: never): the size of the file to beat; past it (by the
// coder's projection), or past the format's search bound, the attempt
// gives up and returns no file. `alone`: no ranks' attempt came before (for
// the progress bar).
constexpr uint64_t kNoRivalFile = ~uint64_t(0);  // a giveUpAbove for the search bound alone
std::optional<Attempt> encodeTopologically(const Mesh& mesh, const PreparedMesh& prepared, const ManifoldCut& cut,
                                           const EncodeOptions& options, ProgressReporter& progress, bool alone,
                                           uint64_t giveUpAbove = 0) {
    progress.stage("coding topologically", alone ? 0.01 : 0.9);
    const size_t originals = mesh.vertexCount(), copies = cut.copyOf.size();
    std::vector<int32_t> grid(prepared.quantized);  // copies at their originals' grid points
    grid.reserve(3 * (originals + copies));
    for (uint32_t original : cut.copyOf)
        for (int k = 0; k < 3; ++k) grid.push_back(prepared.quantized[3 * size_t(original) + size_t(k)]);
    TopologicalLayout layout;
    TopologicalBudget budget;
    // The faces as given passed the check, and a cut's are codable by
    // construction (the walk would throw on any that is not).
    budget.meshChecked = true;
    budget.giveUpAbove = giveUpAbove;
    // Alone it is the whole encoding (to 0.95); after the ranks, their
    // last stretch.
    budget.progress = alone ? WalkProgress{&progress, 0.01, 0.94} : WalkProgress{&progress, 0.9, 0.05};
    TopologicalStreams streams = encodeTopological(grid, prepared.grid.bits, *prepared.triangles, cut.copyOf, &layout, nullptr, budget);
    if (!streams.complete) return std::nullopt;
    // Decoded vertex -> input vertex: of an input vertex and its copies, the
    // one the walk met first is decoded as the original.
    std::vector<uint32_t> order(originals);
    std::vector<uint32_t> decodedIndex(originals);  // input vertex -> decoded
    for (size_t d = 0; d < originals; ++d) {
        const uint32_t v = layout.vertexOf[d];
        order[d] = v < originals ? v : cut.copyOf[v - originals];
        decodedIndex[order[d]] = uint32_t(d);
    }

    Attempt attempt;
    Encoded& result = attempt.encoded;
    result.grid = prepared.grid;
    const size_t faceCount = layout.faceOf.size();
    FileHeader header;
    header.vertexCount = originals;
    header.faceCount = faceCount + cut.looseTriangles.size() / 3 + prepared.repairs.duplicateOf.size();
    header.hasRepairs = prepared.repaired;
    header.copyCount = copies;
    header.grid = result.grid;
    header.connectivityCoder = ConnectivityCoder::Topological;
    // The fields the ranks would read: fixed, and meaningless here.
    header.predictor = Predictor::Parallelogram;
    header.levers = Levers::none();
    header.keepsVertexOrder = options.keepVertexOrder;
    header.componentCount = layout.components;

    Repairs inDecodedOrder;
    if (prepared.repaired) {
        std::vector<uint32_t> loose(cut.looseTriangles.size());
        for (size_t c = 0; c < loose.size(); ++c) loose[c] = decodedIndex[cut.looseTriangles[c]];
        inDecodedOrder = repairsInDecodedOrder(prepared, layout.copyOf, std::move(loose), layout.faceOf);
        attempt.repairs = encodeRepairs(inDecodedOrder, originals);
    }
    if (options.keepVertexOrder) attempt.vertexOrder = encodeVertexOrder(order);
    attempt.decodedTriangles = std::move(layout.triangles);
    if (prepared.repaired) undoCut(attempt.decodedTriangles, inDecodedOrder, originals);
    if (options.keepVertexOrder) {
        for (uint32_t& v : attempt.decodedTriangles) v = order[v];
        for (size_t v = 0; v < order.size(); ++v) order[v] = uint32_t(v);
    }
    result.vertexOrder = std::move(order);
    result.faceRank.assign(prepared.inputFaces, 0);  // no ranks
    attempt.header = header;
    attempt.connectivity = std::move(streams.connectivity);
    fillStatsFromTraversal(result.stats, 0, inDecodedOrder);
    result.stats.boundaryEdges = layout.boundaryEdges;
    writeAttempt(attempt, GeometryCoder::SpanningTree, std::move(streams.geometry));
    return attempt;
}

}  // namespace

Attempt encodeConnectivity(const Mesh& mesh, const EncodeOptions& options, ProgressReporter& progress,
                           const Grid* grid) {
    PreparedMesh prepared;
    prepared.grid = makeGrid(mesh.positions, options.bits);  // checks bits, emptiness, finiteness
    if (grid) prepared.grid = *grid;
    prepared.quantized = quantize(mesh.positions, prepared.grid);
    {
        // The decoder's own test of every decoded coordinate: a grid point
        // rounding past FLT_MAX would make a file no reader opens.
        std::vector<float> decodedPositions;
        size_t badVertex = 0;
        if (!dequantize(prepared.quantized, prepared.grid, decodedPositions, &badVertex))
            throw Error(ErrorKind::InvalidInput, "vertex " + std::to_string(badVertex) +
                        " would decode outside the range of single-precision floats; scale the mesh down");
    }
    progress.stage("checking mesh", 0.0);
    checkIndices(mesh);  // refuses with messages in the input's own indices
    if (options.geometry != GeometryCoder::Auto && !geometryCoderOf(options.geometry))
        throw Error(ErrorKind::InvalidInput, "unknown geometry coder " + std::to_string(int(options.geometry)));
    if (options.predictor != Predictor::Auto && options.predictor != Predictor::Parallelogram &&
        options.predictor != Predictor::Midpoint)
        throw Error(ErrorKind::InvalidInput, "unknown predictor " + std::to_string(int(options.predictor)));
    if (options.geometry == GeometryCoder::Refine &&
        (options.refineBits < 0 || options.refineBits > std::min(kMaxRefineBits, options.bits - 1)))
        throw Error(ErrorKind::InvalidInput, "refinement bits " + std::to_string(options.refineBits) + " out of range 0.." +
                    std::to_string(std::min(kMaxRefineBits, options.bits - 1)) + " at " +
                    std::to_string(options.bits) + " bits");
    if (options.threads < 0)
        throw Error(ErrorKind::InvalidInput, "threads " + std::to_string(options.threads) + " is negative (0: as the machine allows)");
    if (options.connectivity != ConnectivityCoder::Auto && options.connectivity != ConnectivityCoder::Ranks &&
        options.connectivity != ConnectivityCoder::Topological)
        throw Error(ErrorKind::InvalidInput, "unknown connectivity coder " + std::to_string(int(options.connectivity)));
    // The topological coder codes the positions itself: a vertex coder
    // asked for (raw keeps the input order) is the ranks' alone.
    if (options.connectivity == ConnectivityCoder::Topological && options.geometry != GeometryCoder::Auto)
        throw Error(ErrorKind::InvalidInput, std::string("the topological connectivity coder codes the positions itself; geometry coder ") +
                    geometryCoderName(options.geometry) + " goes with the distance ranks");
    // Auto, with nothing asked for that only the ranks have (a vertex coder,
    // a predictor, levers, curvature, parts), chooses the coder.
    const bool ranksAskedFor = options.geometry != GeometryCoder::Auto || options.predictor != Predictor::Auto ||
                               options.curvature || options.connectivityParts != 0 ||
                               leversName(options.levers) != leversName(Levers());
    const bool coderChosen = options.connectivity == ConnectivityCoder::Auto && !ranksAskedFor;
    const bool hubs = coderChosen && hasHubs(mesh);
    // The topological coder alone needs no vertex section of its own.
    const bool ranks = options.connectivity != ConnectivityCoder::Topological && !hubs;
    if (options.connectivityParts < 0 || options.connectivityParts > 2)
        throw Error(ErrorKind::InvalidInput, "connectivity parts " + std::to_string(options.connectivityParts) +
                    " is not 0 (as the mesh asks), 1 or 2");
    // The first attempt's vertex section needs the quantized grid alone:
    // with a second thread it is coded there while this one checks the
    // mesh's topology and cuts it (igea: 4 % of the encoding).
    const bool treeFirst = options.geometry == GeometryCoder::Auto || options.geometry == GeometryCoder::SpanningTree ||
                           (options.geometry == GeometryCoder::Refine && options.refineBits == 0);
    const GeometryCoder firstCoder = treeFirst ? GeometryCoder::SpanningTree : options.geometry;
    const int firstLowBits = options.geometry == GeometryCoder::Refine ? options.refineBits : 0;
    // The early connectivity (below) runs on the calling thread while the
    // vertex section is coded, where the section's numbering can be known
    // before it: on the full grid, for a coder that does not keep the
    // input's order.
    const bool earlyConnectivity = ranks && secondThreadAllowed(options) && firstLowBits == 0 &&
                                   !geometryCoderOf(firstCoder)->keepsInputOrder &&
                                   mesh.vertexCount() <= kEarlyConnectivityUpToVertices;
    EncodeOptions sectionOptions = options;
    if (earlyConnectivity && mesh.vertexCount() > kSectionThreadsBesideUpToVertices) sectionOptions.threads = 1;
    // Declared after everything the second thread reads (sectionOptions):
    // on an exception the future is destroyed first, and waits for it.
    VertexSection firstSection;
    std::future<VertexSection> firstSectionCoding;
    if (ranks && secondThreadAllowed(options))
        // Its own second thread (the graph's halves, the forest) makes a
        // third while the topology check lasts (igea: 30 of 350 ms), unless
        // it keeps to one beside the early connectivity.
        firstSectionCoding = startBeside([&] {
            return codeVertexSection(prepared.quantized, sectionOptions, firstCoder, firstLowBits, nullptr);
        });
    // A mesh the traversal can take as it is needs no cut (the common case,
    // and the cheap test); any other is cut into manifold pieces.
    ManifoldCut cut;
    bool needsCut = false;
    {
        // Its edge table answers only this question: freed before the
        // attempts build their own (144 bytes a vertex on igea).
        MeshTopology asGiven;
        needsCut = !topologyProblem(mesh, &asGiven).empty();
    }
    // The attempts renumber the input's own faces when they need no cut.
    prepared.triangles = needsCut ? &cut.triangles : &mesh.triangles;
    prepared.codableAsGiven = !needsCut;
    if (needsCut) {
        progress.stage("cutting into manifold pieces", 0.005);
        cut = cutIntoManifold(mesh.triangles, mesh.vertexCount());
    }
    // With no cut, no flips (only a repaired mesh's are read) and no table
    // of input faces: each face is its own (4 bytes a face less).
    prepared.inputFaces = mesh.faceCount();
    prepared.repaired = !cut.isIdentity();
    prepared.inputFace = std::move(cut.inputFace);
    prepared.repairs.flipped = std::move(cut.flipped);
    prepared.repairs.duplicateOf = std::move(cut.duplicateOf);
    prepared.repairs.duplicateReversed = std::move(cut.duplicateReversed);
    if (!ranks) {
        std::optional<Attempt> topological =
            encodeTopologically(mesh, prepared, cut, options, progress, true, hubs ? kNoRivalFile : 0);
        if (!topological) {  // hubs, and past the search bound: the ranks after all
            EncodeOptions asRanks = options;
            asRanks.connectivity = ConnectivityCoder::Ranks;
            return encodeConnectivity(mesh, asRanks, progress, grid);
        }
        topological->encoded.quantized = std::move(prepared.quantized);
        return std::move(*topological);
    }

    // While the vertex section is coded on the second thread, the first
    // attempt's connectivity is coded here, in the numbering the section
    // will give (format 9, morton_order.h): on the full grid (not Refine's
    // coarse one), for a coder that does not keep the input's order.
    EarlyConnectivity early;
    EarlyConnectivity* before = nullptr;
    if (earlyConnectivity) {
        EncodeOptions first = options;
        first.geometry = firstCoder;
        early = encodeBeforeVertexSection(mesh, prepared, cut, first, progress);
        before = &early;
    }
    if (firstSectionCoding.valid()) firstSection = firstSectionCoding.get();
    VertexSection* given = firstSection.coder ? &firstSection : nullptr;
    Attempt best;
    if (options.geometry == GeometryCoder::Auto) {
        best = encodeWithChosenGeometry(mesh, prepared, cut, options, progress, std::move(firstSection), before);
    } else if (options.geometry != GeometryCoder::Refine || options.refineBits > 0) {
        best = encodeWithGeometry(mesh, prepared, cut, options, firstLowBits, progress, nullptr, given, before);
    } else {
        // Refine with the low bits left to the encoder: the spanning tree alone,
        // and 1 .. kMaxTriedRefineBits low bits (the sizes are not unimodal in
        // the low bits: plane-holes grows at 1 and 2, shrinks at 3 to 5).
        EncodeOptions tree = options;
        tree.geometry = GeometryCoder::SpanningTree;
        best = encodeWithGeometry(mesh, prepared, cut, tree, 0, progress, nullptr, given, before);
        for (int lowBits = 1; lowBits <= std::min(kMaxTriedRefineBits, options.bits - 1); ++lowBits) {
            Attempt refined = encodeWithGeometry(mesh, prepared, cut, options, lowBits, progress);
            if (refined.encoded.bytes.size() < best.encoded.bytes.size()) best = std::move(refined);
        }
    }
    // Auto (coderChosen): the topological coder too, the smaller file kept.
    // It gives up once its projected size passes the ranks' file by
    // kTopologicalGiveUp: on scans, where the ranks win by 11 to 13 %
    // (bunny, horse, igea), after a quarter of the faces.
    if (coderChosen) {
        const uint64_t rival = best.encoded.bytes.size();
        std::optional<Attempt> topological = encodeTopologically(mesh, prepared, cut, options, progress, false,
                                                                 uint64_t(double(rival) * kTopologicalGiveUp) + 64);
        if (topological && topological->encoded.bytes.size() < rival) best = std::move(*topological);
    }
    // The attempts only read the quantized input; the one kept takes it.
    best.encoded.quantized = std::move(prepared.quantized);
    return best;
}

}  // namespace drm
