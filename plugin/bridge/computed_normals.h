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
// degrees to which a .drm file keeps normals (drmcodec.h, normal bits 10).
extern const double kComputedNormalTolerance;

// True when every live vertex's normal points the way the angle-weighted
// normal from its faces does (within kComputedNormalTolerance), zero-length
// normals matching zero-length ones (vertices in no face, or in degenerate
// faces only). A `mergeStep` above 0 says the file may weld vertices on one
// grid point of that size, as the codec does for meshes with other
// per-vertex attributes (drm::EncodeOptions::weld): each normal must then
// also match the one computed over every face at its position, and no two
// different positions may lie within a step of each other (they could
// become one vertex). False for a mesh without faces (a point cloud's
// normals are always its own) or with a non-finite position.
bool normalsAreComputedFromFaces(const CMeshO& cm, double mergeStep);

// The grid step of `bits` quantization bits over the live vertices'
// bounding box: its longest side over 2^bits - 1 (an upper bound of the
// codec's step, so vertices it may merge are found).
double gridStep(const CMeshO& cm, int bits);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_COMPUTED_NORMALS_H
