#include "filter_drm/filter_drm.h"

#include "bridge/encode_parameters.h"
#include "bridge/error_message.h"
#include "bridge/host.h"
#include "bridge/log_text.h"
#include "filter_drm/rank_colouring.h"

namespace {

// The progress callback leaves the last stage in the status bar.
struct StatusBarReset {
    ~StatusBarReset() { drm_meshlab::clearStatusBar(); }
};

std::string cannotRank(const std::string& name) {
    return std::string(drm_meshlab::kRankFilterName) + ": cannot rank " + name + ": " +
           drm_meshlab::currentErrorMessage();
}

const char* const kNoCurrentMesh = "Colorize Faces by Distance Rank: there is no current mesh";

}  // namespace

QString DrmFilterPlugin::pluginName() const { return "FilterDRM"; }

#if DRM_MESHLAB_API >= 2021

QString DrmFilterPlugin::vendor() const { return drm_meshlab::kPluginVendor; }

DrmFilterPlugin::DrmFilterPlugin() {
    typeList = {FP_RANK_COLOURS};
    for (ActionIDType type : types()) actionList.push_back(new QAction(filterName(type), this));
}

QString DrmFilterPlugin::filterName(ActionIDType filter) const {
    return filter == FP_RANK_COLOURS ? QString(drm_meshlab::kRankFilterName) : QString();
}

QString DrmFilterPlugin::pythonFilterName(ActionIDType filter) const {
    return filter == FP_RANK_COLOURS ? QString(drm_meshlab::kRankFilterPythonName) : QString();
}

QString DrmFilterPlugin::filterInfo(ActionIDType filter) const {
    return filter == FP_RANK_COLOURS ? QString::fromStdString(drm_meshlab::rankFilterHelpHtml()) : QString();
}

// FaceColoring puts the filter in Filters > Color Creation and Processing, and
// makes MeshLab switch the view to per-face colour after it ran.
FilterPlugin::FilterClass DrmFilterPlugin::getClass(const QAction* /*action*/) const {
    return FilterPlugin::FaceColoring;
}

int DrmFilterPlugin::getRequirements(const QAction* /*action*/) {
    return drm_meshlab::kRankColouringComponents;
}

// Only faces are needed; colour and quality are created by the filter.
int DrmFilterPlugin::getPreConditions(const QAction* /*action*/) const { return MeshModel::MM_FACENUMBER; }

int DrmFilterPlugin::postCondition(const QAction* /*action*/) const {
    return drm_meshlab::kRankColouringComponents;
}

FilterPlugin::FilterArity DrmFilterPlugin::filterArity(const QAction* /*action*/) const {
    return FilterPlugin::SINGLE_MESH;
}

RichParameterList DrmFilterPlugin::initParameterList(const QAction* /*action*/, const MeshModel& /*m*/) {
    RichParameterList parameters;
    drm_meshlab::addQuantizationAndPredictor(parameters);
    return parameters;
}

std::map<std::string, QVariant> DrmFilterPlugin::applyFilter(const QAction* /*action*/,
                                                             const RichParameterList& parameters, MeshDocument& md,
                                                             unsigned int& postConditionMask, vcg::CallBackPos* cb) {
    MeshModel* m = md.mm();
    if (m == nullptr) throw MLException(kNoCurrentMesh);
    const StatusBarReset statusBarReset;
    drm_meshlab::RankColouringReport report;
    try {
        report = drm_meshlab::colourMeshByRank(*m, parameters, cb);
    } catch (...) {
        const std::string message = cannotRank(m->label().toStdString());
        log(GLLogStream::WARNING, message);
        throw MLException(QString::fromStdString(message));
    }
    postConditionMask = drm_meshlab::kRankColouringComponents;
    log(report.summary);
    // The log pane takes HTML: a legend with colour swatches, the only one a
    // user gets, since the 3D view has none.
    log(drm_meshlab::rankLegendHtml(report.facesPerBucket));
    log(report.histogram);
    return {};
}

#else

DrmFilterPlugin::DrmFilterPlugin() {
    typeList << FP_RANK_COLOURS;
    for (FilterIDType type : typeList) actionList << new QAction(filterName(type), this);
}

QString DrmFilterPlugin::filterName(FilterIDType filter) const {
    return filter == FP_RANK_COLOURS ? QString(drm_meshlab::kRankFilterName) : QString();
}

QString DrmFilterPlugin::filterInfo(FilterIDType filter) const {
    return filter == FP_RANK_COLOURS ? QString::fromStdString(drm_meshlab::rankFilterHelpHtml()) : QString();
}

// FaceColoring puts the filter in Filters > Color Creation and Processing, and
// makes MeshLab switch the view to per-face colour after it ran.
MeshFilterInterface::FilterClass DrmFilterPlugin::getClass(QAction* /*action*/) {
    return MeshFilterInterface::FaceColoring;
}

int DrmFilterPlugin::getRequirements(QAction* /*action*/) {
    return drm_meshlab::kRankColouringComponents;
}

// Only faces are needed; colour and quality are created by the filter.
int DrmFilterPlugin::getPreConditions(QAction* /*action*/) const { return MeshModel::MM_FACENUMBER; }

int DrmFilterPlugin::postCondition(QAction* /*action*/) const {
    return drm_meshlab::kRankColouringComponents;
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
    if (m == nullptr) return fail(kNoCurrentMesh);
    const StatusBarReset statusBarReset;
    drm_meshlab::RankColouringReport report;
    try {
        report = drm_meshlab::colourMeshByRank(*m, parameters, cb);
    } catch (...) {
        return fail(cannotRank(m->label().toStdString()));
    }
    Log(report.summary);
    // The GUI's log pane takes HTML (and collapses spaces): a legend with
    // colour swatches, the only one a user gets, since the 3D view has none.
    // meshlabserver prints the log as it is: aligned plain text.
    if (drm_meshlab::inMeshlabserver()) {
        for (const std::string& line : drm_meshlab::rankLegendText(report.facesPerBucket)) Log(line);
    } else {
        Log(drm_meshlab::rankLegendHtml(report.facesPerBucket));
    }
    Log(report.histogram);
    return true;
}

#endif

MESHLAB_PLUGIN_NAME_EXPORTER(DrmFilterPlugin)
