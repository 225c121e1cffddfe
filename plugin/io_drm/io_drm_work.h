// What opening and saving a .drm file in MeshLab do, for either plugin API:
// io_drm.cpp calls these and turns their results and exceptions into what
// its API expects.
#ifndef DRM_MESHLAB_IO_DRM_WORK_H
#define DRM_MESHLAB_IO_DRM_WORK_H

#include "bridge/meshlab_api.h"

#include <QString>

#include <string>
#include <vector>

namespace drm_meshlab {

// What an open or save has to tell the user besides success: notes (a
// texture file not found, computed normals left out), what of the mesh the
// file does not keep, and one summary line (the file's size and where it
// goes).
struct IoReport {
    std::vector<std::string> notes;
    std::string notKept;  // "drm: note: x.drm does not keep the mesh's ...", or empty
    std::string summary;
};

// The format names the plugin registers, and the dialog's description.
extern const char* const kDrmExtension;    // "DRM"
extern const char* const kDrmDescription;  // "Distance-ranked compressed mesh"

// Reads and decodes `fileName` into `m` (cleared first); returns the
// vcg::tri::io::Mask bits of what it filled. Throws on any failure, with
// `m` left empty.
int openDrm(const QString& fileName, MeshModel& m, vcg::CallBackPos* cb, IoReport& report);

// Encodes `m` with the export dialog's `mask` and `parameters` and replaces
// `fileName` atomically. Throws on any failure; an existing file is then
// left as it was.
void saveDrm(const QString& fileName, MeshModel& m, int mask, const RichParameterList& parameters,
             vcg::CallBackPos* cb, IoReport& report);

// The sentence for a failed open or save of `fileName`, from inside a
// catch (...) block: "cannot open x.drm: corrupt file: ...".
std::string failureMessage(const char* verb, const QString& fileName);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_IO_DRM_WORK_H
