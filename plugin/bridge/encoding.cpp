#include "bridge/encoding.h"

#include "bridge/log_text.h"

#include <cstdio>

namespace drm_meshlab {

drm::Encoded encodeMesh(const drm::Mesh& mesh, const drm::EncodeOptions& options) {
    return drm::encode(mesh, options);
}

std::string twoDecimals(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.2f", value);
    return text;
}

std::string statsSummary(const drm::Stats& stats) {
    const std::string repairs = drm::describeRepairs(stats);
    // A topological file has no apex predictor: it says its coder instead.
    const std::string coder = stats.connectivity == drm::ConnectivityCoder::Topological
                                  ? std::string("topological connectivity")
                                  : std::string(drm::predictorName(stats.predictor)) + " predictor";
    return std::to_string(stats.vertices) + " vertices, " + std::to_string(stats.faces) + " faces, " +
           std::to_string(stats.bits) + " bits, " + coder + ": " + sizeBreakdown(stats) +
           (repairs.empty() ? "" : "; not a manifold oriented surface, so cut and restored exactly: " + repairs);
}

}  // namespace drm_meshlab
