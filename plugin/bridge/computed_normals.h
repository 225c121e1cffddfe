// Whether a MeshLab mesh's vertex normals are its own or the ones MeshLab
// computes from the faces.
//
// MeshLab gives every mesh it opens vertex normals: the file's, or, when the
// file has none, the angle-weighted mean of the faces' normals around each
// vertex (vcg::tri::UpdateNormal::PerVertexAngleWeighted). Storing the
// computed ones would spend about 5 bits per vertex on data MeshLab derives
// again when it opens the file, so the export leaves them out.
#ifndef DRM_MESHLAB_COMPUTED_NORMALS_H
#define DRM_MESHLAB_COMPUTED_NORMALS_H

#include "bridge/meshlab_api.h"

namespace drm_meshlab {

// The largest angle between a vertex's normal and the computed one, in
// radians, for the two to count as the same: 0.08 degrees, below the 0.17
// degrees to which a .drm file keeps normals (drm.h, normal bits 10).
extern const double kComputedNormalTolerance;

// True when every live vertex's normal points the way the angle-weighted
// normal from its faces does (within kComputedNormalTolerance), zero-length
// normals matching zero-length ones (vertices in no face, or in degenerate
// faces only). With `verticesMayMerge` (the file may weld vertices at one
// position, as the codec does for meshes with other per-vertex attributes:
// drm::EncodeOptions::weld), each normal must also match the one computed
// over every face at its position. False for a mesh without faces: a point
// cloud's normals are always its own.
bool normalsAreComputedFromFaces(const CMeshO& cm, bool verticesMayMerge);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_COMPUTED_NORMALS_H
