#include "io_drm/io_drm.h"

#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/error_message.h"
#include "bridge/host.h"
#include "bridge/lost_attributes.h"
#include "bridge/progress_bridge.h"

#include <drm/drm.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/vcg_attributes.h>
#include <drm_vcg/vcg_mesh.h>

#include <QFile>
#include <QFileInfo>

#include <algorithm>
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

// The attributes a .drm file keeps. As MeshLab's PLY export does, normals
// are offered but not ticked by default: MeshLab computes them for every
// mesh it opens, so they are seldom the file's own.
void DrmIOPlugin::GetExportMaskCapability(QString& /*format*/, int& capability, int& defaultBits) const {
    capability = drm_meshlab::kExportCapability;
    defaultBits = capability & ~vcg::tri::io::Mask::IOM_VERTNORMAL;
}

void DrmIOPlugin::initSaveParameter(const QString& /*format*/, MeshModel& /*m*/, RichParameterList& parameters) {
    drm_meshlab::addQuantizationAndPredictor(parameters);
    drm_meshlab::addKeepVertexOrder(parameters);
    drm_meshlab::addVerify(parameters);
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
        // Optional components first (MeshLab's own importers do the same),
        // then the values.
        int attributeMask = drm::vcgio::ioMaskOf(decoded.mesh);
        if (!decoded.mesh.cornerNormals.empty()) attributeMask |= vcg::tri::io::Mask::IOM_VERTNORMAL;
        m.Enable(attributeMask);
        const int restored = drm::vcgio::attributesToVcg(decoded.mesh, m.cm);
        // Per-vertex texture coordinates: MeshLab's exporters and filters
        // read wedge ones once a texture is named (meshlabserver's PLY export
        // of such a mesh asserts on disabled wedges), so the wedges carry a
        // copy, as MeshLab's own PLY importer gives.
        if (!decoded.mesh.texCoords.empty() && decoded.mesh.cornerTexCoords.empty()) {
            m.updateDataMask(MeshModel::MM_WEDGTEXCOORD);
            for (CFaceO& face : m.cm.face)
                if (!face.IsD())
                    for (int k = 0; k < 3; ++k) face.WT(k) = face.V(k)->T();
        }
        mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX | restored;
        // Texture names are relative to the .drm file, as for PLY and OBJ.
        for (std::string& texture : m.cm.textures) std::replace(texture.begin(), texture.end(), '\\', '/');
        for (const std::string& note : drm_meshlab::openNotes(decoded.mesh, QFileInfo(fileName).absolutePath()))
        {
            const std::string line = "drm: note: " + name + ": " + note;
            Log(GLLogStream::FILTER, line);  // a note, not an error (WARNING is red)
            qInfo("%s", line.c_str());       // meshlabserver prints no log
        }
        report("drm: opened " + name + ": " + drm_meshlab::statsSummary(decoded.stats));
        return true;
    } catch (...) {
        m.cm.Clear();
        return fail("cannot open " + name + ": " + drm_meshlab::currentErrorMessage());
    }
}

bool DrmIOPlugin::save(const QString& /*format*/, const QString& fileName, MeshModel& m, const int mask,
                       const RichParameterList& parameters, vcg::CallBackPos* cb, QWidget* /*parent*/) {
    const std::string name = shownName(fileName);
    const StatusBarReset statusBarReset;
    try {
        drm::EncodeOptions options = drm_meshlab::encodeOptionsFrom(parameters);
        options.progress = drm_meshlab::progressTo(cb);
        drm::Mesh mesh = drm::vcgio::fromVcg(m.cm);
        const int kept = drm_meshlab::exportedAttributes(m, mask);
        drm::vcgio::attributesFromVcg(m.cm, kept, mesh);
        const drm::Encoded encoded = drm_meshlab::encodeMesh(mesh, options);
        // Atomic: an existing file is replaced only by a complete new one,
        // with its mode and owner, through a symbolic link, and only if the
        // user may write it (drm_vcg/file_io.h).
        drm::vcgio::writeFileAtomically(localPath(fileName), encoded.bytes);

        const std::vector<std::string> lost = drm_meshlab::lostAttributes(m, kept, mesh, encoded.stats);
        if (!lost.empty()) {
            const std::string note = "drm: note: " + name + " does not keep the mesh's " +
                                     drm_meshlab::joinedList(lost);
            // A note, not an error: MeshLab's WARNING level is shown in red.
            Log(GLLogStream::FILTER, note);
            qInfo("%s", note.c_str());
        }
        report("drm: saved " + name + ": " + drm_meshlab::statsSummary(encoded.stats));
        return true;
    } catch (...) {
        return fail("cannot save " + name + ": " + drm_meshlab::currentErrorMessage());
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(DrmIOPlugin)
