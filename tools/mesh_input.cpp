// Loading meshes for encoding and the one-line summary (see mesh_input.h).
#include "mesh_input.h"

#include "cli.h"

#include <drm_vcg/manifold.h>

namespace drm {
namespace cli {

drm::vcgio::LoadedMesh loadMeshForEncoding(const std::string& path) {
    drm::vcgio::LoadedMesh loaded = drm::vcgio::loadMesh(path);
    const drm::vcgio::ManifoldReport report = drm::vcgio::checkManifold(loaded.mesh);
    if (!report.ok()) throw drm::Error("cannot encode " + path + ": " + report.summary());
    return loaded;
}

void printNotes(const std::vector<std::string>& notes) {
    for (const std::string& note : notes) printNote(note);
}

std::string summaryOf(const drm::Stats& stats) {
    return "V " + std::to_string(stats.vertices) + ", F " + std::to_string(stats.faces) + ", " +
           std::to_string(stats.totalBytes) + " bytes; bits per vertex: connectivity " +
           fixed(stats.connectivityBitsPerVertex(), 3) + ", geometry " + fixed(stats.geometryBitsPerVertex(), 3) +
           ", total " + fixed(stats.totalBitsPerVertex(), 3);
}

}  // namespace cli
}  // namespace drm
