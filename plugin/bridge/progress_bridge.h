// The codec's progress callback, reported to MeshLab's progress bar.
#ifndef DRM_MESHLAB_PROGRESS_BRIDGE_H
#define DRM_MESHLAB_PROGRESS_BRIDGE_H

#include <common/interfaces.h>

#include <drm/drm.h>

namespace drm_meshlab {

// A drm::Progress that forwards to `cb` as a percentage (0..100) with the
// codec's stage label, only when the percentage changes: the codec reports
// often, and meshlabserver prints the label on every call. MeshLab's
// callback returning false cancels the codec (it then throws drm::Error).
// Empty when `cb` is null (meshlabserver opens and saves without one).
drm::Progress progressTo(vcg::CallBackPos* cb);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_PROGRESS_BRIDGE_H
