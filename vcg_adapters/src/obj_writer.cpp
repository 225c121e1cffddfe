// saveObj: Wavefront OBJ with colours, texture coordinates, normals and
// materials, and its material library beside it. Written directly (as
// savePly) so that vertex, face and corner order stay exactly as given.
#include "drm_vcg/file_io.h"
#include "drm_vcg/mesh_io.h"
#include "mesh_checks.h"
#include "mtl_library.h"
#include "text_lines.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>

namespace drm {
namespace vcgio {

namespace {


// Nine significant digits give every float back exactly.
void appendFloat(std::string& out, float value) {
    char text[32];
    std::snprintf(text, sizeof text, " %.9g", double(value));
    out += text;
}

std::string metadataValue(const drm::Mesh& mesh, const std::string& key, bool* found = nullptr) {
    for (const auto& entry : mesh.metadata)
        if (entry.first == key) {
            if (found) *found = true;
            return entry.second;
        }
    if (found) *found = false;
    return "";
}

std::string baseName(const std::string& path) {
    const size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string stemOf(const std::string& path) {
    const std::string name = baseName(path);
    const size_t dot = name.find_last_of('.');
    return (dot == std::string::npos || dot == 0) ? name : name.substr(0, dot);
}

// The material library is a file the user did not name: saveObj writes it
// beside the OBJ, and so through a link only to a file in the OBJ's own
// folder, as the reader reads one (mesh_io.cpp, libraryInsideFolder). A
// link planted there must not make drm read or replace a file elsewhere.
void refuseLibraryLinkOutside(const std::string& objPath, const std::string& libraryPath) {
    struct stat info;
    if (::lstat(libraryPath.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return;
    const std::string folder = folderOf(objPath).empty() ? "." : folderOf(objPath);
    char* folderReal = ::realpath(folder.c_str(), nullptr);
    char* target = ::realpath(libraryPath.c_str(), nullptr);
    std::string folderText = folderReal ? folderReal : "", targetText = target ? target : "";
    std::free(folderReal);
    std::free(target);
    if (folderText != "/") folderText += "/";
    if (targetText.empty() || targetText.compare(0, folderText.size(), folderText) != 0)
        throw Error(ErrorKind::Io, "cannot write " + libraryPath + ": it is a link to a file outside the OBJ's folder "
                    "(the material library is written only beside the OBJ); nothing written");
}

// Indices of distinct values (compared bit for bit), in order of first use.
class ValueTable {
public:
    explicit ValueTable(size_t width) : width_(width) {}
    // 1-based OBJ index of the value at `values`.
    size_t add(const float* values) {
        std::string key(reinterpret_cast<const char*>(values), width_ * sizeof(float));
        auto found = index_.find(key);
        if (found != index_.end()) return found->second;
        values_.insert(values_.end(), values, values + width_);
        const size_t index = values_.size() / width_;
        index_.emplace(std::move(key), index);
        return index;
    }
    const std::vector<float>& values() const { return values_; }

private:
    size_t width_;
    std::vector<float> values_;
    std::map<std::string, size_t> index_;
};

// A material library for a mesh with textures but none of its own: one
// material per material name (or per texture), each with its texture.
struct GeneratedLibrary {
    std::string text;
    std::vector<std::string> materialNames;  // used by usemtl
    std::vector<uint32_t> faceMaterial;      // per face, into materialNames
};

// Throws drm::Error("cannot write PATH: WHAT "NAME" cannot be written in
// OBJ: reason") for a name that would change the file's structure.
void refuseUnwritableName(const std::string& path, const std::string& what, const std::string& name) {
    if (const char* reason = unwritableNameReason(name, true))
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": " + what + " \"" + printableName(name) +
                    "\" cannot be written in OBJ: " + reason);
}

GeneratedLibrary generateLibrary(const drm::Mesh& mesh) {
    GeneratedLibrary library;
    const size_t faces = mesh.faceCount();
    auto textureOf = [&mesh](size_t f) { return mesh.faceTexture.empty() ? 0u : mesh.faceTexture[f]; };
    std::vector<std::string> materialTexture;
    if (!mesh.materials.empty() && mesh.faceMaterial.size() == faces) {
        library.materialNames = mesh.materials;
        library.faceMaterial = mesh.faceMaterial;
        materialTexture.assign(mesh.materials.size(), mesh.textures[0]);
        for (size_t f = faces; f-- > 0;)
            if (textureOf(f) < mesh.textures.size()) materialTexture[mesh.faceMaterial[f]] = mesh.textures[textureOf(f)];
    } else {
        for (size_t t = 0; t < mesh.textures.size(); ++t) {
            library.materialNames.push_back("texture_" + std::to_string(t));
            materialTexture.push_back(mesh.textures[t]);
        }
        library.faceMaterial.resize(faces);
        for (size_t f = 0; f < faces; ++f)
            library.faceMaterial[f] = textureOf(f) < mesh.textures.size() ? textureOf(f) : 0;
    }
    library.text = "# written by drm " + std::string(drm::version()) + "\n";
    for (size_t m = 0; m < library.materialNames.size(); ++m)
        library.text += "\nnewmtl " + library.materialNames[m] + "\nKa 0.2 0.2 0.2\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " +
                        materialTexture[m] + "\n";
    return library;
}

// Whether `path` is a regular file holding exactly `text`; anything else
// (a FIFO, a device, a file of another size) is not read at all.
bool fileHoldsText(const std::string& path, const std::string& text) {
    struct stat info;
    if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) || uint64_t(info.st_size) != text.size()) return false;
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream content;
    content << in.rdbuf();
    return content.str() == text;
}

}  // namespace

std::vector<std::string> saveObj(const std::string& path, const drm::Mesh& mesh) {
    checkMeshForWriting(path, mesh);
    std::vector<std::string> notes;
    const size_t vertices = mesh.vertexCount(), faces = mesh.faceCount();

    // The material library: the statements the mesh came with, read again
    // (mtl_library.h), or one made up for its textures; written as
    // OUT.mtl beside OUT.obj whatever name the mesh stored, so a file
    // names no path that decoding writes.
    bool haveText = false, haveName = false;
    const std::string keptText = metadataValue(mesh, "obj.mtl", &haveText);
    const std::string keptName = metadataValue(mesh, "obj.mtllib", &haveName);
    std::string libraryText = haveText ? readMtl(keptText).text : std::string();
    std::vector<std::string> materialNames = mesh.materials;
    std::vector<uint32_t> faceMaterial = mesh.faceMaterial;
    if (!haveText && !mesh.textures.empty()) {
        for (const std::string& name : mesh.textures) refuseUnwritableName(path, "the texture file name", name);
        GeneratedLibrary generated = generateLibrary(mesh);
        libraryText = generated.text;
        materialNames = generated.materialNames;
        faceMaterial = generated.faceMaterial;
        haveText = true;
    }
    if (!haveText && haveName)
        notes.push_back("the material library " + printableName(keptName) + " was not in the .drm file: " + path + " names none");
    if (path.find('\\', path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/')) != std::string::npos)
        throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": a '\\' in an OBJ's file name would name its library "
                    "in another folder for readers that take it as a separator");
    const std::string libraryPath = objLibraryPath(path);
    const std::string libraryName = baseName(libraryPath);
    if (haveText) refuseUnwritableName(path, "the material library's name", libraryName);
    for (const std::string& name : materialNames) refuseUnwritableName(path, "the material name", name);

    std::string out = "# written by drm " + std::string(drm::version()) + "\n";
    if (haveText) out += "mtllib " + libraryName + "\n";
    const bool withColours = !mesh.colors.empty();
    for (size_t i = 0; i < vertices; ++i) {
        out += "v";
        for (int k = 0; k < 3; ++k) appendFloat(out, mesh.positions[3 * i + size_t(k)]);
        if (withColours) {
            for (int k = 0; k < 3; ++k) {
                char text[16];
                std::snprintf(text, sizeof text, " %.6g", double(mesh.colors[4 * i + size_t(k)]) / 255.0);
                out += text;
            }
        }
        out += "\n";
    }

    // Texture coordinates and normals: per corner where the mesh has them
    // per corner, otherwise per vertex; distinct values written once.
    ValueTable texCoords(2), normals(3);
    std::vector<size_t> cornerTex, cornerNormal;
    const size_t corners = 3 * faces;
    if (!mesh.cornerTexCoords.empty()) {
        for (size_t c = 0; c < corners; ++c) cornerTex.push_back(texCoords.add(&mesh.cornerTexCoords[2 * c]));
    } else if (!mesh.texCoords.empty()) {
        for (size_t c = 0; c < corners; ++c) cornerTex.push_back(texCoords.add(&mesh.texCoords[2 * size_t(mesh.triangles[c])]));
    }
    if (!mesh.cornerNormals.empty()) {
        for (size_t c = 0; c < corners; ++c) cornerNormal.push_back(normals.add(&mesh.cornerNormals[3 * c]));
    } else if (!mesh.normals.empty()) {
        for (size_t c = 0; c < corners; ++c) cornerNormal.push_back(normals.add(&mesh.normals[3 * size_t(mesh.triangles[c])]));
    }
    for (size_t i = 0; i < texCoords.values().size(); i += 2) {
        out += "vt";
        appendFloat(out, texCoords.values()[i]);
        appendFloat(out, texCoords.values()[i + 1]);
        out += "\n";
    }
    for (size_t i = 0; i < normals.values().size(); i += 3) {
        out += "vn";
        for (int k = 0; k < 3; ++k) appendFloat(out, normals.values()[i + size_t(k)]);
        out += "\n";
    }

    const bool withMaterials = faceMaterial.size() == faces && !materialNames.empty();
    long currentMaterial = -1;
    for (size_t f = 0; f < faces; ++f) {
        if (withMaterials && long(faceMaterial[f]) != currentMaterial) {
            currentMaterial = long(faceMaterial[f]);
            // Faces before any usemtl come back under the material "".
            if (!(f == 0 && materialNames[size_t(currentMaterial)].empty()))
                out += "usemtl " + materialNames[size_t(currentMaterial)] + "\n";
        }
        out += "f";
        for (int k = 0; k < 3; ++k) {
            const size_t c = 3 * f + size_t(k);
            out += " " + std::to_string(mesh.triangles[c] + 1);
            if (!cornerTex.empty() || !cornerNormal.empty()) out += "/";
            if (!cornerTex.empty()) out += std::to_string(cornerTex[c]);
            if (!cornerNormal.empty()) out += "/" + std::to_string(cornerNormal[c]);
        }
        out += "\n";
    }

    // The OBJ and its library are written together: if either cannot be,
    // neither file is touched. A library already holding the text is left.
    std::vector<std::pair<std::string, std::vector<uint8_t>>> files;
    files.emplace_back(path, std::vector<uint8_t>(out.begin(), out.end()));
    if (haveText) refuseLibraryLinkOutside(path, libraryPath);
    if (haveText && !fileHoldsText(libraryPath, libraryText))
        files.emplace_back(libraryPath, std::vector<uint8_t>(libraryText.begin(), libraryText.end()));
    writeFilesAtomically(files);

    if (withColours) {
        bool opaque = true;
        for (size_t i = 0; i < vertices; ++i) opaque = opaque && mesh.colors[4 * i + 3] == 255;
        if (!opaque) notes.push_back("OBJ holds no colour alpha: it is not in " + path + " (write .ply)");
    }
    // OBJ gives normals and texture coordinates to face corners only.
    if (faces == 0 && !mesh.normals.empty())
        notes.push_back("OBJ holds normals only for face corners: the vertices' normals are not in " + path + " (write .ply)");
    if (faces == 0 && !mesh.texCoords.empty())
        notes.push_back("OBJ holds texture coordinates only for face corners: the vertices' are not in " + path + " (write .ply)");
    if (!mesh.quality.empty()) notes.push_back("OBJ holds no vertex quality: it is not in " + path + " (write .ply)");
    if (!mesh.faceColors.empty()) notes.push_back("OBJ holds no face colours: they are not in " + path + " (write .ply)");
    if (!mesh.faceQuality.empty()) notes.push_back("OBJ holds no face quality: it is not in " + path + " (write .ply)");
    if (!mesh.cornerTexCoords.empty() && !mesh.texCoords.empty())
        notes.push_back("the per-vertex texture coordinates are not in " + path + " (the per-corner ones are)");
    if (!mesh.cornerNormals.empty() && !mesh.normals.empty())
        notes.push_back("the per-vertex normals are not in " + path + " (the per-corner ones are)");
    return notes;
}

std::string objLibraryPath(const std::string& objPath) { return folderOf(objPath) + stemOf(objPath) + ".mtl"; }

std::vector<std::string> saveMesh(const std::string& path, const drm::Mesh& mesh) {
    std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".ply") return savePly(path, mesh);
    if (extension == ".obj") return saveObj(path, mesh);
    throw Error(ErrorKind::InvalidInput, "cannot write " + path + ": unknown mesh format (expected .ply or .obj)");
}

}  // namespace vcgio
}  // namespace drm
