// Reading the mesh a command is about to encode, and reporting on it.
#ifndef DRM_TOOLS_MESH_INPUT_H
#define DRM_TOOLS_MESH_INPUT_H

#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <string>
#include <vector>

namespace drm {
namespace cli {

// loadMesh; a file without vertices is refused here, naming the file.
// Non-manifold meshes are the codec's business (it cuts and restores them).
// Thread-safe: files are read one at a time (vcglib's OFF and STL readers share state).
drm::vcgio::LoadedMesh loadMeshForEncoding(const std::string& path);

// "" for a mesh that needed no repair, otherwise a sentence counting the
// vertex copies, turned faces and faces repeating a vertex, and their cost.
std::string repairsOf(const drm::Stats& stats);

void printNotes(const std::vector<std::string>& notes);

// "V 6475, F 12946, 5432 bytes; bits per vertex: connectivity 0.712,
// geometry 21.301, total 22.100"
std::string summaryOf(const drm::Stats& stats);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_MESH_INPUT_H
