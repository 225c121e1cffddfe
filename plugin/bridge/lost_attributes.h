// What a MeshLab mesh carries that a .drm file does not keep.
//
// A .drm file stores quantized positions and oriented triangles only; the
// user should hear, when saving, which of their mesh's data stays behind.
#ifndef DRM_MESHLAB_LOST_ATTRIBUTES_H
#define DRM_MESHLAB_LOST_ATTRIBUTES_H

#include <common/interfaces.h>

#include <string>
#include <vector>

namespace drm_meshlab {

// Names of the attributes of `m` a .drm file drops ("vertex colours",
// "face quality", "polygonal faces", ...), in a fixed order. Normals are
// not listed: MeshLab always has them, and recomputes them on open.
std::vector<std::string> lostAttributes(const MeshModel& m);

// "a, b and c".
std::string joinedList(const std::vector<std::string>& items);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_LOST_ATTRIBUTES_H
