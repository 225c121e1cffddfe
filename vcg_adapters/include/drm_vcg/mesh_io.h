// Reading meshes through vcglib's importers, and writing binary PLY.
//
// The codec keeps vertex order, face order and face orientation, so the
// reader must too: nothing is cleaned, merged, reordered or reoriented.
// C++14-clean, no Qt.
#ifndef DRM_VCG_MESH_IO_H
#define DRM_VCG_MESH_IO_H

#include <drm/drm.h>

#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {

struct LoadedMesh {
    drm::Mesh mesh;
    // Sentences for the user: what the reader changed (polygons split into
    // triangles, STL corners welded) and what the file holds that a .drm
    // file does not keep (colours, normals, texture coordinates, ...).
    std::vector<std::string> notes;
};

// Reads a PLY, OBJ, OFF or STL file (chosen by extension, any case).
// Vertices and faces stay in file order, corners in file order; polygons
// are fan-split into triangles in place. STL, which has no shared vertices,
// is welded on bit-identical positions in order of first appearance.
// Throws drm::Error("cannot read FILE: reason").
LoadedMesh loadMesh(const std::string& path);

// True if loadMesh would try to read this file (by extension).
bool isMeshFileName(const std::string& path);

// Optional per-face data written by savePly. Either vector may be empty
// (the property is then left out); otherwise it holds one entry per face
// (rgb: three bytes per face).
struct FaceAttributes {
    std::vector<uint8_t> rgb;
    std::vector<float> quality;
};

// Writes binary little-endian PLY: float x, y, z per vertex, uchar/int
// vertex_indices per face, then the optional face red/green/blue (uchar)
// and quality (float). Atomic: the file appears complete or not at all, and
// an existing file is only replaced on success. Throws drm::Error.
void savePly(const std::string& path, const drm::Mesh& mesh, const FaceAttributes* attrs = nullptr);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_MESH_IO_H
