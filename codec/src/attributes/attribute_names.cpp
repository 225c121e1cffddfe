// Names of the attributes a .drm file can carry, and which a mesh carries.
#include <string>

#include "drmcodec/drmcodec.h"

namespace drm {
namespace {

struct AttributeName {
    uint32_t bit;
    const char* name;
};

constexpr AttributeName kNames[] = {
    {kAttrColors, "colors"},
    {kAttrNormals, "normals"},
    {kAttrTexCoords, "texcoords"},
    {kAttrQuality, "quality"},
    {kAttrCornerTexCoords, "corner-texcoords"},
    {kAttrCornerNormals, "corner-normals"},
    {kAttrFaceColors, "face-colors"},
    {kAttrFaceQuality, "face-quality"},
    {kAttrFaceMaterial, "materials"},
    {kAttrFaceTexture, "textures"},
    {kAttrMetadata, "metadata"},
};

}  // namespace

bool Mesh::hasAttributes() const { return attributesOf(*this) != 0; }

uint32_t attributesOf(const Mesh& m) {
    uint32_t bits = 0;
    if (!m.colors.empty()) bits |= kAttrColors;
    if (!m.normals.empty()) bits |= kAttrNormals;
    if (!m.texCoords.empty()) bits |= kAttrTexCoords;
    if (!m.quality.empty()) bits |= kAttrQuality;
    if (!m.cornerTexCoords.empty()) bits |= kAttrCornerTexCoords;
    if (!m.cornerNormals.empty()) bits |= kAttrCornerNormals;
    if (!m.faceColors.empty()) bits |= kAttrFaceColors;
    if (!m.faceQuality.empty()) bits |= kAttrFaceQuality;
    if (!m.faceMaterial.empty() || !m.materials.empty()) bits |= kAttrFaceMaterial;
    if (!m.faceTexture.empty() || !m.textures.empty()) bits |= kAttrFaceTexture;
    if (!m.metadata.empty()) bits |= kAttrMetadata;
    return bits;
}

std::string attributesName(uint32_t bits) {
    if ((bits & kAttrAll) == kAttrAll) return "all";
    std::string out;
    for (const AttributeName& n : kNames)
        if (bits & n.bit) out += (out.empty() ? "" : ",") + std::string(n.name);
    return out.empty() ? "none" : out;
}

uint32_t parseAttributes(const std::string& list) {
    if (list == "all") return kAttrAll;
    if (list == "none") return 0;
    uint32_t bits = 0;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        bool known = false;
        for (const AttributeName& n : kNames)
            if (name == n.name) {
                bits |= n.bit;
                known = true;
            }
        if (!known) {
            std::string names;
            for (const AttributeName& n : kNames) names += std::string(names.empty() ? "" : ", ") + n.name;
            throw Error(ErrorKind::InvalidInput, "unknown attribute '" + name + "' (use all, none, or a list of " + names + ")");
        }
        start = comma + 1;
    }
    return bits;
}

uint32_t sectionAttributes(const std::string& sectionName) {
    if (sectionName == "material names") return kAttrFaceMaterial;
    if (sectionName == "texture names") return kAttrFaceTexture;
    for (const AttributeName& n : kNames)
        if (sectionName == n.name) return n.bit;
    return 0;
}

}  // namespace drm
