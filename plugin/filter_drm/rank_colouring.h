// Painting faces of a MeshLab mesh by rank (the log lines about it: bridge/log_text.h).
#ifndef DRM_MESHLAB_RANK_COLOURING_H
#define DRM_MESHLAB_RANK_COLOURING_H

#include <common/interfaces.h>

#include <drm/drm.h>

#include <cstdint>
#include <string>
#include <vector>

namespace drm_meshlab {

// Gives the f-th live (non-deleted) face of `cm` the colour of faceRank[f]
// (drm_vcg/rank_palette.h, the palette of `drm ranks`) and the rank as its
// quality; faceRank is drm::Encoded::faceRank of drm::vcgio::fromVcg(cm).
// Per-face colour and quality must be enabled. Returns the number of faces
// in each palette bucket. Throws drm::Error if the counts disagree.
std::vector<uint64_t> colourFacesByRank(CMeshO& cm, const std::vector<uint32_t>& faceRank);

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_RANK_COLOURING_H
