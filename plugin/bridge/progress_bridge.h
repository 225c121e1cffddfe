// The codec's progress callback, reported to MeshLab's progress bar.
#ifndef DRM_MESHLAB_PROGRESS_BRIDGE_H
#define DRM_MESHLAB_PROGRESS_BRIDGE_H

#include "bridge/meshlab_api.h"

#include <drmcodec/drmcodec.h>

namespace drm_meshlab {

enum class ProgressStyle {
    // The GUI: percentage (0..100) and the codec's stage label ("ranking")
    // for the progress bar and status bar, only when the percentage changes
    // (the codec reports often).
    StatusBar,
    // meshlabserver, which prints each label as it comes, without a
    // separator, and drops a call whose percentage equals the last one: each
    // stage once per operation, as a line of its own ("drm: ranking\n"),
    // through `cb`, or on stdout and into the -l log when `cb` is null (the
    // server opens and saves files without a callback).
    Lines,
};

// A drm::Progress that forwards to `cb` in the given style. MeshLab's
// callback returning false cancels the codec (it then throws drm::Error).
// Empty when `cb` is null in the StatusBar style.
drm::Progress progressTo(vcg::CallBackPos* cb, ProgressStyle style);

// The style of the program we run in (host.h).
drm::Progress progressTo(vcg::CallBackPos* cb);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_PROGRESS_BRIDGE_H
