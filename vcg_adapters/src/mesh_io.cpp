// loadMesh: PLY through ply_reader.cpp (vcglib's misreads many valid
// files), OFF and STL through vcglib's importers, OBJ through
// obj_reader.cpp (vcglib's drops faces, see obj_reader.h). Every path
// keeps vertex order, face order and corner order as in the file.
#include "drm_vcg/mesh_io.h"

#include "drm_vcg/file_io.h"
#include "drm_vcg/vcg_attributes.h"
#include "drm_vcg/vcg_mesh.h"
#include "format_preflight.h"
#include "loading_mesh.h"
#include "mtl_library.h"
#include "obj_reader.h"
#include "ply_reader.h"
#include "stl_ascii_reader.h"
#include "stl_weld.h"
#include "text_lines.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sys/stat.h>

#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_stl.h>

namespace drm {
namespace vcgio {

namespace {

typedef vcg::tri::io::Mask Mask;

std::string lowerExtension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string extension = path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

void addDroppedNote(std::vector<std::string>& notes, const std::vector<std::string>& dropped) {
    if (!dropped.empty()) notes.push_back("the file's " + joinList(dropped) + " are not kept in .drm files");
}

// What vcglib's load mask says the file had that drm::Mesh does not hold
// (attributesFromVcg keeps the rest).
std::vector<std::string> droppedAttributes(int mask, const LoadingMesh& m) {
    std::vector<std::string> dropped;
    if (mask & Mask::IOM_FACENORMAL) dropped.push_back("per-face normals");
    if (mask & Mask::IOM_WEDGNORMAL) dropped.push_back("per-corner normals");
    if (mask & Mask::IOM_WEDGCOLOR) dropped.push_back("per-corner colours");
    if (mask & Mask::IOM_VERTRADIUS) dropped.push_back("vertex radii");
    if (m.en > 0) dropped.push_back("edges");
    if (mask & Mask::IOM_CAMERA) dropped.push_back("camera parameters");
    if (!m.normalmaps.empty()) dropped.push_back("normal map file names");
    return dropped;
}

// "the file's PLY properties a, b and c are not kept in .drm files",
// naming at most six.
void addNamesNote(std::vector<std::string>& notes, const char* what, std::vector<std::string> names) {
    if (names.size() > 6) {
        const size_t more = names.size() - 5;
        names.resize(5);
        names.push_back(std::to_string(more) + " more");
    }
    if (!names.empty()) notes.push_back("the file's " + std::string(what) + " " + joinList(names) + " are not kept in .drm files");
}

// NaN or infinite normals and texture coordinates cannot be quantized; the
// codec refuses them too, but here the message can name the file.
void checkFinite(const std::vector<float>& values, size_t perItem, const char* item, const char* what) {
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw Error(ErrorKind::InvalidInput, std::string(item) + " " + std::to_string(i / perItem) + " has a non-finite " + what + " (" +
                        std::to_string(values[i]) + ")");
}

// A material or texture name with a control character could not be
// written back into any file's line: refused here, when encoding, rather
// than by every decode.
void checkNamesWritable(const drm::Mesh& mesh) {
    const auto check = [](const std::vector<std::string>& names, const char* what) {
        for (const std::string& name : names)
            if (holdsControlCharacter(name))
                throw Error(ErrorKind::InvalidInput, std::string(what) + " \"" + printableName(name) +
                            "\" holds a control character, which no mesh file can hold in a name");
    };
    check(mesh.materials, "the material name");
    check(mesh.textures, "the texture file name");
}

void checkAttributesFinite(const drm::Mesh& mesh) {
    checkFinite(mesh.normals, 3, "vertex", "normal");
    checkFinite(mesh.texCoords, 2, "vertex", "texture coordinate");
    checkFinite(mesh.cornerNormals, 3, "corner", "normal");
    checkFinite(mesh.cornerTexCoords, 2, "corner", "texture coordinate");
}

// vcglib marks the inner edges of a split polygon as "faux"; a triangle with
// one came from a polygon. (Unless the file stored vcglib's own face flags.)
size_t trianglesFromPolygons(int mask, const LoadingMesh& m) {
    if (mask & Mask::IOM_FACEFLAGS) return 0;
    size_t count = 0;
    for (const LoadingFace& f : m.face)
        if (f.IsF(0) || f.IsF(1) || f.IsF(2)) ++count;
    return count;
}

void addPolygonNote(std::vector<std::string>& notes, size_t fromPolygons, size_t triangles) {
    if (fromPolygons > 0)
        notes.push_back("polygons were split into triangles: " + std::to_string(fromPolygons) + " of the " +
                        std::to_string(triangles) + " triangles come from polygons");
}

LoadedMesh fromLoadingMesh(const LoadingMesh& m, int mask) {
    LoadedMesh loaded;
    loaded.mesh = fromVcg(m);
    attributesFromVcg(m, mask, loaded.mesh);
    addPolygonNote(loaded.notes, trianglesFromPolygons(mask, m), loaded.mesh.faceCount());
    addDroppedNote(loaded.notes, droppedAttributes(mask, m));
    return loaded;
}

// vcglib reads some files partly without an error (faces of an index type
// it has no descriptor for, say); comparing with the count the preflight
// took from the file catches that.
void checkTriangleCount(uint64_t expected, const drm::Mesh& mesh) {
    if (mesh.faceCount() != expected)
        throw Error(ErrorKind::InvalidInput, "vcglib read " + std::to_string(mesh.faceCount()) + " of the " + std::to_string(expected) +
                    " triangles the file describes (unsupported property types?)");
}

LoadedMesh loadPly(const std::string& path) {
    PlyContents ply;
    {
        const std::vector<uint8_t> bytes = readFileBytes(path);
        ply = readPly(bytes.data(), bytes.size());
    }
    LoadedMesh loaded;
    loaded.mesh = std::move(ply.mesh);
    addPolygonNote(loaded.notes, ply.trianglesFromPolygons, loaded.mesh.faceCount());
    loaded.notes.insert(loaded.notes.end(), ply.conversions.begin(), ply.conversions.end());
    addDroppedNote(loaded.notes, ply.dropped);
    addNamesNote(loaded.notes, "PLY properties", ply.otherProperties);
    addNamesNote(loaded.notes, "PLY elements", ply.otherElements);
    if (loaded.mesh.faceCount() == 0) loaded.notes.push_back("the file has no faces");
    return loaded;
}

LoadedMesh loadOff(const std::string& path) {
    const std::vector<uint8_t> bytes = readFileBytes(path);
    const std::string text(bytes.begin(), bytes.end());
    const uint64_t expectedTriangles = preflightOff(text);
    LoadingMesh m;
    int mask = 0;
    const int status = vcg::tri::io::ImporterOFF<LoadingMesh>::OpenMem(m, text.data(), text.size(), mask);
    if (status != 0) throw Error(ErrorKind::InvalidInput, vcg::tri::io::ImporterOFF<LoadingMesh>::ErrorMsg(status));
    LoadedMesh loaded = fromLoadingMesh(m, mask);
    checkTriangleCount(expectedTriangles, loaded.mesh);
    return loaded;
}

void addWeldNote(std::vector<std::string>& notes, const drm::Mesh& soup, const drm::Mesh& welded) {
    notes.push_back("STL has no shared vertices: its " + std::to_string(soup.vertexCount()) +
                    " triangle corners were welded into " + std::to_string(welded.vertexCount()) +
                    " vertices at identical positions");
}

// ASCII STL through stl_ascii_reader.h (every solid); binary STL through
// vcglib, which also reads the face colours some tools put in a facet's
// attribute bytes.
LoadedMesh loadStl(const std::string& path) {
    LoadedMesh loaded;
    const std::vector<uint8_t> bytes = readFileBytes(path);
    if (!preflightStl(bytes)) {
        const AsciiStl stl = readAsciiStl(std::string(bytes.begin(), bytes.end()));
        loaded.mesh = weldIdenticalPositions(stl.soup);
        addWeldNote(loaded.notes, stl.soup, loaded.mesh);
        if (stl.solids > 1)
            loaded.notes.push_back("the file's " + std::to_string(stl.solids) + " solids are read as one mesh");
        if (stl.soup.faceCount() > 0) loaded.notes.push_back("the facets' normals are not kept in .drm files");
        else loaded.notes.push_back("the file has no faces");
        return loaded;
    }
    LoadingMesh m;
    int mask = 0;
    const int status = vcg::tri::io::ImporterSTL<LoadingMesh>::Open(m, path.c_str(), mask);
    if (status != 0) throw Error(ErrorKind::InvalidInput, vcg::tri::io::ImporterSTL<LoadingMesh>::ErrorMsg(status));
    const drm::Mesh soup = fromVcg(m);
    loaded.mesh = weldIdenticalPositions(soup);
    // Welding changes the vertices, not the faces: face colours stay.
    attributesFromVcg(m, mask & Mask::IOM_FACECOLOR, loaded.mesh);
    loaded.mesh.textures.clear();
    addWeldNote(loaded.notes, soup, loaded.mesh);
    if (soup.faceCount() > 0) loaded.notes.push_back("the facets' normals are not kept in .drm files");
    addDroppedNote(loaded.notes, droppedAttributes(mask & ~(Mask::IOM_FACECOLOR | Mask::IOM_FACENORMAL), m));
    return loaded;
}

std::string directoryOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Where the library `mtllib` names lies, if it is inside the OBJ's folder
// or below it; otherwise "" with `why` set. A library elsewhere is never
// read: an OBJ someone sends must not make drm copy other files (an
// absolute path, "../", or a link leading out) into the .drm it writes.
std::string libraryInsideFolder(const std::string& objPath, const std::string& mtllib, std::string& why) {
    std::string name = mtllib;
    std::replace(name.begin(), name.end(), '\\', '/');
    const bool absolute = name[0] == '/' || (name.size() >= 2 && std::isalpha(static_cast<unsigned char>(name[0])) && name[1] == ':');
    bool upward = false;
    for (size_t from = 0; from <= name.size();) {
        size_t to = name.find('/', from);
        if (to == std::string::npos) to = name.size();
        upward = upward || name.compare(from, to - from, "..") == 0;
        from = to + 1;
    }
    if (absolute || upward) {
        why = "it is outside the OBJ's folder";
        return "";
    }
    const std::string path = directoryOf(objPath) + name;
    char* folder = ::realpath(directoryOf(objPath).empty() ? "." : directoryOf(objPath).c_str(), nullptr);
    char* library = ::realpath(path.c_str(), nullptr);
    std::string folderText = folder ? folder : "", libraryText = library ? library : "";
    std::free(folder);
    std::free(library);
    if (libraryText.empty()) {
        why = "it is not beside the file (or unreadable)";
        return "";
    }
    if (folderText != "/") folderText += "/";
    if (libraryText.compare(0, folderText.size(), folderText) != 0) {
        why = "it is a link to a file outside the OBJ's folder";
        return "";
    }
    struct stat info;
    if (::stat(libraryText.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) {
        why = "it is not a regular file";
        return "";
    }
    if (info.st_size > (64 << 20)) {
        why = "it is over 64 MiB";
        return "";
    }
    return libraryText;
}

// The .mtl file named by `mtllib`: the statements understood go into the
// metadata ("obj.mtllib": the name as written, "obj.mtl": the statements,
// see mtl_library.h), its map_Kd file names into the texture list, and each
// face gets its material's texture when there are several.
void addMaterialLibrary(const std::string& objPath, const std::string& mtllib, LoadedMesh& loaded) {
    drm::Mesh& mesh = loaded.mesh;
    std::vector<std::string>& notes = loaded.notes;
    if (mtllib.empty()) return;
    mesh.metadata.emplace_back("obj.mtllib", mtllib);
    std::string why;
    const std::string mtlPath = libraryInsideFolder(objPath, mtllib, why);
    if (mtlPath.empty()) {
        notes.push_back("the material library " + printableName(mtllib) + " is not read (" + why + "): only its name is kept");
        return;
    }
    const std::vector<uint8_t> bytes = readFileBytes(mtlPath);
    loaded.otherFilesRead.push_back(mtlPath);
    const MtlLibrary parsed = readMtl(std::string(bytes.begin(), bytes.end()));
    mesh.metadata.emplace_back("obj.mtl", parsed.text);
    if (!parsed.dropped.empty()) {
        std::vector<std::string> lines = parsed.dropped;
        if (parsed.droppedCount > lines.size()) lines.push_back(std::to_string(parsed.droppedCount - lines.size()) + " more");
        notes.push_back("the material library " + printableName(mtllib) + "'s statements on " + joinList(lines) +
                        " are not kept in .drm files");
    }
    std::vector<uint32_t> textureOfMaterial(mesh.materials.size(), 0);
    for (const auto& entry : parsed.textures) {
        size_t index = std::find(mesh.textures.begin(), mesh.textures.end(), entry.second) - mesh.textures.begin();
        if (index == mesh.textures.size()) mesh.textures.push_back(entry.second);
        for (size_t m = 0; m < mesh.materials.size(); ++m)
            if (mesh.materials[m] == entry.first) textureOfMaterial[m] = uint32_t(index);
    }
    if (mesh.textures.size() > 1 && !mesh.faceMaterial.empty()) {
        mesh.faceTexture.resize(mesh.faceMaterial.size());
        for (size_t f = 0; f < mesh.faceMaterial.size(); ++f) mesh.faceTexture[f] = textureOfMaterial[mesh.faceMaterial[f]];
    }
}

LoadedMesh loadObj(const std::string& path) {
    const std::vector<uint8_t> bytes = readFileBytes(path);
    ObjContents obj = readObj(std::string(bytes.begin(), bytes.end()));
    LoadedMesh loaded;
    loaded.mesh = std::move(obj.mesh);
    addPolygonNote(loaded.notes, obj.trianglesFromPolygons, loaded.mesh.faceCount());
    addMaterialLibrary(path, obj.mtllib, loaded);
    if (obj.cornersWithoutTexCoord > 0)
        loaded.notes.push_back(std::to_string(obj.cornersWithoutTexCoord) +
                               " face corners have no texture coordinate: they get (0, 0)");
    if (obj.cornersWithoutNormal > 0)
        loaded.notes.push_back(std::to_string(obj.cornersWithoutNormal) + " face corners have no normal: they get (0, 0, 0)");
    if (obj.verticesWithoutColour > 0)
        loaded.notes.push_back(std::to_string(obj.verticesWithoutColour) + " vertices have no colour: they get white");
    if (obj.coloursOver255) loaded.notes.push_back("vertex colours above 1 were read as 0..255, not 0..1");
    if (obj.otherLibraries > 0)
        loaded.notes.push_back("only the first material library, " + printableName(obj.mtllib) + ", is read: the file names " +
                               std::to_string(obj.otherLibraries) + " more, whose materials are not kept");
    if (obj.texCoordW) loaded.notes.push_back("the texture coordinates' third (w) component is not kept in .drm files");
    if (obj.unusedTexCoords) loaded.notes.push_back("the file's texture coordinates (vt) are used by no face: they are not kept");
    if (obj.unusedNormals) loaded.notes.push_back("the file's normals (vn) are used by no face: they are not kept");
    std::vector<std::string> dropped;
    if (obj.linesOrPoints) dropped.push_back("lines and points");
    addDroppedNote(loaded.notes, dropped);
    return loaded;
}

}  // namespace

bool isMeshFileName(const std::string& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".ply" || extension == ".obj" || extension == ".off" || extension == ".stl";
}

LoadedMesh loadMesh(const std::string& path) {
    const std::string prefix = "cannot read " + path + ": ";
    struct stat info;
    if (::stat(path.c_str(), &info) != 0) throw Error(ErrorKind::Io, prefix + std::strerror(errno));
    if (!S_ISREG(info.st_mode)) throw Error(ErrorKind::Io, prefix + "not a regular file");
    if (info.st_size == 0) throw Error(ErrorKind::InvalidInput, prefix + "the file is empty");
    const std::string extension = lowerExtension(path);
    try {
        LoadedMesh loaded;
        if (extension == ".ply") loaded = loadPly(path);
        else if (extension == ".off") loaded = loadOff(path);
        else if (extension == ".stl") loaded = loadStl(path);
        else if (extension == ".obj") loaded = loadObj(path);
        else throw Error(ErrorKind::InvalidInput, "unknown mesh format '" + extension + "' (expected .ply, .obj, .off or .stl)");
        if (loaded.mesh.vertexCount() == 0) throw Error(ErrorKind::InvalidInput, "the file holds no vertices");
        checkNamesWritable(loaded.mesh);
        checkAttributesFinite(loaded.mesh);
        return loaded;
    } catch (const std::bad_alloc&) {
        throw Error(ErrorKind::InvalidInput, prefix + "out of memory (is the header's element count right?)");
    } catch (const Error& e) {
        // Our own errors keep their kind (a read that fails stays Io);
        // readFileBytes already names the file.
        const std::string reason = e.what();
        if (reason.compare(0, prefix.size(), prefix) == 0) throw;
        throw Error(e.kind(), prefix + reason);
    } catch (const std::exception& e) {
        throw Error(ErrorKind::InvalidInput, prefix + e.what());
    }
}

}  // namespace vcgio
}  // namespace drm
