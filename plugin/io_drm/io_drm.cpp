#include "io_drm/io_drm.h"

#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/host.h"
#include "bridge/lost_attributes.h"
#include "bridge/progress_bridge.h"

#include <drm/drm.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/vcg_mesh.h>

#include <QFile>
#include <QFileInfo>

#include <new>
#include <vector>

namespace {

std::string localPath(const QString& fileName) { return QFile::encodeName(fileName).toStdString(); }

std::string shownName(const QString& fileName) { return QFileInfo(fileName).fileName().toStdString(); }

// Clears the status bar when an open or save ends, however it ends: the
// progress callback leaves the codec's last stage there otherwise.
struct StatusBarReset {
    ~StatusBarReset() { drm_meshlab::clearStatusBar(); }
};

}  // namespace

QString DrmIOPlugin::pluginName() const { return "IODRM"; }

QList<MeshIOInterface::Format> DrmIOPlugin::importFormats() const {
    return {Format("Distance-ranked compressed mesh", tr("DRM"))};
}

QList<MeshIOInterface::Format> DrmIOPlugin::exportFormats() const {
    return {Format("Distance-ranked compressed mesh", tr("DRM"))};
}

// A .drm file keeps positions and triangles only, so there is nothing to
// tick in the save dialog's attribute boxes.
void DrmIOPlugin::GetExportMaskCapability(QString& /*format*/, int& capability, int& defaultBits) const {
    capability = 0;
    defaultBits = 0;
}

void DrmIOPlugin::initSaveParameter(const QString& /*format*/, MeshModel& /*m*/, RichParameterList& parameters) {
    drm_meshlab::addQuantizationAndPredictor(parameters);
    drm_meshlab::addKeepVertexOrder(parameters);
}

bool DrmIOPlugin::fail(const std::string& message) {
    errorMessage = QString::fromStdString(message);
    Log(GLLogStream::WARNING, message);
    qWarning("drm: error: %s", message.c_str());
    return false;
}

void DrmIOPlugin::report(const std::string& line) {
    Log(GLLogStream::FILTER, line);
    drm_meshlab::printToServerOutput(line);
}

bool DrmIOPlugin::open(const QString& /*format*/, const QString& fileName, MeshModel& m, int& mask,
                       const RichParameterList& /*parameters*/, vcg::CallBackPos* cb, QWidget* /*parent*/) {
    const std::string name = shownName(fileName);
    const StatusBarReset statusBarReset;
    try {
        const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(localPath(fileName));
        const drm::Decoded decoded = drm::decode(bytes, drm_meshlab::progressTo(cb));
        drm::vcgio::toVcg(decoded.mesh, m.cm);
        mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
        report("drm: opened " + name + ": " + drm_meshlab::statsSummary(decoded.stats));
        return true;
    } catch (const drm::Error& e) {
        m.cm.Clear();
        return fail("cannot open " + name + ": " + e.what());
    } catch (const std::bad_alloc&) {
        m.cm.Clear();
        return fail("cannot open " + name + ": not enough memory");
    } catch (const std::exception& e) {
        m.cm.Clear();
        return fail("cannot open " + name + ": " + e.what());
    }
}

bool DrmIOPlugin::save(const QString& /*format*/, const QString& fileName, MeshModel& m, const int /*mask*/,
                       const RichParameterList& parameters, vcg::CallBackPos* cb, QWidget* /*parent*/) {
    const std::string name = shownName(fileName);
    const StatusBarReset statusBarReset;
    try {
        drm::EncodeOptions options = drm_meshlab::encodeOptionsFrom(parameters);
        options.progress = drm_meshlab::progressTo(cb);
        const drm::Mesh mesh = drm::vcgio::fromVcg(m.cm);
        const drm::Encoded encoded = drm_meshlab::encodeMesh(mesh, options);
        // Atomic: an existing file is replaced only by a complete new one,
        // with its mode and owner, through a symbolic link, and only if the
        // user may write it (drm_vcg/file_io.h).
        drm::vcgio::writeFileAtomically(localPath(fileName), encoded.bytes);

        const std::vector<std::string> lost = drm_meshlab::lostAttributes(m);
        if (!lost.empty()) {
            const std::string note = "drm: note: " + name + " does not keep the mesh's " +
                                     drm_meshlab::joinedList(lost) + " (only positions, on a " +
                                     std::to_string(options.bits) + "-bit grid, and triangles)";
            // A note, not an error: MeshLab's WARNING level is shown in red.
            Log(GLLogStream::FILTER, note);
            qInfo("%s", note.c_str());
        }
        report("drm: saved " + name + ": " + drm_meshlab::statsSummary(encoded.stats));
        return true;
    } catch (const drm::Error& e) {
        return fail("cannot save " + name + ": " + e.what());
    } catch (const std::bad_alloc&) {
        return fail("cannot save " + name + ": not enough memory");
    } catch (const std::exception& e) {
        return fail("cannot save " + name + ": " + e.what());
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(DrmIOPlugin)
