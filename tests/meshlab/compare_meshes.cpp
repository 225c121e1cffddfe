// compare_meshes A.ply B.ply [--face-colours] [--face-quality] [--vertex-colours]
//                [--vertex-texcoords] [--wedge-texcoords]
//
// Exit 0 when both PLY files hold bit-identical vertex positions and the same
// faces (same corners, same order), and with the options the same per-face
// RGB colours / quality, per-vertex RGBA colours, per-vertex or per-wedge
// texture coordinates (bit-identical); otherwise prints the first
// difference and exits 1.
// The MeshLab tests use it to hold the plugins to the `drm` tool's output.
// <cstring> first: vcglib's wrap/callback.h uses strcpy without including it.
#include <cstdio>
#include <cstring>
#include <string>

#include <vcg/complex/complex.h>

#include <wrap/io_trimesh/import_ply.h>

namespace {

class Vertex;
class Face;
struct UsedTypes : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3f, vcg::vertex::Color4b, vcg::vertex::TexCoord2f,
                                  vcg::vertex::BitFlags> {};
class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::Color4b, vcg::face::Qualityf,
                              vcg::face::WedgeTexCoord2f, vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face> > {};

bool load(const char* path, Mesh& m, int& mask) {
    mask = 0;
    const int result = vcg::tri::io::ImporterPLY<Mesh>::Open(m, path, mask);
    if (result != 0 && vcg::tri::io::ImporterPLY<Mesh>::ErrorCritical(result)) {
        std::fprintf(stderr, "compare_meshes: cannot read %s: %s\n", path,
                     vcg::tri::io::ImporterPLY<Mesh>::ErrorMsg(result));
        return false;
    }
    return true;
}

int differ(const std::string& what) {
    std::printf("DIFFERENT: %s\n", what.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    bool colours = false, quality = false, vertexColours = false, vertexTexCoords = false, wedgeTexCoords = false;
    const char* paths[2] = {nullptr, nullptr};
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--face-colours") == 0) colours = true;
        else if (std::strcmp(argv[i], "--face-quality") == 0) quality = true;
        else if (std::strcmp(argv[i], "--vertex-colours") == 0) vertexColours = true;
        else if (std::strcmp(argv[i], "--vertex-texcoords") == 0) vertexTexCoords = true;
        else if (std::strcmp(argv[i], "--wedge-texcoords") == 0) wedgeTexCoords = true;
        else if (positional < 2) paths[positional++] = argv[i];
        else positional = 3;
    }
    if (positional != 2) {
        std::fprintf(stderr, "usage: compare_meshes A.ply B.ply [--face-colours] [--face-quality] [--vertex-colours]"
                             " [--vertex-texcoords] [--wedge-texcoords]\n");
        return 2;
    }
    Mesh a, b;
    int maskA = 0, maskB = 0;
    if (!load(paths[0], a, maskA) || !load(paths[1], b, maskB)) return 2;

    if (a.vert.size() != b.vert.size())
        return differ(std::to_string(a.vert.size()) + " vs " + std::to_string(b.vert.size()) + " vertices");
    if (a.face.size() != b.face.size())
        return differ(std::to_string(a.face.size()) + " vs " + std::to_string(b.face.size()) + " faces");
    for (size_t i = 0; i < a.vert.size(); ++i) {
        // Bit patterns, not values: "identical" means the same floats.
        if (std::memcmp(&a.vert[i].P()[0], &b.vert[i].P()[0], 3 * sizeof(float)) != 0)
            return differ("vertex " + std::to_string(i) + " position");
    }
    for (size_t f = 0; f < a.face.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const size_t ia = size_t(a.face[f].V(k) - &a.vert[0]);
            const size_t ib = size_t(b.face[f].V(k) - &b.vert[0]);
            if (ia != ib)
                return differ("face " + std::to_string(f) + " corner " + std::to_string(k) + ": vertex " +
                              std::to_string(ia) + " vs " + std::to_string(ib));
        }
    }
    std::string same = std::to_string(a.vert.size()) + " vertex positions, " + std::to_string(a.face.size()) + " faces";
    if (colours) {
        for (int mask : {maskA, maskB})
            if (!(mask & vcg::tri::io::Mask::IOM_FACECOLOR)) return differ("a file has no face colours");
        for (size_t f = 0; f < a.face.size(); ++f) {
            for (int k = 0; k < 3; ++k) {  // RGB; MeshLab adds alpha, drm does not
                if (a.face[f].C()[k] != b.face[f].C()[k])
                    return differ("face " + std::to_string(f) + " colour " + std::to_string(int(a.face[f].C()[0])) +
                                  "," + std::to_string(int(a.face[f].C()[1])) + "," +
                                  std::to_string(int(a.face[f].C()[2])) + " vs " +
                                  std::to_string(int(b.face[f].C()[0])) + "," + std::to_string(int(b.face[f].C()[1])) +
                                  "," + std::to_string(int(b.face[f].C()[2])));
            }
        }
        same += ", " + std::to_string(a.face.size()) + " face colours";
    }
    if (quality) {
        for (int mask : {maskA, maskB})
            if (!(mask & vcg::tri::io::Mask::IOM_FACEQUALITY)) return differ("a file has no face quality");
        for (size_t f = 0; f < a.face.size(); ++f)
            if (a.face[f].Q() != b.face[f].Q())
                return differ("face " + std::to_string(f) + " quality " + std::to_string(a.face[f].Q()) + " vs " +
                              std::to_string(b.face[f].Q()));
        same += ", " + std::to_string(a.face.size()) + " face qualities";
    }
    if (vertexColours) {
        for (int mask : {maskA, maskB})
            if (!(mask & vcg::tri::io::Mask::IOM_VERTCOLOR)) return differ("a file has no vertex colours");
        for (size_t i = 0; i < a.vert.size(); ++i)
            if (a.vert[i].C() != b.vert[i].C()) return differ("vertex " + std::to_string(i) + " colour");
        same += ", " + std::to_string(a.vert.size()) + " vertex colours";
    }
    if (vertexTexCoords) {
        for (int mask : {maskA, maskB})
            if (!(mask & vcg::tri::io::Mask::IOM_VERTTEXCOORD)) return differ("a file has no vertex texture coordinates");
        for (size_t i = 0; i < a.vert.size(); ++i)
            if (a.vert[i].T().U() != b.vert[i].T().U() || a.vert[i].T().V() != b.vert[i].T().V())
                return differ("vertex " + std::to_string(i) + " texture coordinate");
        same += ", " + std::to_string(a.vert.size()) + " vertex texture coordinates";
    }
    if (wedgeTexCoords) {
        for (int mask : {maskA, maskB})
            if (!(mask & vcg::tri::io::Mask::IOM_WEDGTEXCOORD)) return differ("a file has no wedge texture coordinates");
        for (size_t f = 0; f < a.face.size(); ++f)
            for (int k = 0; k < 3; ++k)
                if (a.face[f].WT(k).U() != b.face[f].WT(k).U() || a.face[f].WT(k).V() != b.face[f].WT(k).V())
                    return differ("face " + std::to_string(f) + " corner " + std::to_string(k) + " texture coordinate");
        same += ", " + std::to_string(3 * a.face.size()) + " wedge texture coordinates";
    }
    std::printf("IDENTICAL: %s\n", same.c_str());
    return 0;
}
