// savePly: binary little-endian PLY, written directly (the format is simple
// and this keeps vertex order, face order and corner order exactly).
#include "drm_vcg/file_io.h"
#include "drm_vcg/mesh_io.h"

#include <cstring>
#include <string>

namespace drm {
namespace vcgio {

namespace {

void appendLittleEndian32(std::string& out, uint32_t value) {
    for (int byte = 0; byte < 4; ++byte) out.push_back(char((value >> (8 * byte)) & 0xFF));
}

void appendFloat(std::string& out, float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    appendLittleEndian32(out, bits);
}

void checkSizes(const std::string& path, const drm::Mesh& mesh, const FaceAttributes* attrs) {
    if (mesh.positions.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
        throw Error("cannot write " + path + ": mesh arrays are not a multiple of 3 long");
    const size_t faces = mesh.faceCount();
    for (size_t c = 0; c < mesh.triangles.size(); ++c) {
        if (mesh.triangles[c] >= mesh.vertexCount())
            throw Error("cannot write " + path + ": face " + std::to_string(c / 3) +
                        " refers to missing vertex " + std::to_string(mesh.triangles[c]));
    }
    if (mesh.vertexCount() > 0x7FFFFFFFu)
        throw Error("cannot write " + path + ": too many vertices for PLY's int indices");
    if (attrs && !attrs->rgb.empty() && attrs->rgb.size() != 3 * faces)
        throw Error("cannot write " + path + ": " + std::to_string(attrs->rgb.size()) +
                    " colour bytes for " + std::to_string(faces) + " faces");
    if (attrs && !attrs->quality.empty() && attrs->quality.size() != faces)
        throw Error("cannot write " + path + ": " + std::to_string(attrs->quality.size()) +
                    " quality values for " + std::to_string(faces) + " faces");
}

}  // namespace

void savePly(const std::string& path, const drm::Mesh& mesh, const FaceAttributes* attrs) {
    checkSizes(path, mesh, attrs);
    const bool withColour = attrs && !attrs->rgb.empty();
    const bool withQuality = attrs && !attrs->quality.empty();

    std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by drm " +
                         std::string(drm::version()) + "\n";
    header += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    header += "element face " + std::to_string(mesh.faceCount()) + "\n";
    header += "property list uchar int vertex_indices\n";
    if (withColour) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (withQuality) header += "property float quality\n";
    header += "end_header\n";

    std::string body;
    body.reserve(12 * mesh.vertexCount() + 17 * mesh.faceCount());
    for (float coordinate : mesh.positions) appendFloat(body, coordinate);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        body.push_back(char(3));
        for (int k = 0; k < 3; ++k) appendLittleEndian32(body, mesh.triangles[3 * f + k]);
        if (withColour)
            for (int k = 0; k < 3; ++k) body.push_back(char(attrs->rgb[3 * f + k]));
        if (withQuality) appendFloat(body, attrs->quality[f]);
    }

    writeFileAtomically(path, [&](std::ostream& out) {
        out.write(header.data(), std::streamsize(header.size()));
        out.write(body.data(), std::streamsize(body.size()));
    });
}

}  // namespace vcgio
}  // namespace drm
