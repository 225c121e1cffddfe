#include "filter_drm/rank_colouring.h"

#include "bridge/encoding.h"

#include <drm_vcg/rank_palette.h>

#include <cstdio>

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
        throw drm::Error("the codec ranked " + std::to_string(faceRank.size()) + " faces, but the mesh has " +
                         std::to_string(cm.fn));
    return facesPerBucket;
}

std::vector<std::string> rankReport(const std::vector<uint64_t>& facesPerBucket, const drm::Stats& stats) {
    std::vector<std::string> lines;
    uint64_t faces = 0;
    for (uint64_t n : facesPerBucket) faces += n;
    lines.push_back("Faces per colour:");
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount && size_t(bucket) < facesPerBucket.size(); ++bucket) {
        const drm::vcgio::RankColour colour = drm::vcgio::rankBucketColour(bucket);
        const uint64_t n = facesPerBucket[size_t(bucket)];
        char line[160];
        std::snprintf(line, sizeof(line), "  %-15s #%02x%02x%02x %10llu  %6.2f%%", drm::vcgio::rankBucketName(bucket),
                      colour.r, colour.g, colour.b, (unsigned long long)n,
                      faces ? 100.0 * double(n) / double(faces) : 0.0);
        lines.push_back(line);
    }
    // The rank codes themselves: rank 0 marks a boundary edge, which
    // creates no face, so these counts differ from the faces above.
    std::string histogram = "Rank codes (0 = boundary edge):";
    const size_t shown = 12;  // the tail of a long histogram is summed
    uint64_t tail = 0;
    size_t tailFrom = 0;
    for (size_t r = 0; r < stats.rankHistogram.size(); ++r) {
        const uint64_t n = stats.rankHistogram[r];
        if (r < shown) {
            if (n > 0) histogram += " " + std::to_string(r) + ":" + std::to_string(n);
        } else {
            if (tail == 0 && n > 0) tailFrom = r;
            tail += n;
        }
    }
    if (tail > 0)
        histogram += " " + std::to_string(tailFrom) + "-" + std::to_string(stats.rankHistogram.size() - 1) + ":" +
                     std::to_string(tail);
    lines.push_back(histogram);
    return lines;
}

}  // namespace drm_meshlab
