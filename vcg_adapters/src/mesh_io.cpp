// loadMesh: PLY, OFF and STL through vcglib's importers, OBJ through
// obj_reader.cpp (vcglib's drops faces, see obj_reader.h). Every path keeps
// vertex order, face order and corner order as in the file.
#include "drm_vcg/mesh_io.h"

#include "drm_vcg/file_io.h"
#include "drm_vcg/vcg_mesh.h"
#include "format_preflight.h"
#include "loading_mesh.h"
#include "obj_reader.h"
#include "stl_weld.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <new>
#include <sys/stat.h>

#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
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

// "a", "a and b", "a, b and c".
std::string joinList(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += (i + 1 == items.size()) ? " and " : ", ";
        out += items[i];
    }
    return out;
}

void addDroppedNote(std::vector<std::string>& notes, const std::vector<std::string>& dropped) {
    if (!dropped.empty()) notes.push_back("the file's " + joinList(dropped) + " are not kept in .drm files");
}

// What vcglib's load mask says the file had that drm::Mesh does not hold.
std::vector<std::string> droppedAttributes(int mask, const LoadingMesh& m) {
    std::vector<std::string> dropped;
    if (mask & Mask::IOM_VERTCOLOR) dropped.push_back("vertex colours");
    if (mask & (Mask::IOM_VERTNORMAL | Mask::IOM_FACENORMAL | Mask::IOM_WEDGNORMAL)) dropped.push_back("normals");
    if (mask & (Mask::IOM_VERTTEXCOORD | Mask::IOM_WEDGTEXCOORD)) dropped.push_back("texture coordinates");
    if (mask & (Mask::IOM_FACECOLOR | Mask::IOM_WEDGCOLOR)) dropped.push_back("face colours");
    if (mask & Mask::IOM_VERTQUALITY) dropped.push_back("vertex quality values");
    if (mask & Mask::IOM_FACEQUALITY) dropped.push_back("face quality values");
    if (mask & Mask::IOM_VERTRADIUS) dropped.push_back("vertex radii");
    if (m.en > 0) dropped.push_back("edges");
    if (mask & Mask::IOM_CAMERA) dropped.push_back("camera parameters");
    if (!m.textures.empty()) dropped.push_back("texture file names");
    return dropped;
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
    addPolygonNote(loaded.notes, trianglesFromPolygons(mask, m), loaded.mesh.faceCount());
    addDroppedNote(loaded.notes, droppedAttributes(mask, m));
    return loaded;
}

// vcglib reads some files partly without an error (faces of an index type
// it has no descriptor for, say); comparing with the count the preflight
// took from the file catches that.
void checkTriangleCount(uint64_t expected, const drm::Mesh& mesh) {
    if (mesh.faceCount() != expected)
        throw Error("vcglib read " + std::to_string(mesh.faceCount()) + " of the " + std::to_string(expected) +
                    " triangles the file describes (unsupported property types?)");
}

LoadedMesh loadPly(const std::string& path) {
    const int64_t expectedTriangles = preflightPly(readFileBytes(path));
    LoadingMesh m;
    int mask = 0;
    const int status = vcg::tri::io::ImporterPLY<LoadingMesh>::Open(m, path.c_str(), mask);
    if (status == vcg::tri::io::PlyInfo::E_SHORTFILE) throw Error("the file ends early (truncated?)");
    if (vcg::tri::io::ImporterPLY<LoadingMesh>::ErrorCritical(status))
        throw Error(vcg::tri::io::ImporterPLY<LoadingMesh>::ErrorMsg(status));
    LoadedMesh loaded = fromLoadingMesh(m, mask);
    if (expectedTriangles >= 0) checkTriangleCount(uint64_t(expectedTriangles), loaded.mesh);
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
    if (status != 0) throw Error(vcg::tri::io::ImporterOFF<LoadingMesh>::ErrorMsg(status));
    LoadedMesh loaded = fromLoadingMesh(m, mask);
    checkTriangleCount(expectedTriangles, loaded.mesh);
    return loaded;
}

LoadedMesh loadStl(const std::string& path) {
    preflightStl(readFileBytes(path));
    LoadingMesh m;
    int mask = 0;
    const int status = vcg::tri::io::ImporterSTL<LoadingMesh>::Open(m, path.c_str(), mask);
    if (status != 0) throw Error(vcg::tri::io::ImporterSTL<LoadingMesh>::ErrorMsg(status));
    LoadedMesh loaded;
    const drm::Mesh soup = fromVcg(m);
    loaded.mesh = weldIdenticalPositions(soup);
    loaded.notes.push_back("STL has no shared vertices: its " + std::to_string(soup.vertexCount()) +
                           " triangle corners were welded into " + std::to_string(loaded.mesh.vertexCount()) +
                           " vertices at identical positions");
    addDroppedNote(loaded.notes, droppedAttributes(mask, m));
    return loaded;
}

LoadedMesh loadObj(const std::string& path) {
    const std::vector<uint8_t> bytes = readFileBytes(path);
    ObjContents obj = readObj(std::string(bytes.begin(), bytes.end()));
    LoadedMesh loaded;
    loaded.mesh = std::move(obj.mesh);
    addPolygonNote(loaded.notes, obj.trianglesFromPolygons, loaded.mesh.faceCount());
    std::vector<std::string> dropped;
    if (obj.vertexColours) dropped.push_back("vertex colours");
    if (obj.normals) dropped.push_back("normals");
    if (obj.textureCoordinates) dropped.push_back("texture coordinates");
    if (obj.materials) dropped.push_back("materials");
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
    if (::stat(path.c_str(), &info) != 0) throw Error(prefix + std::strerror(errno));
    if (!S_ISREG(info.st_mode)) throw Error(prefix + "not a regular file");
    if (info.st_size == 0) throw Error(prefix + "the file is empty");
    const std::string extension = lowerExtension(path);
    try {
        LoadedMesh loaded;
        if (extension == ".ply") loaded = loadPly(path);
        else if (extension == ".off") loaded = loadOff(path);
        else if (extension == ".stl") loaded = loadStl(path);
        else if (extension == ".obj") loaded = loadObj(path);
        else throw Error("unknown mesh format '" + extension + "' (expected .ply, .obj, .off or .stl)");
        if (loaded.mesh.vertexCount() == 0) throw Error("the file holds no vertices");
        return loaded;
    } catch (const std::bad_alloc&) {
        throw Error(prefix + "out of memory (is the header's element count right?)");
    } catch (const std::exception& e) {
        const std::string reason = e.what();
        // readFileBytes already names the file.
        if (reason.compare(0, 12, "cannot read ") == 0) throw Error(reason);
        throw Error(prefix + reason);
    }
}

}  // namespace vcgio
}  // namespace drm
