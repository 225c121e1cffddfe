// Painting the faces of a MeshLab mesh by distance rank: the work of the
// "Colorize Faces by Distance Rank" filter, for either plugin API (the log
// text itself: bridge/log_text.h).
#ifndef DRM_MESHLAB_RANK_COLOURING_H
#define DRM_MESHLAB_RANK_COLOURING_H

#include "bridge/meshlab_api.h"

#include <drmcodec/drmcodec.h>

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

// The MeshModel components the filter fills (per-face colour and quality):
// its requirements and its post-condition.
constexpr int kRankColouringComponents = MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;

// What the filter logs after colouring a mesh.
struct RankColouringReport {
    std::string summary;        // "Distance ranks of NAME: connectivity 1.23 bpv (...)"
    std::vector<uint64_t> facesPerBucket;  // for the legend (log_text.h)
    std::string histogram;      // rankHistogramText
};

// Encodes `m` with the rank coder and the options in `parameters`, enables
// face colour and quality and fills them by rank. Throws drm::Error (bad
// parameter, mesh the codec refuses, cancel) with `m`'s faces unchanged.
RankColouringReport colourMeshByRank(MeshModel& m, const RichParameterList& parameters, vcg::CallBackPos* cb);

// The filter's name in menus and .mlx scripts: unique across MeshLab, and
// never to change.
extern const char* const kRankFilterName;  // "Colorize Faces by Distance Rank"
// Its name in PyMeshLab (MeshLab 2021.05+): lower case, words joined by _.
extern const char* const kRankFilterPythonName;

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_RANK_COLOURING_H
