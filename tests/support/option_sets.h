// Encoder option sets that between them produce every header flag, both
// predictors, both connectivity coders, every geometry coder, the vertex-order section and the
// extremes of the quantization range, so files made with them reach every
// branch of the decoder. Shared by the seed corpus, the robustness tests and
// the determinism check.
#ifndef DRM_TEST_OPTION_SETS_H
#define DRM_TEST_OPTION_SETS_H

#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm_test {

struct NamedOptions {
    std::string name;
    drm::EncodeOptions options;
};

inline std::vector<NamedOptions> optionSets() {
    std::vector<NamedOptions> sets;
    auto add = [&](const std::string& name, auto change) {
        drm::EncodeOptions o;
        // Keep the chosen levers: small meshes would otherwise often be
        // written with none, and their contexts would never be decoded.
        o.tryWithoutLevers = false;
        // The sets below are about the ranks' branches: with the coder left
        // to the encoder, a small mesh may come out topological instead.
        o.connectivity = drm::ConnectivityCoder::Ranks;
        change(o);
        sets.push_back({name, o});
    };
    add("default", [](drm::EncodeOptions& o) { o.connectivity = drm::ConnectivityCoder::Auto; });
    // The topological coder: its sections, with copies from a cut,
    // at the grid's extremes and with the input order kept.
    add("topological", [](drm::EncodeOptions& o) { o.connectivity = drm::ConnectivityCoder::Topological; });
    add("topological-bits1-keep-order", [](drm::EncodeOptions& o) {
        o.connectivity = drm::ConnectivityCoder::Topological;
        o.bits = 1;
        o.keepVertexOrder = true;
    });
    add("topological-bits21", [](drm::EncodeOptions& o) {
        o.connectivity = drm::ConnectivityCoder::Topological;
        o.bits = 21;
    });
    add("bits4", [](drm::EncodeOptions& o) { o.bits = 4; });
    add("bits21", [](drm::EncodeOptions& o) { o.bits = 21; });
    add("bits1", [](drm::EncodeOptions& o) { o.bits = 1; });  // many vertices share a grid point
    add("bits2", [](drm::EncodeOptions& o) { o.bits = 2; });
    add("bits1-raw", [](drm::EncodeOptions& o) {
        o.bits = 1;
        o.geometry = drm::GeometryCoder::Raw;
    });
    add("raw", [](drm::EncodeOptions& o) { o.geometry = drm::GeometryCoder::Raw; });
    add("raw-bits21-parallelogram", [](drm::EncodeOptions& o) {
        o.geometry = drm::GeometryCoder::Raw;
        o.bits = 21;
        o.predictor = drm::Predictor::Parallelogram;
    });
    add("sorted-bits21", [](drm::EncodeOptions& o) {  // 63-bit Morton keys
        o.geometry = drm::GeometryCoder::Sorted;
        o.bits = 21;
    });
    add("parallelogram", [](drm::EncodeOptions& o) { o.predictor = drm::Predictor::Parallelogram; });
    add("midpoint-curvature", [](drm::EncodeOptions& o) {
        o.predictor = drm::Predictor::Midpoint;
        o.curvature = true;
    });
    add("no-levers", [](drm::EncodeOptions& o) { o.levers = drm::Levers::none(); });
    add("filter-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.topologicalFilter = true;
    });
    add("gap-closing-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.gapClosing = true;
    });
    add("confidence-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.confidenceContext = true;
    });
    add("angle-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.angleOrder = true;
    });
    add("front-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.frontNeighbours = true;
    });
    // The fans are walked for the boundary flags alone (gap closing and
    // front neighbours walk them too).
    add("boundary-only", [](drm::EncodeOptions& o) {
        o.levers = drm::Levers::none();
        o.levers.boundaryFlag = true;
    });
    add("keep-order", [](drm::EncodeOptions& o) { o.keepVertexOrder = true; });
    // The refine coder with its low bits fixed, so the file always holds it
    // (left to the encoder, small meshes fall back to the spanning tree).
    add("refine-k2", [](drm::EncodeOptions& o) {
        o.geometry = drm::GeometryCoder::Refine;
        o.refineBits = 2;
    });
    add("refine-bits4-k3", [](drm::EncodeOptions& o) {  // a 1-bit coarse grid: most points coincide
        o.geometry = drm::GeometryCoder::Refine;
        o.bits = 4;
        o.refineBits = 3;
    });
    add("refine-k5-keep-order-curvature", [](drm::EncodeOptions& o) {
        o.geometry = drm::GeometryCoder::Refine;
        o.refineBits = 5;
        o.keepVertexOrder = true;
        o.curvature = true;
    });
    add("keep-order-bits12-try-without", [](drm::EncodeOptions& o) {
        o.keepVertexOrder = true;
        o.tryWithoutLevers = true;
    });
    // The two connectivity parts, forced on small meshes: the seam
    // rule, kept vertices, starts on shared ones; with the paper's method,
    // with refine's second pass over both parts' faces, and at 2 bits
    // (points on one grid point across the split).
    add("two-parts", [](drm::EncodeOptions& o) { o.connectivityParts = 2; });
    add("two-parts-no-levers", [](drm::EncodeOptions& o) {
        o.connectivityParts = 2;
        o.levers = drm::Levers::none();
    });
    add("two-parts-refine-k2-keep-order", [](drm::EncodeOptions& o) {
        o.connectivityParts = 2;
        o.geometry = drm::GeometryCoder::Refine;
        o.refineBits = 2;
        o.keepVertexOrder = true;
    });
    add("two-parts-bits2", [](drm::EncodeOptions& o) {
        o.connectivityParts = 2;
        o.bits = 2;
    });
    return sets;
}

}  // namespace drm_test

#endif  // DRM_TEST_OPTION_SETS_H
