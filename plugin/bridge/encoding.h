// Encoding a MeshLab mesh, and the sentences the plugins log about it.
#ifndef DRM_MESHLAB_ENCODING_H
#define DRM_MESHLAB_ENCODING_H

#include <drmcodec/drmcodec.h>

#include <string>

namespace drm_meshlab {

// drm::encode (any triangle mesh: non-manifold ones are cut and restored
// by the codec itself).
drm::Encoded encodeMesh(const drm::Mesh& mesh, const drm::EncodeOptions& options);

// One line: "6475 vertices, 12946 faces, 12 bits, parallelogram predictor:
// 10877 bytes, 13.44 bpv = header 31 B (0.04) + connectivity 526 B (0.65) +
// geometry 10320 B (12.75)" (every part of the file, see sizeBreakdown), and
// what the codec repaired, if anything.
std::string statsSummary(const drm::Stats& stats);

// "0.65" (two decimals, no locale).
std::string twoDecimals(double value);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_ENCODING_H
