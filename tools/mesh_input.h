// Reading the mesh a command is about to encode, and reporting on it.
#ifndef DRM_TOOLS_MESH_INPUT_H
#define DRM_TOOLS_MESH_INPUT_H

#include <drm/drm.h>
#include <drm_vcg/mesh_io.h>

#include <string>
#include <vector>

namespace drm {
namespace cli {

// loadMesh, then the manifold check: a mesh the codec would refuse is
// refused here with every problem counted, e.g. "cannot encode a.ply:
// 2 non-manifold edges; first: edge (3, 7) is shared by 3 faces (...)".
drm::vcgio::LoadedMesh loadMeshForEncoding(const std::string& path);

void printNotes(const std::vector<std::string>& notes);

// "V 6475, F 12946, 5432 bytes; bits per vertex: connectivity 0.712,
// geometry 21.301, total 22.100"
std::string summaryOf(const drm::Stats& stats);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_MESH_INPUT_H
