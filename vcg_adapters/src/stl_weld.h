// Welding an STL triangle soup into an indexed mesh.
//
// STL stores three positions per triangle and no vertex indices, so a
// shared vertex appears once per triangle using it. Corners at bit-identical
// positions are one vertex (the same rule as the benchmark meshes in
// ../shared/meshes, whose STL sources were welded this way); nothing closer
// than identical is merged, so no geometry changes.
#ifndef DRM_VCG_STL_WELD_H
#define DRM_VCG_STL_WELD_H

#include <drmcodec/drmcodec.h>

namespace drm {
namespace vcgio {

// Vertices are numbered in order of first appearance; faces keep their order
// and corner order.
drm::Mesh weldIdenticalPositions(const drm::Mesh& soup);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_STL_WELD_H
