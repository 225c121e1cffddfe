#include "filter_drm/rank_colouring.h"

#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/log_text.h"
#include "bridge/progress_bridge.h"

#include <drm_vcg/rank_palette.h>
#include <drm_vcg/vcg_mesh.h>

namespace drm_meshlab {

const char* const kRankFilterName = "Colorize Faces by Distance Rank";
const char* const kRankFilterPythonName = "compute_color_by_distance_rank_per_face";

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
        throw drm::Error(drm::ErrorKind::InvalidInput, "the codec ranked " + std::to_string(faceRank.size()) +
                                                           " faces, but the mesh has " + std::to_string(cm.fn));
    return facesPerBucket;
}

RankColouringReport colourMeshByRank(MeshModel& m, const RichParameterList& parameters, vcg::CallBackPos* cb) {
    drm::EncodeOptions options = encodeOptionsFrom(parameters);
    options.connectivity = drm::ConnectivityCoder::Ranks;  // the ranks are what the colours show
    options.progress = progressTo(cb);
    const drm::Mesh mesh = drm::vcgio::fromVcg(m.cm);
    const drm::Encoded encoded = encodeMesh(mesh, options);

    // MeshLab enables the requirements before running a filter; this keeps
    // the filter correct when called some other way.
    m.updateDataMask(kRankColouringComponents);
    RankColouringReport report;
    report.facesPerBucket = colourFacesByRank(m.cm, encoded.faceRank);
    report.summary = "Distance ranks of " + m.label().toStdString() + ": connectivity " +
                     twoDecimals(encoded.stats.connectivityBitsPerVertex()) + " bpv (" +
                     std::to_string(encoded.stats.connectivityBytes) + " bytes for " +
                     std::to_string(encoded.stats.vertices) + " vertices); " + statsSummary(encoded.stats);
    report.histogram = rankHistogramText(encoded.stats);
    return report;
}

}  // namespace drm_meshlab
