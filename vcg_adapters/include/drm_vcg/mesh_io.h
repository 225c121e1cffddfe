// Reading meshes (PLY with drm's own reader, not vcglib's; mesh_io.cpp says
// how each format is read), and writing binary PLY and OBJ.
//
// The codec keeps vertex order, face order and face orientation, so the
// reader must too: nothing is cleaned, merged, reordered or reoriented.
// C++14-clean, no Qt.
#ifndef DRM_VCG_MESH_IO_H
#define DRM_VCG_MESH_IO_H

#include <drmcodec/drmcodec.h>

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
    // Other files read besides the mesh file (an OBJ's material library),
    // so that a caller can refuse to write over them.
    std::vector<std::string> otherFilesRead;
};

// Reads a PLY, OBJ, OFF or STL file (chosen by extension, any case).
// Vertices and faces stay in file order, corners in file order; polygons
// are fan-split into triangles in place. STL, which has no shared vertices,
// is welded on bit-identical positions in order of first appearance.
// Throws drm::Error("cannot read FILE: reason").
LoadedMesh loadMesh(const std::string& path);

// True if loadMesh would try to read this file (by extension).
bool isMeshFileName(const std::string& path);

// Optional per-face data written by savePly instead of the mesh's own face
// colours and quality (drm ranks' colouring). Either vector may be empty;
// otherwise it holds one entry per face (rgb: three bytes per face).
struct FaceAttributes {
    std::vector<uint8_t> rgb;
    std::vector<float> quality;
};

// Writes binary little-endian PLY with the names vcglib and MeshLab read:
// float x, y, z, then whichever the mesh carries of float nx, ny, nz, uchar
// red, green, blue, alpha, float quality, float texture_u, texture_v per
// vertex; uchar/int vertex_indices per face, then float texcoord (a list of
// six: the corners' u, v), int texnumber, uchar red, green, blue, alpha,
// float quality; a `comment TextureFile NAME` line per texture. Atomic: the
// file appears complete or not at all, and an existing file is only
// replaced on success. Returns what the mesh carries that PLY cannot hold
// (per-corner normals, materials, metadata), as notes. Throws drm::Error.
std::vector<std::string> savePly(const std::string& path, const drm::Mesh& mesh,
                                 const FaceAttributes* attrs = nullptr);

// Writes Wavefront OBJ: `v x y z [r g b]`, `vt` (per corner, or per vertex),
// `vn` (per vertex, or per corner), `f v/t/n`, `mtllib` and `usemtl` groups
// when the mesh has materials. The material library (the statements kept
// in the metadata "obj.mtl", read again as an .mtl file is, or, for a mesh
// with textures but none, one material per texture) is written to
// objLibraryPath(path) and the `mtllib` line names it: no other file is
// written, whatever names the mesh holds. An existing library with the same
// text is left alone; otherwise it is replaced, as atomically as the OBJ.
// A material, texture or library name that OBJ cannot hold as written (a
// line break, blanks at its ends, a '#' after a blank) is refused before
// anything is written. Returns what OBJ cannot hold (alpha, quality, face
// colours), as notes. Throws drm::Error.
std::vector<std::string> saveObj(const std::string& path, const drm::Mesh& mesh);

// The material library saveObj writes for an OBJ: the same folder and name
// with the extension .mtl (out.obj: out.mtl).
std::string objLibraryPath(const std::string& objPath);

// savePly or saveObj by the extension of `path` (.ply or .obj, any case);
// throws drm::Error for any other.
std::vector<std::string> saveMesh(const std::string& path, const drm::Mesh& mesh);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_MESH_IO_H
