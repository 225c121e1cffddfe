// Loading meshes for encoding and the one-line summary (see mesh_input.h).
#include "mesh_input.h"

#include "cli.h"

#include <mutex>

namespace drm {
namespace cli {

drm::vcgio::LoadedMesh loadMeshForEncoding(const std::string& path) {
    // vcglib's readers, which drm still uses for OFF and binary STL, keep
    // shared state (error tables filled on first use): `drm encode -o` and
    // `drm verify` with several files read one file at a time and encode in
    // parallel.
    static std::mutex reading;
    drm::vcgio::LoadedMesh loaded;
    {
        std::lock_guard<std::mutex> lock(reading);
        loaded = drm::vcgio::loadMesh(path);
    }
    if (loaded.mesh.vertexCount() == 0) throw drm::Error(drm::ErrorKind::InvalidInput, "cannot encode " + path + ": the mesh has no vertices");
    return loaded;
}

std::string repairsOf(const drm::Stats& stats) {
    const std::string repairs = drm::describeRepairs(stats);
    if (repairs.empty()) return repairs;
    return "cut into manifold pieces for the traversal and restored exactly on decoding: " + repairs + ", " +
           fixed(8.0 * double(stats.repairBytes) / double(stats.vertices), 3) + " bits per vertex";
}

void printNotes(const std::vector<std::string>& notes) {
    for (const std::string& note : notes) printNote(note);
}

std::string summaryOf(const drm::Stats& stats) {
    return "V " + std::to_string(stats.vertices) + ", F " + std::to_string(stats.faces) + ", " +
           std::to_string(stats.totalBytes) + " bytes; bits per vertex: connectivity " +
           fixed(stats.connectivityBitsPerVertex(), 3) + ", geometry " + fixed(stats.geometryBitsPerVertex(), 3) +
           (stats.attributeBytes > 0
                ? ", attributes " + fixed(stats.vertices ? 8.0 * double(stats.attributeBytes) / double(stats.vertices) : 0.0, 3)
                : std::string()) +
           ", total " + fixed(stats.totalBitsPerVertex(), 3);
}

}  // namespace cli
}  // namespace drm
