// Encoding a MeshLab mesh, and the sentences the plugins log about it.
#ifndef DRM_MESHLAB_ENCODING_H
#define DRM_MESHLAB_ENCODING_H

#include <drm/drm.h>

#include <string>

namespace drm_meshlab {

// drm::encode, with a friendlier refusal: when the codec rejects the mesh,
// the error also counts every non-manifold or misoriented element
// (drm::vcgio::checkManifold) and names the MeshLab filters that repair
// them, since the codec itself stops at the first one.
drm::Encoded encodeMesh(const drm::Mesh& mesh, const drm::EncodeOptions& options);

// One line: "6475 vertices, 12946 faces, 12 bits, parallelogram predictor:
// connectivity 0.65 bpv, geometry 12.79 bpv, total 13.44 bpv (10877 bytes)".
std::string statsSummary(const drm::Stats& stats);

// "0.65" (two decimals, no locale).
std::string twoDecimals(double value);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_ENCODING_H
