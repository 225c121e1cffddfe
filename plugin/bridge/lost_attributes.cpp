#include "bridge/lost_attributes.h"

#include <drm_vcg/joined_list.h>

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace drm_meshlab {

namespace {

typedef vcg::tri::io::Mask IoMask;

// Each box of the export dialog a .drm file honours, with the MeshModel
// data mask that says the mesh holds it.
struct Box {
    int ioMask;
    int dataMask;
    const char* name;
};

const Box kBoxes[] = {
    {IoMask::IOM_VERTCOLOR, MeshModel::MM_VERTCOLOR, "vertex colours"},
    {IoMask::IOM_VERTNORMAL, MeshModel::MM_VERTNORMAL, "vertex normals"},
    {IoMask::IOM_VERTQUALITY, MeshModel::MM_VERTQUALITY, "vertex quality"},
    {IoMask::IOM_VERTTEXCOORD, MeshModel::MM_VERTTEXCOORD, "vertex texture coordinates"},
    {IoMask::IOM_FACECOLOR, MeshModel::MM_FACECOLOR, "face colours"},
    {IoMask::IOM_FACEQUALITY, MeshModel::MM_FACEQUALITY, "face quality"},
    {IoMask::IOM_WEDGTEXCOORD, MeshModel::MM_WEDGTEXCOORD, "wedge texture coordinates"},
};

}  // namespace

const int kExportCapability = IoMask::IOM_VERTCOLOR | IoMask::IOM_VERTNORMAL | IoMask::IOM_VERTQUALITY |
                              IoMask::IOM_VERTTEXCOORD | IoMask::IOM_FACECOLOR | IoMask::IOM_FACEQUALITY |
                              IoMask::IOM_WEDGTEXCOORD;

int exportedAttributes(const MeshModel& m, int mask) {
    int kept = 0;
    for (const Box& box : kBoxes)
        if ((mask & box.ioMask) && m.hasDataMask(box.dataMask)) kept |= box.ioMask;
    return kept;
}

std::vector<std::string> lostAttributes(const MeshModel& m, int kept, const drm::Mesh& mesh,
                                        const drm::Stats& stats) {
    struct Attribute {
        int mask;
        const char* name;
    };
    static const Attribute unkept[] = {
        {MeshModel::MM_VERTRADIUS, "vertex radii"},
        {MeshModel::MM_WEDGNORMAL, "wedge normals"},
        {MeshModel::MM_WEDGCOLOR, "wedge colours"},
        {MeshModel::MM_POLYGONAL, "polygonal faces (saved as their triangles)"},
    };
    std::vector<std::string> lost;
    for (const Attribute& a : unkept)
        if (m.hasDataMask(a.mask)) lost.push_back(a.name);
    if (m.cm.en > 0) lost.push_back("edges");
    for (const Box& box : kBoxes)
        if (m.hasDataMask(box.dataMask) && !(kept & box.ioMask))
            lost.push_back(std::string(box.name) + " (not ticked)");
    if (!m.cm.textures.empty() && !(kept & (IoMask::IOM_WEDGTEXCOORD | IoMask::IOM_VERTTEXCOORD)))
        lost.push_back("texture file names (texture coordinates not ticked)");
    // What the encoder was given but wrote no section for.
    uint32_t written = 0;
    for (const drm::Stats::AttributeSize& section : stats.attributeSizes) written |= drm::sectionAttributes(section.name);
    const uint32_t missing = drm::attributesOf(mesh) & ~written;
    if (missing != 0) lost.push_back(drm::attributesName(missing) + " (this codec build has no section for them)");
    return lost;
}

std::vector<std::string> openNotes(const drm::Mesh& mesh, const QString& folder) {
    std::vector<std::string> notes;
    const QDir dir(folder);
    std::vector<std::string> missing;
    for (std::string texture : mesh.textures) {
        std::replace(texture.begin(), texture.end(), '\\', '/');
        const QString name = QString::fromStdString(texture);
        if (!QFileInfo(QDir::isAbsolutePath(name) ? name : dir.filePath(name)).exists()) missing.push_back(texture);
    }
    if (!missing.empty()) notes.push_back("texture files not found beside the file: " + drm::vcgio::joinList(missing));
    if (!mesh.cornerNormals.empty() && mesh.normals.empty())
        notes.push_back("MeshLab holds no per-corner normals: each vertex gets the mean of its corners' normals");
    return notes;
}

}  // namespace drm_meshlab
