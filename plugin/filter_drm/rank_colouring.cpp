#include "filter_drm/rank_colouring.h"

#include <drm_vcg/rank_palette.h>

namespace drm_meshlab {

std::vector<uint64_t> colourFacesByRank(CMeshO& cm, const std::vector<uint32_t>& faceRank) {
    std::vector<uint64_t> facesPerBucket(drm::vcgio::kRankBucketCount, 0);
    size_t live = 0;
    for (CMeshO::FaceIterator fi = cm.face.begin(); fi != cm.face.end(); ++fi) {
        if (fi->IsD()) continue;
        if (live >= faceRank.size()) break;
        const uint32_t rank = faceRank[live++];
        const drm::vcgio::RankColour colour = drm::vcgio::rankColour(rank);
        fi->C() = vcg::Color4b(colour.r, colour.g, colour.b, 255);
        fi->Q() = CFaceO::QualityType(rank);
        ++facesPerBucket[size_t(drm::vcgio::rankBucket(rank))];
    }
    if (live != faceRank.size() || live != size_t(cm.fn))
        throw drm::Error(drm::ErrorKind::InvalidInput, "the codec ranked " + std::to_string(faceRank.size()) + " faces, but the mesh has " +
                         std::to_string(cm.fn));
    return facesPerBucket;
}

}  // namespace drm_meshlab
