// checkMeshForWriting: see mesh_checks.h.
#include "mesh_checks.h"

namespace drm {
namespace vcgio {

namespace {

void checkSize(const std::string& path, size_t size, size_t perItem, size_t items, const char* array,
               const char* item) {
    if (size != 0 && size != perItem * items)
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": " + std::to_string(size) + " " + array + " values for " +
                    std::to_string(items) + " " + item + " (expected " + std::to_string(perItem * items) + ")");
}

}  // namespace

void checkMeshForWriting(const std::string& path, const drm::Mesh& mesh) {
    if (mesh.positions.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": mesh arrays are not a multiple of 3 long");
    const size_t vertices = mesh.vertexCount(), faces = mesh.faceCount();
    for (size_t c = 0; c < mesh.triangles.size(); ++c) {
        if (mesh.triangles[c] >= vertices)
            throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": face " + std::to_string(c / 3) + " refers to missing vertex " +
                        std::to_string(mesh.triangles[c]));
    }
    if (vertices > 0x7FFFFFFFu) throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": too many vertices for int indices");
    checkSize(path, mesh.colors.size(), 4, vertices, "colour", "vertices");
    checkSize(path, mesh.normals.size(), 3, vertices, "normal", "vertices");
    checkSize(path, mesh.texCoords.size(), 2, vertices, "texture coordinate", "vertices");
    checkSize(path, mesh.quality.size(), 1, vertices, "quality", "vertices");
    checkSize(path, mesh.cornerTexCoords.size(), 6, faces, "corner texture coordinate", "faces");
    checkSize(path, mesh.cornerNormals.size(), 9, faces, "corner normal", "faces");
    checkSize(path, mesh.faceColors.size(), 4, faces, "face colour", "faces");
    checkSize(path, mesh.faceQuality.size(), 1, faces, "face quality", "faces");
    checkSize(path, mesh.faceMaterial.size(), 1, faces, "face material", "faces");
    checkSize(path, mesh.faceTexture.size(), 1, faces, "face texture", "faces");
    for (size_t f = 0; f < mesh.faceMaterial.size(); ++f)
        if (mesh.faceMaterial[f] >= mesh.materials.size())
            throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": face " + std::to_string(f) + " uses material " +
                        std::to_string(mesh.faceMaterial[f]) + " of " + std::to_string(mesh.materials.size()));
    for (size_t f = 0; f < mesh.faceTexture.size(); ++f)
        if (mesh.faceTexture[f] > 0x7FFFu)
            throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": face " + std::to_string(f) + " uses texture " +
                        std::to_string(mesh.faceTexture[f]));
}

}  // namespace vcgio
}  // namespace drm
