// Checks shared by the mesh writers: a mesh they are given must be
// consistent (array sizes, face indices) before a byte is written.
#ifndef DRM_VCG_MESH_CHECKS_H
#define DRM_VCG_MESH_CHECKS_H

#include <drmcodec/drmcodec.h>

#include <string>

namespace drm {
namespace vcgio {

// Throws drm::Error("cannot write PATH: reason") if the mesh's arrays do
// not have the sizes drmcodec.h gives them, a face refers to a missing vertex,
// or a face's texture or material index is out of its list.
void checkMeshForWriting(const std::string& path, const drm::Mesh& mesh);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_MESH_CHECKS_H
