#include "io_drm/io_drm_work.h"

#include "bridge/computed_normals.h"
#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/error_message.h"
#include "bridge/lost_attributes.h"
#include "bridge/progress_bridge.h"

#include <drmcodec/drmcodec.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/joined_list.h>
#include <drm_vcg/vcg_attributes.h>
#include <drm_vcg/vcg_mesh.h>

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <vector>

namespace drm_meshlab {

const char* const kDrmExtension = "DRM";
const char* const kDrmDescription = "Distance-ranked compressed mesh";

namespace {

std::string localPath(const QString& fileName) { return QFile::encodeName(fileName).toStdString(); }

std::string shownName(const QString& fileName) { return QFileInfo(fileName).fileName().toStdString(); }

}  // namespace

int openDrm(const QString& fileName, MeshModel& m, vcg::CallBackPos* cb, IoReport& report) {
    const std::string name = shownName(fileName);
    try {
        const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(localPath(fileName));
        const drm::Decoded decoded = drm::decode(bytes, progressTo(cb));
        drm::vcgio::toVcg(decoded.mesh, m.cm);
        // Optional components first (MeshLab's own importers do the same),
        // then the values.
        int attributeMask = drm::vcgio::ioMaskOf(decoded.mesh);
        if (!decoded.mesh.cornerNormals.empty()) attributeMask |= vcg::tri::io::Mask::IOM_VERTNORMAL;
        enableComponents(m, attributeMask);
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
        // Texture names are relative to the .drm file, as for PLY and OBJ.
        for (std::string& texture : m.cm.textures) std::replace(texture.begin(), texture.end(), '\\', '/');
        for (const std::string& note : openNotes(decoded.mesh, QFileInfo(fileName).absolutePath()))
            report.notes.push_back("drm: note: " + name + ": " + note);
        report.summary = "drm: opened " + name + ": " + statsSummary(decoded.stats);
        return vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX | restored;
    } catch (...) {
        m.cm.Clear();
        throw;
    }
}

void saveDrm(const QString& fileName, MeshModel& m, int mask, const RichParameterList& parameters,
             vcg::CallBackPos* cb, IoReport& report) {
    const std::string name = shownName(fileName);
    drm::EncodeOptions options = encodeOptionsFrom(parameters);
    options.progress = progressTo(cb);
    drm::Mesh mesh = drm::vcgio::fromVcg(m.cm);
    int kept = exportedAttributes(m, mask);
    // MeshLab computes these again when it opens a file without normals:
    // neither stored nor, when unticked, counted as lost.
    const int otherPerVertex = vcg::tri::io::Mask::IOM_VERTCOLOR | vcg::tri::io::Mask::IOM_VERTQUALITY |
                               vcg::tri::io::Mask::IOM_VERTTEXCOORD | vcg::tri::io::Mask::IOM_WEDGTEXCOORD;
    const double mergeStep = (kept & otherPerVertex) != 0 ? gridStep(m.cm, options.bits) : 0.0;
    const bool computedNormals = m.hasDataMask(MeshModel::MM_VERTNORMAL) && normalsAreComputedFromFaces(m.cm, mergeStep);
    const bool normalsLeftOut = computedNormals && (kept & vcg::tri::io::Mask::IOM_VERTNORMAL);
    if (computedNormals) kept &= ~vcg::tri::io::Mask::IOM_VERTNORMAL;
    drm::vcgio::attributesFromVcg(m.cm, kept, mesh);
    const drm::Encoded encoded = encodeMesh(mesh, options);
    // Atomic: an existing file is replaced only by a complete new one, with
    // its mode and owner, through a symbolic link, and only if the user may
    // write it (drm_vcg/file_io.h).
    drm::vcgio::writeFileAtomically(localPath(fileName), encoded.bytes);

    std::vector<std::string> lost = lostAttributes(m, kept, mesh, encoded.stats);
    if (computedNormals)
        lost.erase(std::remove(lost.begin(), lost.end(), std::string("vertex normals (not ticked)")), lost.end());
    if (normalsLeftOut)
        report.notes.push_back("drm: note: " + name +
                               " leaves out the vertex normals: they are the ones MeshLab computes from the faces "
                               "when it opens a file without normals");
    if (!lost.empty()) report.notKept = "drm: note: " + name + " does not keep the mesh's " + drm::vcgio::joinList(lost);
    report.summary = "drm: saved " + name + ": " + statsSummary(encoded.stats);
}

std::string failureMessage(const char* verb, const QString& fileName) {
    return std::string("cannot ") + verb + " " + shownName(fileName) + ": " + currentErrorMessage();
}

}  // namespace drm_meshlab
