#include "io_drm/io_drm.h"

#include "bridge/encode_parameters.h"
#include "bridge/host.h"
#include "bridge/lost_attributes.h"
#include "io_drm/io_drm_work.h"

#include <cstdio>

namespace {

// Clears the status bar when an open or save ends, however it ends: the
// progress callback leaves the codec's last stage there otherwise.
struct StatusBarReset {
    ~StatusBarReset() { drm_meshlab::clearStatusBar(); }
};

}  // namespace

QString DrmIOPlugin::pluginName() const { return "IODRM"; }

#if DRM_MESHLAB_API >= 2021

QString DrmIOPlugin::vendor() const { return drm_meshlab::kPluginVendor; }

std::list<FileFormat> DrmIOPlugin::importFormats() const {
    return {FileFormat(drm_meshlab::kDrmDescription, drm_meshlab::kDrmExtension)};
}

std::list<FileFormat> DrmIOPlugin::exportFormats() const {
    return {FileFormat(drm_meshlab::kDrmDescription, drm_meshlab::kDrmExtension)};
}

// Every attribute a .drm file keeps is ticked: the dialog offers only those
// the mesh has, and what the user unticks is named in a note after saving.
void DrmIOPlugin::exportMaskCapability(const QString& /*format*/, int& capability, int& defaultBits) const {
    capability = drm_meshlab::kExportCapability;
    defaultBits = capability;
}

RichParameterList DrmIOPlugin::initSaveParameter(const QString& /*format*/, const MeshModel& /*m*/) const {
    RichParameterList parameters;
    drm_meshlab::addQuantizationAndPredictor(parameters);
    drm_meshlab::addKeepVertexOrder(parameters);
    drm_meshlab::addVerify(parameters);
    return parameters;
}

void DrmIOPlugin::logLine(GLLogStream::Levels level, const std::string& line) const { log(level, line); }

void DrmIOPlugin::open(const QString& /*format*/, const QString& fileName, MeshModel& m, int& mask,
                       const RichParameterList& /*parameters*/, vcg::CallBackPos* cb) {
    const StatusBarReset statusBarReset;
    drm_meshlab::IoReport report;
    try {
        mask = drm_meshlab::openDrm(fileName, m, cb, report);
    } catch (...) {
        const std::string message = drm_meshlab::failureMessage("open", fileName);
        logLine(GLLogStream::WARNING, message);
        throw MLException(QString::fromStdString(message));
    }
    // Notes, not errors: MeshLab's WARNING level is shown in red.
    for (const std::string& note : report.notes) logLine(GLLogStream::FILTER, note);
    logLine(GLLogStream::FILTER, report.summary);
}

void DrmIOPlugin::save(const QString& /*format*/, const QString& fileName, MeshModel& m, const int mask,
                       const RichParameterList& parameters, vcg::CallBackPos* cb) {
    const StatusBarReset statusBarReset;
    drm_meshlab::IoReport report;
    try {
        drm_meshlab::saveDrm(fileName, m, mask, parameters, cb, report);
    } catch (...) {
        const std::string message = drm_meshlab::failureMessage("save", fileName);
        logLine(GLLogStream::WARNING, message);
        throw MLException(QString::fromStdString(message));
    }
    for (const std::string& note : report.notes) logLine(GLLogStream::FILTER, note);
    // What the file does not keep is data the user may not expect to lose:
    // MeshLab shows it after saving, and logs it.
    if (!report.notKept.empty()) reportWarning(QString::fromStdString(report.notKept));
    logLine(GLLogStream::FILTER, report.summary);
}

#else

QList<MeshIOInterface::Format> DrmIOPlugin::importFormats() const {
    return {Format(drm_meshlab::kDrmDescription, drm_meshlab::kDrmExtension)};
}

QList<MeshIOInterface::Format> DrmIOPlugin::exportFormats() const {
    return {Format(drm_meshlab::kDrmDescription, drm_meshlab::kDrmExtension)};
}

// Every attribute a .drm file keeps is ticked: the dialog offers only those
// the mesh has, and what the user unticks is named in a note after saving.
void DrmIOPlugin::GetExportMaskCapability(QString& /*format*/, int& capability, int& defaultBits) const {
    capability = drm_meshlab::kExportCapability;
    defaultBits = capability;
}

void DrmIOPlugin::initSaveParameter(const QString& /*format*/, MeshModel& /*m*/, RichParameterList& parameters) {
    drm_meshlab::addQuantizationAndPredictor(parameters);
    drm_meshlab::addKeepVertexOrder(parameters);
    drm_meshlab::addVerify(parameters);
}

bool DrmIOPlugin::fail(const std::string& message) {
    errorMessage = QString::fromStdString(message);
    Log(GLLogStream::WARNING, message);
    std::fprintf(stderr, "drm: error: %s\n", message.c_str());
    return false;
}

// The GUI's log pane; in meshlabserver, which shows no IO plugin's log,
// stdout and the -l log file too.
void DrmIOPlugin::logLine(GLLogStream::Levels level, const std::string& line) {
    Log(level, line);
    drm_meshlab::printToServerOutput(line);
}

bool DrmIOPlugin::open(const QString& /*format*/, const QString& fileName, MeshModel& m, int& mask,
                       const RichParameterList& /*parameters*/, vcg::CallBackPos* cb, QWidget* /*parent*/) {
    const StatusBarReset statusBarReset;
    drm_meshlab::IoReport report;
    try {
        mask = drm_meshlab::openDrm(fileName, m, cb, report);
    } catch (...) {
        return fail(drm_meshlab::failureMessage("open", fileName));
    }
    // Notes, not errors: MeshLab's WARNING level is shown in red.
    for (const std::string& note : report.notes) logLine(GLLogStream::FILTER, note);
    logLine(GLLogStream::FILTER, report.summary);
    return true;
}

bool DrmIOPlugin::save(const QString& /*format*/, const QString& fileName, MeshModel& m, const int mask,
                       const RichParameterList& parameters, vcg::CallBackPos* cb, QWidget* /*parent*/) {
    const StatusBarReset statusBarReset;
    drm_meshlab::IoReport report;
    try {
        drm_meshlab::saveDrm(fileName, m, mask, parameters, cb, report);
    } catch (...) {
        return fail(drm_meshlab::failureMessage("save", fileName));
    }
    for (const std::string& note : report.notes) logLine(GLLogStream::FILTER, note);
    if (!report.notKept.empty()) logLine(GLLogStream::FILTER, report.notKept);
    logLine(GLLogStream::FILTER, report.summary);
    return true;
}

#endif

MESHLAB_PLUGIN_NAME_EXPORTER(DrmIOPlugin)
