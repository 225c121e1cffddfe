#include "encode/ranked_attempt.h"

#include <algorithm>
#include <cstdint>
#include <future>
#include <string>

#include "concurrency.h"
#include "connectivity/connectivity_parts.h"
#include "connectivity/ranked/predictor_selection.h"
#include "encode/connectivity_split.h"
#include "encode/rank_stream.h"
#include "geometry/geometry_coders.h"
#include "mesh/vertex_order.h"
#include "stats.h"

namespace drm {

namespace {

// Below this many faces the paper's method (no levers) is tried too, and
// kept where smaller: on meshes of a few hundred faces the levers' contexts
// see too few codes to learn. From 4,096 faces, where the confidence
// contexts split finer (kFineBucketsFromFaces, edge_model.cpp), it never
// wins on the corpus (docs/tuning.md), so the attempt (one in six of such a
// mesh's connectivity attempts) is not made.
constexpr size_t kTryWithoutLeversBelowFaces = 4096;
// Below this many faces, the traversal is also started from
// kFirstVerticesTried - 1 other vertices, at the first multiples of
// 1 / kFirstVerticesSpread of the numbering, and in the input's order
// (encodeWithGeometry). Each start tried buys a little less file for more
// encoding time; one other vertex, a quarter of the way, is the balance
// (docs/tuning.md).
constexpr size_t kTryStartsBelowFaces = 20000;
constexpr size_t kFirstVerticesTried = 2;
constexpr size_t kFirstVerticesSpread = 4;

}  // namespace

void writeAttempt(Attempt& attempt, GeometryCoder coder, std::vector<uint8_t> geometry) {
    attempt.header.geometryCoder = coder;
    attempt.geometry = std::move(geometry);
    FileParts written;
    attempt.encoded.bytes = writeFile(attempt.header, attempt.connectivity, attempt.geometry, attempt.vertexOrder,
                                      attempt.repairs, {}, &written);
    fillStatsFromHeader(attempt.encoded.stats, written, attempt.encoded.bytes.size());
}

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

namespace {

// One attempt over one numbering, one set of levers and one choice of
// component starts. The attempt's quantized and vertexOrder are left
// empty: only the attempt kept gets them, by move (encodeWithGeometry,
// encodeConnectivity).
Attempt encodeOnce(const EncodeSession& session, const NumberedMesh& numbered, const Levers& levers,
                   const ComponentStarts& starts, ProgressReporter& progress) {
    const PreparedMesh& prepared = session.prepared;
    const EncodeOptions& options = session.options;
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
    header.levers = levers;
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
        CodedRanks coded = codeRanks(whole, session, numbered, levers, starts, result, progress, 0.05, 0.9);
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
        CodedRanks a = codeRanks(first, session, numbered, levers, smallest, result, progress, 0.05, 0.9 * share);
        CodedRanks b = codeRanks(second, session, numbered, levers, smallest, result, progress, 0.05 + 0.9 * share,
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

}  // namespace

Attempt encodeNumbered(const EncodeSession& session, NumberedMesh& numbered, const std::vector<int32_t>& vertexGrid,
                       ProgressReporter& progress) {
    const Mesh& mesh = session.mesh;
    const PreparedMesh& prepared = session.prepared;
    const ManifoldCut& cut = session.cut;
    const EncodeOptions& options = session.options;
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
            // nothing (and take about 2 % of igea's encoding instructions).
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
    // Where the traversal starts changes every rank after it (over 11 start
    // vertices, block's connectivity ranges over a tenth of its size, and
    // which start wins is close to chance). Small meshes try several starts.
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
            Attempt attempt = encodeOnce(session, numbered, options.levers, startsToTry[k], reporter);
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
        Attempt alternative = encodeOnce(session, numbered, Levers::none(), bestStarts, progress);
        if (alternative.encoded.bytes.size() < best.encoded.bytes.size()) best = std::move(alternative);
    }
    best.encoded.vertexOrder = std::move(numbered.order);
    if (options.keepVertexOrder)
        for (size_t v = 0; v < best.encoded.vertexOrder.size(); ++v) best.encoded.vertexOrder[v] = uint32_t(v);
    return best;
}

}  // namespace drm
