// Decoder (paper, Table 2): read the vertex set, then replay the traversal,
// turning each rank back into the vertex that closes the triangle.
//
// decodeCore runs the stages below in order; each reads what the earlier
// ones left in a Decoding and adds its part:
//   readFile (file_format.h)     header and section table, checked
//   decodeVertices               the geometry section's first pass
//   (connectivity coder 2, topological: decodeTopologically instead of
//   the three stages from here, both sections at once)
//   readRepairsBeforeTraversal   the vertex copies of a manifold cut
//   decodeConnectivity           the ranks, replayed into triangles
//   refineVertices               the geometry's second pass (Refine)
//   undoRepairs                  the cut undone
//   restoreVertexOrder           back to the input numbering
//   decodeAttributeSections      (attribute_sections.h)
//   dequantizeVertices, fillStats
#include <algorithm>
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "attributes/attribute_sections.h"
#include "concurrency.h"
#include "connectivity/connectivity_parts.h"
#include "decode/decoder.h"
#include "connectivity/ranked/edge_model.h"
#include "container/file_format.h"
#include "geometry/geometry_coders.h"
#include "spatial/morton.h"
#include "spatial/morton_order.h"
#include "progress.h"
#include "mesh/quantize.h"
#include "entropy/rank_coder.h"
#include "mesh/repair_section.h"
#include "spatial/spatial_index.h"
#include "connectivity/start_triangle.h"
#include "stats.h"
#include "connectivity/topological/topological_coder.h"
#include "connectivity/traversal.h"
#include "mesh/vertex_order.h"

namespace drm {

namespace {

// What the stages hand on to one another.
struct Decoding {
    Decoding(const FileParts& p, const GeometryCoderEntry& coder) : parts(p), header(p.header), geometryCoder(coder) {}

    const FileParts& parts;
    const FileHeader& header;
    const GeometryCoderEntry& geometryCoder;
    Decoded result;
    VertexSet vertices;  // the first pass (its grid moves into result.quantized)
    size_t vertexCount = 0;  // the file's vertices, copies not included
    // A mesh that was cut into manifold pieces: the traversal also sees the
    // vertex copies, and the faces repeating a vertex are not in it.
    std::unique_ptr<RepairReader> repairs;
    size_t looseCount = 0, duplicateCount = 0;
    size_t traversalFaces = 0, traversalVertices = 0;
    uint64_t boundaryEdges = 0;  // the topological coder's boundary symbols

    const std::vector<uint32_t>& copyOf() const {
        static const std::vector<uint32_t> none;
        return repairs ? repairs->repairs().copyOf : none;
    }
};

void decodeVertices(Decoding& d) {
    d.vertices = d.geometryCoder.decode(d.parts.geometry, d.parts.geometrySize, d.header.vertexCount, d.header.grid.bits);
    d.result.quantized = std::move(d.vertices.grid);
    d.vertexCount = size_t(d.header.vertexCount);
    if (d.header.mortonNumbering) {
        // The connectivity's numbering: the section's points in Morton
        // order, those on one grid point in the section's order.
        std::vector<int32_t>& grid = d.result.quantized;
        const std::vector<uint32_t> order = mortonOrder(grid);
        std::vector<int32_t> sorted(grid.size());
        for (size_t v = 0; v < order.size(); ++v)
            for (int k = 0; k < 3; ++k) sorted[3 * v + k] = grid[3 * size_t(order[v]) + k];
        grid.swap(sorted);
    }
}

// Parts 1 to 3 of the repairs section: the copies join the vertex set (at
// their originals' positions), and the loose and repeated faces are counted
// out of the traversal's.
void readRepairsBeforeTraversal(Decoding& d) {
    const FileHeader& header = d.header;
    if (header.hasRepairs) {
        d.repairs.reset(new RepairReader(d.parts.repairs, d.parts.repairsSize, header.vertexCount, header.copyCount,
                                         header.faceCount));
        for (uint32_t original : d.repairs->repairs().copyOf)
            for (int k = 0; k < 3; ++k) d.result.quantized.push_back(d.result.quantized[3 * size_t(original) + k]);
        d.looseCount = d.repairs->repairs().looseCount();
        d.duplicateCount = d.repairs->duplicateCount();
    }
    d.traversalFaces = size_t(header.faceCount) - d.looseCount - d.duplicateCount;
    d.traversalVertices = d.vertexCount + d.copyOf().size();
}

// The topological coder's two sections decode into the vertices
// (copies included, each where its original is) and the traversal's faces,
// in the numbering the ranks' decoder gives (topological_coder.h).
void decodeTopologically(Decoding& d, ProgressReporter& progress) {
    const FileHeader& header = d.header;
    d.vertexCount = size_t(header.vertexCount);
    if (header.hasRepairs) {
        d.repairs.reset(new RepairReader(d.parts.repairs, d.parts.repairsSize, header.vertexCount, header.copyCount,
                                         header.faceCount));
        d.looseCount = d.repairs->repairs().looseCount();
        d.duplicateCount = d.repairs->duplicateCount();
    }
    d.traversalFaces = size_t(header.faceCount) - d.looseCount - d.duplicateCount;
    d.traversalVertices = d.vertexCount + d.copyOf().size();
    TopologicalMesh decoded = decodeTopological(d.parts.connectivity, d.parts.connectivitySize, d.parts.geometry,
                                                d.parts.geometrySize, d.vertexCount, d.copyOf().size(), d.traversalFaces,
                                                header.grid.bits, OtherSearchBound(), WalkProgress{&progress, 0.01, 0.94});
    if (decoded.components != header.componentCount)
        throw Error(ErrorKind::Corrupt, "corrupt file: the header counts " + std::to_string(header.componentCount) +
                    " components, the connectivity section " + std::to_string(decoded.components));
    if (decoded.copyOf != d.copyOf())
        throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section's vertex copies are not those the connectivity section meets");
    d.result.quantized = std::move(decoded.grid);
    d.result.mesh.triangles = std::move(decoded.triangles);
    d.result.faceRank.assign(d.traversalFaces, 0);  // no ranks
    d.boundaryEdges = decoded.boundaryEdges;
}

// One rank stream replayed into faces: a whole mesh's, or one of two
// connectivity parts (connectivity_parts.h).
struct RankStream {
    const uint8_t* data = nullptr;
    size_t size = 0;
    const std::vector<int32_t>* grid = nullptr;  // the stream's vertices: x, y, z each
    size_t faceCount = 0;
    uint64_t componentCount = 0;
    uint32_t seam = kNoIndex;                  // the first of two parts: where the second's vertices begin
    const std::vector<uint32_t>* kept = nullptr;  // the second part: its vertices never culled
};
struct RebuiltFaces {
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> faceRank;
    std::vector<uint64_t> histogram;
};

// progress: may be null (a part decoded beside another). stop, if given, is
// looked at every 1,024 faces: once set (the other part failed or was
// cancelled), this one gives up too.
RebuiltFaces decodeRanks(const Decoding& d, const RankStream& s, const DecodeOptions& options, ProgressReporter* progress,
                         const std::atomic<bool>* stop = nullptr) {
    const FileHeader& header = d.header;
    const std::vector<int32_t>& grid = *s.grid;
    const size_t faceCount = s.faceCount;
    const size_t vertexCount = grid.size() / 3;
    RebuiltFaces out;
    // The face count is only a claim until the ranks deliver the faces; the
    // vertices are already decoded, and a manifold mesh has about two faces
    // a vertex: room for that many is made at once (growing by doubling
    // would copy the faces again and again), never more, whatever the
    // header claims.
    const size_t expectedFaces = std::min<size_t>(faceCount, 2 * vertexCount + 16);
    const std::unique_ptr<SpatialIndex> candidates = makeSpatialIndex(grid, options.index, IndexRole::Traversal);
    Traversal traversal(vertexCount, expectedFaces, candidates.get());
    EdgeModel model(grid, header.grid.bits - d.vertices.lowBits, header.predictor, header.curvature, header.levers,
                    faceCount, *candidates, traversal);
    if (s.seam != kNoIndex) {
        model.setSeam(s.seam);
        for (size_t v = s.seam; v < vertexCount; ++v) traversal.keepVertex(uint32_t(v));
    }
    if (s.kept) {
        for (uint32_t v : *s.kept) traversal.keepVertex(v);
        model.setFirstPartBelowKey(mortonKeyOf(grid.data()));
    }
    RankDecoder coder(s.data, s.size, model.contextCount(), model.boundaryFlags());
    std::vector<uint64_t>& histogram = out.histogram;

    StartCursor cursor(traversal);  // costs nothing until a component starts
    const uint64_t n = vertexCount;
    uint32_t lastStart = 0;
    for (size_t c = 0; c < s.componentCount; ++c) {
        if (traversal.triangleCount() >= faceCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: more components than the header's " + std::to_string(faceCount) + " faces");
        try {
            uint32_t start[3];
            const uint32_t from = cursor.at(lastStart);
            if (from >= n) throw Error(ErrorKind::Corrupt, "every vertex is taken before it starts");
            const uint32_t skipped = coder.getStartGap(StartField::Skipped);
            const uint32_t second = coder.getStartGap(StartField::Second);
            const uint32_t third = coder.getStartGap(StartField::Third);
            if (coder.bytesPastEnd() > 0)
                throw Error(ErrorKind::Corrupt, "the connectivity section ends before its start triangle");
            if (skipped >= n)
                throw Error(ErrorKind::Corrupt, "its start vertex lies " + std::to_string(skipped) + " vertices on, of " +
                            std::to_string(n));
            start[0] = uint32_t((from + uint64_t(skipped)) % n);
            start[1] = vertexAtGap(start[0], second, n);
            start[2] = vertexAtGap(start[0], third, n);
            lastStart = start[0];
            // Every face of part 1 has a vertex below the seam (its ranks
            // see to it for the others): so no face is in both parts.
            if (s.seam != kNoIndex && std::min({start[0], start[1], start[2]}) >= s.seam)
                throw Error(ErrorKind::Corrupt, "its start triangle lies past the first part's vertices");
            traversal.startComponent(start[0], start[1], start[2]);
            out.faceRank.push_back(0);
        } catch (const Error& e) {
            throw Error(ErrorKind::Corrupt, "corrupt file: component " + std::to_string(c) + ": " + e.what());
        }
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            // With boundary flags the candidates and the context are worked
            // out only for an edge the flag gives an apex (EdgeModel::forecastRank).
            const EdgeForecast& forecast = model.forecastBoundary(edge);
            uint32_t rank = 0;
            if (!model.boundaryFlags() || !coder.getBoundaryFlag(forecast.boundaryClass)) {
                model.forecastRank(edge);
                rank = coder.getRank(forecast.context);
            }
            if (coder.bytesPastEnd() > 0)
                throw Error(ErrorKind::Corrupt, "corrupt file: the connectivity section ends before the last face");
            if (rank >= histogram.size()) {
                if (rank > vertexCount) throw Error(ErrorKind::Corrupt, "corrupt file: rank " + std::to_string(rank) + " exceeds the vertex count");
                histogram.resize(size_t(rank) + 1, 0);
            }
            ++histogram[rank];
            if (rank == 0) {
                traversal.closeAsBoundary(edge);
                continue;
            }
            if (traversal.triangleCount() >= faceCount)
                throw Error(ErrorKind::Corrupt, "corrupt file: the connectivity section describes more than the header's " +
                            std::to_string(faceCount) + " faces");
            try {
                const uint32_t apex = model.vertexOfRank(rank, edge);
                model.resolved(apex);
                traversal.attachApex(edge, apex);
                out.faceRank.push_back(rank);
            } catch (const Error& e) {
                throw Error(ErrorKind::Corrupt, "corrupt file: face " + std::to_string(traversal.triangleCount()) + ": " + e.what());
            }
            if (progress) progress->tick(0.05 + 0.9 * double(traversal.triangleCount()) / double(faceCount));
            if (stop && traversal.triangleCount() % 1024 == 0 && stop->load(std::memory_order_relaxed))
                throw Error(ErrorKind::Cancelled, "stopped beside the other connectivity part");
        }
    }
    if (traversal.triangleCount() != faceCount)
        throw Error(ErrorKind::Corrupt, "corrupt file: decoded " + std::to_string(traversal.triangleCount()) + " faces, the header says " +
                    std::to_string(faceCount));
    out.triangles = traversal.takeTriangles();
    return out;
}

bool secondThreadAllowed(const DecodeOptions& options) {
    return options.threads >= 2 || (options.threads == 0 && std::thread::hardware_concurrency() > 1);
}

void decodeConnectivity(Decoding& d, const DecodeOptions& options, ProgressReporter& progress) {
    const FileHeader& header = d.header;
    Decoded& result = d.result;
    RankStream whole;
    whole.data = d.parts.connectivity;
    whole.size = d.parts.connectivitySize;
    whole.grid = &result.quantized;
    whole.faceCount = d.traversalFaces;
    whole.componentCount = header.componentCount;
    if (!header.twoParts) {
        RebuiltFaces faces = decodeRanks(d, whole, options, &progress);
        result.mesh.triangles = std::move(faces.triangles);
        result.faceRank = std::move(faces.faceRank);
        result.stats.rankHistogram = std::move(faces.histogram);
        return;
    }
    // Two parts: part 2 over the vertices from the split on, numbered from
    // 0, beside part 1 over them all.
    const ConnectivityParts parts = readConnectivityParts(whole.data, whole.size, d.traversalVertices,
                                                          header.componentCount, d.traversalFaces);
    const uint32_t split = parts.split;
    const std::vector<int32_t> secondGrid(result.quantized.begin() + 3 * size_t(split), result.quantized.end());
    RankStream first = whole, second = whole;
    first.data = parts.first;
    first.size = parts.firstSize;
    first.faceCount = size_t(parts.firstFaces);
    first.componentCount = parts.firstComponents;
    first.seam = split;
    second.data = parts.second;
    second.size = parts.secondSize;
    second.grid = &secondGrid;
    second.faceCount = d.traversalFaces - size_t(parts.firstFaces);
    second.componentCount = header.componentCount - parts.firstComponents;
    second.kept = &parts.keptInSecond;
    RebuiltFaces a, b;
    if (secondThreadAllowed(options)) {
        std::atomic<bool> stop(false);
        std::future<RebuiltFaces> later = startBeside([&] { return decodeRanks(d, second, options, nullptr, &stop); });
        try {
            a = decodeRanks(d, first, options, &progress);
        } catch (...) {
            stop = true;  // part 1's error (or a cancel) is the one reported
            later.wait();  // what it refers to lives here
            throw;
        }
        b = later.get();
    } else {
        a = decodeRanks(d, first, options, &progress);
        b = decodeRanks(d, second, options, nullptr);
    }
    for (uint32_t& v : b.triangles) v += split;
    a.triangles.insert(a.triangles.end(), b.triangles.begin(), b.triangles.end());
    a.faceRank.insert(a.faceRank.end(), b.faceRank.begin(), b.faceRank.end());
    if (b.histogram.size() > a.histogram.size()) a.histogram.resize(b.histogram.size(), 0);
    for (size_t r = 0; r < b.histogram.size(); ++r) a.histogram[r] += b.histogram[r];
    result.mesh.triangles = std::move(a.triangles);
    result.faceRank = std::move(a.faceRank);
    result.stats.rankHistogram = std::move(a.histogram);
}

// The geometry coder's second pass, across the decoded triangles (vertex
// copies stand for their originals).
void refineVertices(Decoding& d) {
    std::vector<uint32_t> triangles = d.result.mesh.triangles;
    const std::vector<uint32_t>& copyOf = d.copyOf();
    for (uint32_t& v : triangles)
        if (v >= d.vertexCount) v = copyOf[v - d.vertexCount];
    std::vector<int32_t>& quantized = d.result.quantized;
    const std::vector<int32_t> coarse(quantized.begin(), quantized.begin() + 3 * d.vertexCount);
    const std::vector<int32_t> fine = d.geometryCoder.decodeAfterConnectivity(d.vertices, coarse, triangles);
    std::copy(fine.begin(), fine.end(), quantized.begin());
}

// Undo the cut: copies back to their originals, turned faces back over,
// then the repeated faces and the faces that repeat a vertex.
void undoRepairs(Decoding& d) {
    d.repairs->readAfterTraversal(d.traversalFaces);
    std::vector<uint32_t>& t = d.result.mesh.triangles;
    undoCut(t, d.repairs->repairs(), d.vertexCount);
    d.result.faceRank.resize(t.size() / 3, 0);
    d.result.quantized.resize(3 * d.vertexCount);
}

// Back to the input numbering: decoded vertex v was input vertex order[v].
void restoreVertexOrder(Decoding& d) {
    const std::vector<uint32_t> order = decodeVertexOrder(d.parts.vertexOrder, d.parts.vertexOrderSize, d.vertexCount);
    Decoded& result = d.result;
    std::vector<int32_t> inInputOrder(result.quantized.size());
    for (size_t v = 0; v < d.vertexCount; ++v)
        for (int k = 0; k < 3; ++k) inInputOrder[3 * size_t(order[v]) + k] = result.quantized[3 * v + k];
    result.quantized.swap(inInputOrder);
    for (uint32_t& v : result.mesh.triangles) v = order[v];
}

void dequantizeVertices(Decoding& d) {
    size_t badVertex = 0;
    if (!dequantize(d.result.quantized, d.header.grid, d.result.mesh.positions, &badVertex))
        throw Error(ErrorKind::Corrupt, "corrupt file: vertex " + std::to_string(badVertex) +
                    " lies outside the range of single-precision floats");
}

void fillStats(Decoding& d, size_t fileSize) {
    Stats& stats = d.result.stats;
    static const Repairs noRepairs;
    fillStatsFromHeader(stats, d.parts, fileSize);  // leaves the decoded figures (ranks, repairs, attributes) alone
    fillStatsFromTraversal(stats, d.vertices.lowBits, d.repairs ? d.repairs->repairs() : noRepairs);
    if (d.header.connectivityCoder == ConnectivityCoder::Topological) stats.boundaryEdges = d.boundaryEdges;
    stats.vertices = d.result.mesh.vertexCount();  // the file's vertices, or the split ones of a welded mesh
}

// The vertex set coded first, then the ranks that rebuild the faces over
// it (connectivity coder 1).
void decodeByRanks(Decoding& d, const DecodeOptions& options, ProgressReporter& progress) {
    progress.stage("decoding vertices", 0.01);
    decodeVertices(d);
    readRepairsBeforeTraversal(d);
    progress.stage("decoding connectivity", 0.05);
    decodeConnectivity(d, options, progress);
    if (d.geometryCoder.decodeAfterConnectivity) {
        progress.stage("refining vertices", 0.95);
        refineVertices(d);
    }
}

// Faces and positions together, in the order the topological walk meets
// them (connectivity coder 2).
void decodeByTopology(Decoding& d, const DecodeOptions&, ProgressReporter& progress) {
    progress.stage("decoding vertices and connectivity", 0.01);
    decodeTopologically(d, progress);
}

// The decoder's stage for each connectivity coder, keyed by the id the
// header stores (connectivity_coders.h holds what a file may name).
struct ConnectivityStage {
    ConnectivityCoder id;
    void (*decode)(Decoding& d, const DecodeOptions& options, ProgressReporter& progress);
};
constexpr ConnectivityStage kConnectivityStages[] = {
    {ConnectivityCoder::Ranks, decodeByRanks},
    {ConnectivityCoder::Topological, decodeByTopology},
};
const ConnectivityStage& connectivityStageOf(ConnectivityCoder id) {
    for (const ConnectivityStage& stage : kConnectivityStages)
        if (stage.id == id) return stage;
    // readFile refuses ids connectivity_coders.h lacks, and each of those has a stage.
    throw Error(ErrorKind::Internal, "internal error: no decoder for connectivity coder " + std::to_string(int(id)));
}

}  // namespace

Decoded decodeCore(const uint8_t* data, size_t size, const DecodeOptions& options, FileParts* partsOut) {
    ProgressReporter progress(options.progress);
    progress.stage("reading", 0.0);
    FileParts& parts = *partsOut;
    parts = readFile(data, size);
    Decoding d(parts, *geometryCoderOf(parts.header.geometryCoder));  // readFile refuses ids the table lacks
    d.result.grid = parts.header.grid;

    connectivityStageOf(parts.header.connectivityCoder).decode(d, options, progress);
    if (d.repairs) undoRepairs(d);
    if (parts.header.keepsVertexOrder) restoreVertexOrder(d);
    if (!parts.attributes.empty()) {
        progress.stage("decoding attributes", 0.97);
        decodeAttributeSections(parts, d.result);
    }
    dequantizeVertices(d);
    fillStats(d, size);
    progress.stage("done", 1.0);
    return std::move(d.result);
}

}  // namespace drm
