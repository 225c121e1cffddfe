// savePly: binary little-endian PLY, written directly (the format is simple
// and this keeps vertex order, face order and corner order exactly). The
// property names are those vcglib's importer (and so MeshLab) reads back.
#include "drm_vcg/file_io.h"
#include "drm_vcg/mesh_io.h"
#include "mesh_checks.h"
#include "text_lines.h"

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>

namespace drm {
namespace vcgio {

namespace {

// The body goes out in blocks, not as one string of the whole file: a
// decoded 1M-triangle mesh would otherwise hold another 38 bytes per vertex
// at the peak.
class BlockWriter {
public:
    explicit BlockWriter(std::ostream& out) : out_(out) {}
    ~BlockWriter() { flush(); }
    void byte(uint8_t value) {
        if (used_ == sizeof buffer_) flush();
        buffer_[used_++] = char(value);
    }
    void littleEndian32(uint32_t value) {
        if (used_ + 4 > sizeof buffer_) flush();
        const unsigned char bytes[4] = {uint8_t(value), uint8_t(value >> 8), uint8_t(value >> 16), uint8_t(value >> 24)};
        std::memcpy(buffer_ + used_, bytes, 4);
        used_ += 4;
    }
    void float32(float value) {
        uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        littleEndian32(bits);
    }
    void flush() {
        out_.write(buffer_, std::streamsize(used_));
        used_ = 0;
    }

private:
    std::ostream& out_;
    char buffer_[1 << 16];
    size_t used_ = 0;
};

void checkFaceAttributes(const std::string& path, const drm::Mesh& mesh, const FaceAttributes* attrs) {
    const size_t faces = mesh.faceCount();
    if (attrs && !attrs->rgb.empty() && attrs->rgb.size() != 3 * faces)
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": " + std::to_string(attrs->rgb.size()) +
                    " colour bytes for " + std::to_string(faces) + " faces");
    if (attrs && !attrs->quality.empty() && attrs->quality.size() != faces)
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": " + std::to_string(attrs->quality.size()) +
                    " quality values for " + std::to_string(faces) + " faces");
}

// `comment TextureFile NAME`: readers take the rest of the line as the
// name, so a name that would end the line early or lose blanks is refused.
std::string textureComment(const std::string& path, const std::string& name) {
    if (const char* reason = unwritableNameReason(name, false))
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": the texture file name \"" + printableName(name) +
                    "\" cannot be written in PLY: " + reason);
    return "comment TextureFile " + name + "\n";
}

}  // namespace

std::vector<std::string> savePly(const std::string& path, const drm::Mesh& mesh, const FaceAttributes* attrs) {
    checkMeshForWriting(path, mesh);
    checkFaceAttributes(path, mesh, attrs);
    const bool withNormals = !mesh.normals.empty();
    const bool withColours = !mesh.colors.empty();
    const bool withQuality = !mesh.quality.empty();
    const bool withTexCoords = !mesh.texCoords.empty();
    const bool withCornerTexCoords = !mesh.cornerTexCoords.empty();
    const bool withTexNumber = !mesh.faceTexture.empty();
    const bool rankColours = attrs && !attrs->rgb.empty();
    const bool rankQuality = attrs && !attrs->quality.empty();
    const bool withFaceColours = rankColours || !mesh.faceColors.empty();
    const bool withFaceQuality = rankQuality || !mesh.faceQuality.empty();

    std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by drm " +
                         std::string(drm::version()) + "\n";
    for (const std::string& texture : mesh.textures) header += textureComment(path, texture);
    header += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (withNormals) header += "property float nx\nproperty float ny\nproperty float nz\n";
    if (withColours) header += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
    if (withQuality) header += "property float quality\n";
    if (withTexCoords) header += "property float texture_u\nproperty float texture_v\n";
    header += "element face " + std::to_string(mesh.faceCount()) + "\n";
    header += "property list uchar int vertex_indices\n";
    if (withCornerTexCoords) header += "property list uchar float texcoord\n";
    if (withTexNumber) header += "property int texnumber\n";
    if (withFaceColours) {
        header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
        if (!rankColours) header += "property uchar alpha\n";
    }
    if (withFaceQuality) header += "property float quality\n";
    header += "end_header\n";

    writeFileAtomically(path, [&](std::ostream& out) {
        out.write(header.data(), std::streamsize(header.size()));
        BlockWriter body(out);
        for (size_t i = 0; i < mesh.vertexCount(); ++i) {
            for (int k = 0; k < 3; ++k) body.float32(mesh.positions[3 * i + size_t(k)]);
            if (withNormals)
                for (int k = 0; k < 3; ++k) body.float32(mesh.normals[3 * i + size_t(k)]);
            if (withColours)
                for (int k = 0; k < 4; ++k) body.byte(mesh.colors[4 * i + size_t(k)]);
            if (withQuality) body.float32(mesh.quality[i]);
            if (withTexCoords)
                for (int k = 0; k < 2; ++k) body.float32(mesh.texCoords[2 * i + size_t(k)]);
        }
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            body.byte(3);
            for (int k = 0; k < 3; ++k) body.littleEndian32(mesh.triangles[3 * f + size_t(k)]);
            if (withCornerTexCoords) {
                body.byte(6);
                for (int k = 0; k < 6; ++k) body.float32(mesh.cornerTexCoords[6 * f + size_t(k)]);
            }
            if (withTexNumber) body.littleEndian32(mesh.faceTexture[f]);
            if (rankColours) {
                for (int k = 0; k < 3; ++k) body.byte(attrs->rgb[3 * f + size_t(k)]);
            } else if (withFaceColours) {
                for (int k = 0; k < 4; ++k) body.byte(mesh.faceColors[4 * f + size_t(k)]);
            }
            if (rankQuality) body.float32(attrs->quality[f]);
            else if (withFaceQuality) body.float32(mesh.faceQuality[f]);
        }
    });

    std::vector<std::string> notes;
    if (!mesh.cornerNormals.empty()) notes.push_back("PLY holds no per-corner normals: they are not in " + path + " (write .obj)");
    if (!mesh.materials.empty()) notes.push_back("PLY holds no materials: they are not in " + path + " (write .obj)");
    for (const auto& entry : mesh.metadata)
        if (entry.first == "obj.mtllib")
            notes.push_back("the material library " + entry.second + " is not written with PLY (write .obj)");
    return notes;
}

}  // namespace vcgio
}  // namespace drm
