#include "encode/vertex_section.h"

#include <algorithm>
#include <thread>
#include <utility>

#include "encode/ranked_attempt.h"
#include "geometry/refine_coder.h"
#include "spatial/morton_order.h"

namespace drm {

namespace {

// Below this many faces, the connectivity is also coded over the vertex
// section's order (kFlagSectionNumbering) besides Morton order, and the
// smaller file kept. Regular meshes break their many ties between equal
// distances better in the tree's order, a walk over the surface
// (torus-2k's connectivity takes a third less: docs/tuning.md).
constexpr size_t kTrySectionNumberingBelowFaces = 20000;

// From this many vertices, refine's estimates give their coarse tree up
// where it clearly cannot pay (TreeBudget, refineGeometryEstimate): on
// smaller meshes they cost less, and there the extrapolation from the
// first vertices strays further (docs/tuning.md).
constexpr size_t kEstimateBudgetFromVertices = 8192;
// Larger meshes' estimates are not budgeted: the rival's figures (and a
// copy of the tree's section) would add to the encoder's peak memory, the
// vertex section being coded beside the early connectivity there
// (kSectionThreadsBesideUpToVertices).
constexpr size_t kEstimateBudgetUpToVertices = kSectionThreadsBesideUpToVertices;

// The numbering of the vertices for the connectivity (morton_order.h):
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
// exists, and its connectivity is kept: otherwise a single such pair
// reached in the other order would make the guess wrong and the
// connectivity be coded twice (igea x16 has 284 more points than grid
// points at 12 bits).
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

}  // namespace

VertexSection codeVertexSection(const std::vector<int32_t>& quantized, const EncodeOptions& options,
                                GeometryCoder asked, int lowBits, GeometryTreeTrials* trials, int threads) {
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
    section.encoding = section.coder->encode(vertexGrid, options.bits - lowBits, options.index, trials, threads);
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

Attempt encodeWithGeometry(const EncodeSession& session, const VertexSectionPlan& plan, ProgressReporter& progress) {
    const PreparedMesh& prepared = session.prepared;
    const EncodeOptions& options = session.options;
    const int lowBits = plan.lowBits;
    EarlyConnectivity* const early = plan.early;
    progress.stage("coding vertices", 0.01);
    VertexSection section =
        plan.coded ? std::move(*plan.coded)
                   : codeVertexSection(prepared.quantized, options, plan.coder, lowBits, plan.trials, threadsFor(options));
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
        return encodeNumbered(session, numbered, vertexGrid, progress);
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

EarlyConnectivity encodeBeforeVertexSection(const EncodeSession& session, ProgressReporter& progress) {
    const PreparedMesh& prepared = session.prepared;
    EarlyConnectivity early;
    early.order = mortonOrder(prepared.quantized);
    early.certain = !hasCoincidentPoints(prepared.quantized, early.order);
    NumberedMesh numbered;
    numbered.order = early.order;
    early.attempt = encodeNumbered(session, numbered, prepared.quantized, progress);
    return early;
}

}  // namespace drm
