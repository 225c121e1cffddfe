#include "bridge/lost_attributes.h"

namespace drm_meshlab {

std::vector<std::string> lostAttributes(const MeshModel& m) {
    struct Attribute {
        int mask;
        const char* name;
    };
    // MeshModel's data mask says which optional components hold data. Normals
    // are left out on purpose: MeshLab computes them for every mesh it opens,
    // so their presence says nothing about the file they came from.
    static const Attribute attributes[] = {
        {MeshModel::MM_VERTCOLOR, "vertex colours"},
        {MeshModel::MM_VERTQUALITY, "vertex quality"},
        {MeshModel::MM_VERTTEXCOORD, "vertex texture coordinates"},
        {MeshModel::MM_VERTRADIUS, "vertex radii"},
        {MeshModel::MM_WEDGTEXCOORD, "wedge texture coordinates"},
        {MeshModel::MM_WEDGNORMAL, "wedge normals"},
        {MeshModel::MM_WEDGCOLOR, "wedge colours"},
        {MeshModel::MM_FACECOLOR, "face colours"},
        {MeshModel::MM_FACEQUALITY, "face quality"},
        {MeshModel::MM_POLYGONAL, "polygonal faces (saved as their triangles)"},
    };
    std::vector<std::string> lost;
    for (const Attribute& a : attributes)
        if (m.hasDataMask(a.mask)) lost.push_back(a.name);
    if (!m.cm.textures.empty()) lost.push_back("texture file names");
    if (m.cm.en > 0) lost.push_back("edges");
    return lost;
}

std::string joinedList(const std::vector<std::string>& items) {
    std::string text;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) text += (i + 1 == items.size()) ? " and " : ", ";
        text += items[i];
    }
    return text;
}

}  // namespace drm_meshlab
