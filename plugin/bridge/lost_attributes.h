// Which of a MeshLab mesh's attributes go into a .drm file, and what stays
// behind.
//
// The user should hear, when saving, which of their mesh's data a .drm file
// does not keep; and, when opening, what is missing (texture files).
#ifndef DRM_MESHLAB_LOST_ATTRIBUTES_H
#define DRM_MESHLAB_LOST_ATTRIBUTES_H

#include "bridge/meshlab_api.h"

#include <drmcodec/drmcodec.h>

#include <QString>

#include <string>
#include <vector>

namespace drm_meshlab {

// The vcg::tri::io::Mask bits of the export dialog's boxes a .drm file
// honours: vertex colour, normal, quality and texture coordinate, face
// colour and quality, wedge texture coordinates.
extern const int kExportCapability;

// The boxes of `mask` (vcg::tri::io::Mask bits, from the export dialog or
// meshlabserver's -m) that the mesh has data for and a .drm file keeps.
int exportedAttributes(const MeshModel& m, int mask);

// Names of what `m` carries that the saved file does not keep ("vertex
// radii", "wedge colours", "polygonal faces (saved as their triangles)",
// "vertex colours (not ticked)", ...), in a fixed order: what .drm files
// cannot hold, what was not ticked in `kept`, and what `mesh` carried but
// the encoder wrote no section for (`stats`).
std::vector<std::string> lostAttributes(const MeshModel& m, int kept, const drm::Mesh& mesh,
                                        const drm::Stats& stats);

// Sentences about a decoded mesh for the log: texture files not found in
// `folder` (the .drm file's), per-corner normals averaged per vertex.
std::vector<std::string> openNotes(const drm::Mesh& mesh, const QString& folder);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_LOST_ATTRIBUTES_H
