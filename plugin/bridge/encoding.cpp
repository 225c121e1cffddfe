#include "bridge/encoding.h"

#include <drm_vcg/manifold.h>

#include <cstdio>

namespace drm_meshlab {

drm::Encoded encodeMesh(const drm::Mesh& mesh, const drm::EncodeOptions& options) {
    try {
        return drm::encode(mesh, options);
    } catch (const drm::Error& e) {
        std::string message = e.what();
        drm::vcgio::ManifoldReport report;
        try {
            report = drm::vcgio::checkManifold(mesh);
        } catch (const drm::Error&) {
            throw drm::Error(message);  // the codec's own sentence already says what is wrong
        }
        if (!report.ok()) {
            if (!message.empty() && message.back() != '.') message += '.';
            message += " In all: " + report.summary() +
                       ". Filters > Cleaning and Repairing > \"Repair non Manifold Edges by splitting "
                       "vertices\", \"Repair non Manifold Vertices by splitting\" and Filters > Normals, "
                       "Curvatures and Orientation > \"Re-Orient all faces coherentely\" can fix this.";
        }
        throw drm::Error(message);
    }
}

std::string twoDecimals(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.2f", value);
    return text;
}

std::string statsSummary(const drm::Stats& stats) {
    return std::to_string(stats.vertices) + " vertices, " + std::to_string(stats.faces) + " faces, " +
           std::to_string(stats.bits) + " bits, " + drm::predictorName(stats.predictor) +
           " predictor: connectivity " + twoDecimals(stats.connectivityBitsPerVertex()) + " bpv, geometry " +
           twoDecimals(stats.geometryBitsPerVertex()) + " bpv, total " +
           twoDecimals(stats.totalBitsPerVertex()) + " bpv (" + std::to_string(stats.totalBytes) + " bytes)";
}

}  // namespace drm_meshlab
