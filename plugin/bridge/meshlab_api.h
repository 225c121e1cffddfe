// The MeshLab headers the plugins use, for the plugin API they are built for.
//
// DRM_MESHLAB_API (set by plugin/CMakeLists.txt from DRM_MESHLAB_RELEASE):
//   2020  MeshLab 2020.09 and older: MeshIOInterface / MeshFilterInterface,
//         errors returned as false with errorMessage set.
//   2021  MeshLab 2021.05 and newer (2022.02, 2025.07): IOPlugin /
//         FilterPlugin, errors thrown as MLException.
// Include this before any GL or Qt OpenGL header: MeshLab's headers include
// GLEW, which must come first.
#ifndef DRM_MESHLAB_API_H
#define DRM_MESHLAB_API_H

#if !defined(DRM_MESHLAB_API)
#error "DRM_MESHLAB_API must be defined (2020 or 2021): see plugin/CMakeLists.txt"
#endif

#if DRM_MESHLAB_API >= 2021
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/ml_document/mesh_model.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/interfaces/filter_plugin.h>
#include <common/plugins/interfaces/io_plugin.h>
#else
#include <common/interfaces.h>
#endif

namespace drm_meshlab {

// The vendor MeshLab 2021.05 on lists for both plugins (Help > Plugin Info).
constexpr const char* kPluginVendor = "drm (distance-ranked mesh compression)";

// Enables the optional components that the vcg::tri::io::Mask bits of an
// opened file need (MeshModel::Enable in 2020.09, enable from 2021.05 on).
inline void enableComponents(MeshModel& m, int ioMask) {
#if DRM_MESHLAB_API >= 2021
    m.enable(ioMask);
#else
    m.Enable(ioMask);
#endif
}

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_API_H
