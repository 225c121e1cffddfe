// The encoder's core: the mesh prepared once (grid, quantized positions,
// the cut into manifold pieces), then the attempts of attempt_plan.h, the
// smallest file kept.
#include "encode/encoder.h"

#include <algorithm>
#include <cstdint>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "concurrency.h"
#include "encode/attempt_plan.h"
#include "encode/encode_session.h"
#include "encode/refine_policy.h"
#include "encode/topological_attempt.h"
#include "encode/vertex_section.h"
#include "geometry/geometry_coders.h"

namespace drm {

namespace {

// The topological attempt (ConnectivityCoder::Auto) gives up when its
// projected size passes the ranks' file by this factor: scans, where the
// ranks win clearly, stop early, and no corpus file changes for it
// (docs/tuning.md).
constexpr double kTopologicalGiveUp = 1.05;

// Refuses options the encoder cannot take, naming the option and its value.
void checkOptions(const EncodeOptions& options) {
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
    if (options.connectivityParts < 0 || options.connectivityParts > 2)
        throw Error(ErrorKind::InvalidInput, "connectivity parts " + std::to_string(options.connectivityParts) +
                    " is not 0 (as the mesh asks), 1 or 2");
}

// The grid (checked: bits, emptiness, finiteness) and the quantized input.
// grid, if given, is the grid to use.
void quantizeInput(const Mesh& mesh, int bits, const Grid* grid, PreparedMesh& prepared) {
    prepared.grid = makeGrid(mesh.positions, bits);
    if (grid) prepared.grid = *grid;
    prepared.quantized = quantize(mesh.positions, prepared.grid);
    // The decoder's own test of every decoded coordinate: a grid point
    // rounding past FLT_MAX would make a file no reader opens.
    std::vector<float> decodedPositions;
    size_t badVertex = 0;
    if (!dequantize(prepared.quantized, prepared.grid, decodedPositions, &badVertex))
        throw Error(ErrorKind::InvalidInput, "vertex " + std::to_string(badVertex) +
                    " would decode outside the range of single-precision floats; scale the mesh down");
}

// A mesh the traversal can take as it is needs no cut (the common case,
// and the cheap test); any other is cut into manifold pieces, and the
// repairs that undo the cut are kept in prepared.
void cutIntoPieces(const Mesh& mesh, PreparedMesh& prepared, ManifoldCut& cut, ProgressReporter& progress) {
    bool needsCut = false;
    {
        // Its edge table answers only this question: freed before the
        // attempts build their own (144 bytes a vertex).
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
}

// The first ranked attempt's vertex section, on a second thread where the
// encoder may use one (else an invalid future): it needs the quantized
// grid alone, so it is coded while this thread checks and cuts the mesh.
std::future<VertexSection> startFirstSection(const PreparedMesh& prepared, const EncodeOptions& options,
                                             const AttemptPlan& plan) {
    if (!plan.ranks || !secondThreadAllowed(options)) return {};
    const GeometryCoder coder = plan.firstCoder;
    const int lowBits = plan.firstLowBits, threads = plan.firstSectionThreads;
    return startBeside([&prepared, &options, coder, lowBits, threads] {
        return codeVertexSection(prepared.quantized, options, coder, lowBits, nullptr, threads);
    });
}

// Steps 2 to 5 of attempt_plan.h. firstSectionCoding: the first attempt's
// vertex section being coded beside (startFirstSection), or invalid.
Attempt encodeByRanks(const EncodeSession& session, const AttemptPlan& plan,
                      std::future<VertexSection>& firstSectionCoding, ProgressReporter& progress) {
    const EncodeOptions& options = session.options;
    // While the vertex section is coded on the second thread, the first
    // attempt's connectivity is coded here, in the numbering the section
    // will give (morton_order.h).
    EarlyConnectivity early;
    EarlyConnectivity* before = nullptr;
    if (plan.earlyConnectivity) {
        early = encodeBeforeVertexSection(session, progress);
        before = &early;
    }
    VertexSection firstSection;
    if (firstSectionCoding.valid()) firstSection = firstSectionCoding.get();
    VertexSection* given = firstSection.coder ? &firstSection : nullptr;
    Attempt best;
    if (options.geometry == GeometryCoder::Auto) {
        best = encodeWithChosenGeometry(session, std::move(firstSection), before, progress);
    } else if (options.geometry != GeometryCoder::Refine || options.refineBits > 0) {
        best = encodeWithGeometry(session, {options.geometry, plan.firstLowBits, nullptr, given, before}, progress);
    } else {
        // Refine with the low bits left to the encoder: the spanning tree alone,
        // and 1 .. kMaxTriedRefineBits low bits (the sizes are not unimodal in
        // the low bits).
        best = encodeWithGeometry(session, {GeometryCoder::SpanningTree, 0, nullptr, given, before}, progress);
        for (int lowBits = 1; lowBits <= std::min(kMaxTriedRefineBits, options.bits - 1); ++lowBits) {
            Attempt refined = encodeWithGeometry(session, {GeometryCoder::Refine, lowBits}, progress);
            if (refined.encoded.bytes.size() < best.encoded.bytes.size()) best = std::move(refined);
        }
    }
    if (plan.coderChosen) {
        const uint64_t rival = best.encoded.bytes.size();
        std::optional<Attempt> topological =
            encodeTopologically(session, false, uint64_t(double(rival) * kTopologicalGiveUp) + 64, progress);
        if (topological && topological->encoded.bytes.size() < rival) best = std::move(*topological);
    }
    return best;
}

}  // namespace

Attempt encodeConnectivity(const Mesh& mesh, const EncodeOptions& options, ProgressReporter& progress,
                           const Grid* grid) {
    PreparedMesh prepared;
    quantizeInput(mesh, options.bits, grid, prepared);
    progress.stage("checking mesh", 0.0);
    checkIndices(mesh);  // refuses with messages in the input's own indices
    checkOptions(options);
    AttemptPlan plan = planAttempts(mesh, options);
    // Declared after what the second thread reads (prepared, options): on
    // an exception the future is destroyed first, and waits for it.
    std::future<VertexSection> firstSectionCoding = startFirstSection(prepared, options, plan);
    ManifoldCut cut;
    cutIntoPieces(mesh, prepared, cut, progress);
    const EncodeSession session{mesh, prepared, cut, options};
    Attempt best;
    std::optional<Attempt> topological;
    if (!plan.ranks) topological = encodeTopologically(session, true, plan.hubs ? kNoRivalFile : 0, progress);
    if (topological) {
        best = std::move(*topological);
    } else {
        if (!plan.ranks) {  // past the search bound: the ranks after all
            plan = planAttempts(mesh, options, true);
            firstSectionCoding = startFirstSection(prepared, options, plan);
        }
        best = encodeByRanks(session, plan, firstSectionCoding, progress);
    }
    // The attempts only read the quantized input; the one kept takes it.
    best.encoded.quantized = std::move(prepared.quantized);
    return best;
}

}  // namespace drm
