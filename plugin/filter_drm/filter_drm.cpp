#include "filter_drm/filter_drm.h"

#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/error_message.h"
#include "bridge/host.h"
#include "bridge/log_text.h"
#include "bridge/progress_bridge.h"
#include "filter_drm/rank_colouring.h"

#include <drm/drm.h>
#include <drm_vcg/vcg_mesh.h>

#include <new>

DrmFilterPlugin::DrmFilterPlugin() {
    typeList << FP_RANK_COLOURS;
    for (FilterIDType type : typeList) actionList << new QAction(filterName(type), this);
}

QString DrmFilterPlugin::pluginName() const { return "FilterDRM"; }

// The name is how .mlx scripts refer to the filter: it must stay unique
// across MeshLab and must not change.
QString DrmFilterPlugin::filterName(FilterIDType filter) const {
    switch (filter) {
        case FP_RANK_COLOURS:
            return "Colorize Faces by Distance Rank";
    }
    return QString();
}

QString DrmFilterPlugin::filterInfo(FilterIDType filter) const {
    switch (filter) {
        case FP_RANK_COLOURS:
            return QString::fromStdString(drm_meshlab::rankFilterHelpHtml());
    }
    return QString();
}

// FaceColoring puts the filter in Filters > Color Creation and Processing, and
// makes MeshLab switch the view to per-face colour after it ran.
MeshFilterInterface::FilterClass DrmFilterPlugin::getClass(QAction* /*action*/) {
    return MeshFilterInterface::FaceColoring;
}

int DrmFilterPlugin::getRequirements(QAction* /*action*/) {
    return MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
}

// Only faces are needed; colour and quality are created by the filter.
int DrmFilterPlugin::getPreConditions(QAction* /*action*/) const { return MeshModel::MM_FACENUMBER; }

int DrmFilterPlugin::postCondition(QAction* /*action*/) const {
    return MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
}

MeshFilterInterface::FILTER_ARITY DrmFilterPlugin::filterArity(QAction* /*action*/) const {
    return MeshFilterInterface::SINGLE_MESH;
}

void DrmFilterPlugin::initParameterSet(QAction* /*action*/, MeshModel& /*m*/, RichParameterList& parameters) {
    drm_meshlab::addQuantizationAndPredictor(parameters);
}

bool DrmFilterPlugin::fail(const std::string& message) {
    errorMessage = QString::fromStdString(message);
    Log(GLLogStream::WARNING, message);
    return false;
}

bool DrmFilterPlugin::applyFilter(QAction* /*action*/, MeshDocument& md, const RichParameterList& parameters,
                                  vcg::CallBackPos* cb) {
    MeshModel* m = md.mm();
    if (m == nullptr) return fail("Colorize Faces by Distance Rank: there is no current mesh");
    const std::string name = m->label().toStdString();
    // The progress callback leaves the last stage in the status bar.
    struct StatusBarReset {
        ~StatusBarReset() { drm_meshlab::clearStatusBar(); }
    } statusBarReset;
    try {
        drm::EncodeOptions options = drm_meshlab::encodeOptionsFrom(parameters);
        options.connectivity = drm::ConnectivityCoder::Ranks;  // the ranks are what the colours show
        options.progress = drm_meshlab::progressTo(cb);
        const drm::Mesh mesh = drm::vcgio::fromVcg(m->cm);
        const drm::Encoded encoded = drm_meshlab::encodeMesh(mesh, options);

        // MeshLab enables the requirements before running a filter; this
        // keeps the filter correct when called some other way.
        m->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
        const std::vector<uint64_t> facesPerBucket = drm_meshlab::colourFacesByRank(m->cm, encoded.faceRank);

        Log("Distance ranks of %s: connectivity %s bpv (%llu bytes for %llu vertices); %s",
            name.c_str(), drm_meshlab::twoDecimals(encoded.stats.connectivityBitsPerVertex()).c_str(),
            (unsigned long long)encoded.stats.connectivityBytes, (unsigned long long)encoded.stats.vertices,
            drm_meshlab::statsSummary(encoded.stats).c_str());
        // The GUI's log pane takes HTML (and collapses spaces): a legend with
        // colour swatches, the only one a user gets, since the 3D view has
        // none. meshlabserver prints the log as it is: aligned plain text.
        if (drm_meshlab::inMeshlabserver()) {
            for (const std::string& line : drm_meshlab::rankLegendText(facesPerBucket)) Log(line);
        } else {
            Log(drm_meshlab::rankLegendHtml(facesPerBucket));
        }
        Log(drm_meshlab::rankHistogramText(encoded.stats));
        return true;
    } catch (...) {
        return fail("Colorize Faces by Distance Rank: cannot rank " + name + ": " + drm_meshlab::currentErrorMessage());
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(DrmFilterPlugin)
