// The readers keep exactly what the file says: every vertex (used or not),
// every face (degenerate or not), file order, corner order. vcglib's OFF and
// binary STL readers are checked here as much as ours, since their cleaning
// would break the codec's lossless promise.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <limits>

#include "scratch_dir.h"

namespace {

using drm::vcgio::loadMesh;

// Six vertices: 0..3 a tetrahedron's corners, 4 used by no face, 5 halfway
// between 0 and 1. Faces: a normal one, one repeating vertex 0, one of zero
// area (0, 5, 1), the first face again, and one more.
const std::vector<float> kPositions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 7, 7, 7, 0.5f, 0, 0};
const std::vector<uint32_t> kTriangles = {0, 2, 1, 0, 0, 3, 0, 5, 1, 0, 2, 1, 1, 2, 3};

std::string asciiPlyHeader(size_t vertices, size_t faces, const std::string& vertexExtra = "") {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\n" + vertexExtra + "element face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string vertexLines(const std::vector<float>& positions, const std::string& prefix = "") {
    std::string out;
    for (size_t i = 0; i < positions.size(); i += 3)
        out += prefix + std::to_string(positions[i]) + " " + std::to_string(positions[i + 1]) + " " +
               std::to_string(positions[i + 2]) + "\n";
    return out;
}

std::string faceLines(const std::vector<uint32_t>& triangles, const std::string& prefix, int base) {
    std::string out;
    for (size_t c = 0; c < triangles.size(); c += 3)
        out += prefix + std::to_string(triangles[c] + base) + " " + std::to_string(triangles[c + 1] + base) + " " +
               std::to_string(triangles[c + 2] + base) + "\n";
    return out;
}

bool hasNoteContaining(const drm::vcgio::LoadedMesh& loaded, const std::string& text) {
    for (const std::string& note : loaded.notes)
        if (note.find(text) != std::string::npos) return true;
    return false;
}

// The message of loadMesh's refusal ("" if none), and its kind in *kind.
std::string errorOf(const std::string& path, drm::ErrorKind* kind = nullptr) {
    try {
        loadMesh(path);
    } catch (const drm::Error& e) {
        if (kind) *kind = e.kind();
        return e.what();
    }
    return "";
}

TEST(LoadMesh, PlyKeepsUnusedVerticesDegenerateFacesAndOrder) {
    ScratchDir dir;
    writeText(dir.file("m.ply"), asciiPlyHeader(6, 5) + vertexLines(kPositions) + faceLines(kTriangles, "3 ", 0));
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("m.ply"));
    EXPECT_EQ(loaded.mesh.positions, kPositions);
    EXPECT_EQ(loaded.mesh.triangles, kTriangles);
    EXPECT_TRUE(loaded.notes.empty());
}

TEST(LoadMesh, OffKeepsUnusedVerticesDegenerateFacesAndOrder) {
    ScratchDir dir;
    writeText(dir.file("m.off"), "OFF\n# comment\n6 5 0\n" + vertexLines(kPositions) + faceLines(kTriangles, "3 ", 0));
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("m.off"));
    EXPECT_EQ(loaded.mesh.positions, kPositions);
    EXPECT_EQ(loaded.mesh.triangles, kTriangles);
}

TEST(LoadMesh, ObjKeepsFacesOnTheFirstVertex) {
    // vcglib 2020.09's OBJ reader drops every face using vertex 1.
    ScratchDir dir;
    writeText(dir.file("m.obj"), "# test\n" + vertexLines(kPositions, "v ") + faceLines(kTriangles, "f ", 1));
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(loaded.mesh.positions, kPositions);
    EXPECT_EQ(loaded.mesh.triangles, kTriangles);
}

TEST(LoadMesh, ObjReadsSlashesNegativeIndicesAndPolygons) {
    ScratchDir dir;
    writeText(dir.file("m.obj"),
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
              "f 1/1/1 2/1/1 3/1/1\n"
              "f -4//1 -2//1 -1//1\n"
              "f 1 2 3 4\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3}));
    EXPECT_TRUE(hasNoteContaining(loaded, "2 of the 4 triangles come from polygons"));
    // The corners' vt and vn are kept (every corner uses vn 1: per vertex;
    // the quad's corners have none, so all are per corner).
    EXPECT_EQ(loaded.mesh.cornerTexCoords.size(), 6u * 4);
    EXPECT_EQ(loaded.mesh.cornerNormals.size(), 9u * 4);
    EXPECT_EQ(loaded.mesh.cornerNormals[2], 1.0f);
    EXPECT_EQ(loaded.mesh.cornerNormals[9 * 3 + 2], 0.0f);
    EXPECT_TRUE(hasNoteContaining(loaded, "9 face corners have no texture coordinate"));
}

TEST(LoadMesh, PlyPolygonsAreFanSplitInPlace) {
    ScratchDir dir;
    writeText(dir.file("q.ply"), asciiPlyHeader(5, 2) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n4 0 1 2 3\n3 1 4 2\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("q.ply"));
    EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
    EXPECT_TRUE(hasNoteContaining(loaded, "2 of the 3 triangles come from polygons")) << loaded.notes.size();
}

TEST(LoadMesh, OffQuadsBecomeTwoTrianglesWithTheQuadsOrientation) {
    ScratchDir dir;
    writeText(dir.file("q.off"), "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("q.off"));
    const std::vector<uint32_t>& t = loaded.mesh.triangles;
    // vcglib picks the diagonal; either split keeps the orientation.
    const bool diagonal02 = t == std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
    const bool diagonal13 = t == std::vector<uint32_t>{1, 2, 3, 1, 3, 0};
    EXPECT_TRUE(diagonal02 || diagonal13);
    EXPECT_TRUE(hasNoteContaining(loaded, "polygons"));
}

TEST(LoadMesh, KeepsVertexColoursAndNormalsWithoutANote) {
    ScratchDir dir;
    writeText(dir.file("c.ply"),
              asciiPlyHeader(3, 1,
                             "property float nx\nproperty float ny\nproperty float nz\n"
                             "property uchar red\nproperty uchar green\nproperty uchar blue\n") +
                  "0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n0 1 0 0 0 1 0 0 255\n3 0 1 2\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("c.ply"));
    EXPECT_TRUE(loaded.notes.empty()) << loaded.notes[0];
    EXPECT_EQ(loaded.mesh.colors, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255}));
    EXPECT_EQ(loaded.mesh.normals, (std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}));
}

TEST(LoadMesh, StlIsWeldedOnIdenticalPositionsInOrderOfFirstUse) {
    ScratchDir dir;
    writeText(dir.file("a.stl"),
              "solid two\n"
              "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
              "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
              "endsolid two\n");
    const drm::vcgio::LoadedMesh ascii = loadMesh(dir.file("a.stl"));
    EXPECT_EQ(ascii.mesh.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
    EXPECT_EQ(ascii.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
    EXPECT_TRUE(hasNoteContaining(ascii, "6 triangle corners were welded into 4 vertices"));

    // The same two triangles as binary STL.
    std::string binary(80, ' ');
    const uint32_t count = 2;
    binary.append(reinterpret_cast<const char*>(&count), 4);
    const float facets[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& facet : facets) {
        binary.append(reinterpret_cast<const char*>(facet), sizeof facet);
        binary.append(2, '\0');
    }
    writeText(dir.file("b.stl"), binary);
    const drm::vcgio::LoadedMesh fromBinary = loadMesh(dir.file("b.stl"));
    EXPECT_EQ(fromBinary.mesh.positions, ascii.mesh.positions);
    EXPECT_EQ(fromBinary.mesh.triangles, ascii.mesh.triangles);
}

// The plainest binary layout (float x, y, z; a uchar-counted int list of
// three corners) has a fast path of its own: it must give what the general
// path gives for the same mesh read from an ASCII copy, and a file of that
// layout with a polygon is split with its note.
TEST(LoadMesh, PlainBinaryPlyReadsAsItsAsciiCopy) {
    ScratchDir dir;
    for (const char* name : {"bunny-lres.ply", "fandisk.ply", "soup.ply"}) {
        SCOPED_TRACE(name);
        const drm::vcgio::LoadedMesh plain = loadMesh(std::string(DRM_TEST_DATA_DIR) + "/" + name);
        ASSERT_GT(plain.mesh.faceCount(), 0u);
        std::string ascii = asciiPlyHeader(plain.mesh.vertexCount(), plain.mesh.faceCount());
        char number[32];
        for (size_t i = 0; i < plain.mesh.positions.size(); ++i) {
            std::snprintf(number, sizeof number, "%.9g", double(plain.mesh.positions[i]));
            ascii += number;
            ascii += i % 3 == 2 ? "\n" : " ";
        }
        ascii += faceLines(plain.mesh.triangles, "3 ", 0);
        writeText(dir.file("copy.ply"), ascii);
        const drm::vcgio::LoadedMesh fromAscii = loadMesh(dir.file("copy.ply"));
        ASSERT_EQ(fromAscii.mesh.positions.size(), plain.mesh.positions.size());
        EXPECT_EQ(std::memcmp(fromAscii.mesh.positions.data(), plain.mesh.positions.data(), 4 * plain.mesh.positions.size()), 0);
        EXPECT_EQ(fromAscii.mesh.triangles, plain.mesh.triangles);
        EXPECT_EQ(fromAscii.notes, plain.notes);
    }
    // A quad in the plain layout: split, with its note.
    std::string quad = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float corners[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    quad.append(reinterpret_cast<const char*>(corners), sizeof corners);
    quad.push_back(char(4));
    for (int32_t v : {0, 1, 2, 3}) quad.append(reinterpret_cast<const char*>(&v), 4);  // little-endian hosts only
    writeText(dir.file("quad.ply"), quad);
    const drm::vcgio::LoadedMesh split = loadMesh(dir.file("quad.ply"));
    EXPECT_EQ(split.mesh.faceCount(), 2u);
    EXPECT_TRUE(hasNoteContaining(split, "polygons were split"));

    // Bad input in the plain layout is refused before anything is copied:
    // a corner past the vertices, and a file cut short.
    std::string triangle = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    triangle.append(reinterpret_cast<const char*>(corners), sizeof corners);
    triangle.push_back(char(3));
    for (int32_t v : {0, 1, 4}) triangle.append(reinterpret_cast<const char*>(&v), 4);
    writeText(dir.file("bad-index.ply"), triangle);
    EXPECT_NE(errorOf(dir.file("bad-index.ply")).find("refers to vertex 4"), std::string::npos);
    writeText(dir.file("short.ply"), triangle.substr(0, triangle.size() - 6));
    EXPECT_NE(errorOf(dir.file("short.ply")).find("the file ends"), std::string::npos);
}

TEST(SavePly, RoundTripsBitExactlyThroughLoadMesh) {
    ScratchDir dir;
    drm::Mesh mesh;
    const float tiny = std::numeric_limits<float>::denorm_min();
    mesh.positions = {-0.0f, 1e30f, tiny, 0.1f, -2.5f, 3.0e-7f, 123456.789f, 0, -1, 5, 5, 5};
    mesh.triangles = {0, 1, 2, 2, 1, 3, 0, 0, 1};
    drm::vcgio::FaceAttributes attributes;
    attributes.rgb = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    attributes.quality = {0, 1, 17};
    drm::vcgio::savePly(dir.file("s.ply"), mesh, &attributes);
    const std::string text = readText(dir.file("s.ply"));
    EXPECT_NE(text.find("property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\n"),
              std::string::npos);
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("s.ply"));
    ASSERT_EQ(loaded.mesh.positions.size(), mesh.positions.size());
    EXPECT_EQ(std::memcmp(loaded.mesh.positions.data(), mesh.positions.data(), 4 * mesh.positions.size()), 0);
    EXPECT_EQ(loaded.mesh.triangles, mesh.triangles);
    // The face colours and quality come back as the mesh's own.
    ASSERT_EQ(loaded.mesh.faceColors.size(), 12u);
    EXPECT_EQ(loaded.mesh.faceColors[4], 4);
    EXPECT_EQ(loaded.mesh.faceColors[6], 6);
    EXPECT_EQ(loaded.mesh.faceQuality, attributes.quality);
}

TEST(LoadMesh, ErrorsNameTheFileAndTheReason) {
    ScratchDir dir;
    writeText(dir.file("empty.ply"), "");
    writeText(dir.file("zeros.ply"), std::string(1000, '\0'));
    writeText(dir.file("mesh.xyz"), "1 2 3\n");
    writeText(dir.file("index.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 9\n");
    writeText(dir.file("short.off"), "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    writeText(dir.file("index.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    writeText(dir.file("index.ply"), asciiPlyHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
    writeText(dir.file("nonewline.stl"), "solid");
    const std::string square = asciiPlyHeader(4, 1) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    // A polygon whose last corner is out of range, and one of 600 corners
    // in a file too short for them.
    writeText(dir.file("last-corner.ply"), square + "4 0 1 2 2000000000\n");
    writeText(dir.file("many-corners.ply"), square + "600 0 1 2\n");
    writeText(dir.file("short.ply"), square + "4 0 1 2\n");
    std::string huge = square;
    huge.replace(huge.find("element face 1"), 14, "element face 1000000000");
    writeText(dir.file("huge-count.ply"), huge);
    // Binary: a vertex block cut short inside its third vertex, and a face
    // (read as little-endian ints) naming a vertex past the last.
    const std::string binaryHeader =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    writeText(dir.file("binary-short.ply"), binaryHeader + std::string(30, '\0'));
    const char face[] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 7, 1, 0, 0};  // 3 corners: 0, 1, 263
    writeText(dir.file("binary-index.ply"), binaryHeader + std::string(48, '\0') + std::string(face, sizeof face));
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"binary-short.ply", "the file ends inside vertex 2 (truncated?)"},
        {"binary-index.ply", "face 0 refers to vertex 263"},
        {"missing.ply", "No such file"},
        {"empty.ply", "empty"},
        {"zeros.ply", "not a PLY file"},
        {"mesh.xyz", "unknown mesh format '.xyz'"},
        {"index.off", "refers to vertex 9"},
        {"short.off", "ends after 1 of the header's 2 faces"},
        {"index.obj", "refers to vertex 4"},
        {"index.ply", "refers to vertex 3"},
        {"nonewline.stl", "line break"},
        {"last-corner.ply", "face 0 refers to vertex 2000000000"},
        {"many-corners.ply", "600 vertex_indices entries"},
        {"short.ply", "face 0"},
        {"huge-count.ply", "does not fit in the file"},
    };
    for (const auto& c : cases) {
        drm::ErrorKind kind = drm::ErrorKind::Internal;
        const std::string message = errorOf(dir.file(c.first), &kind);
        // A file that cannot be opened is Io; one that opens but holds no
        // mesh the codec can take is InvalidInput.
        EXPECT_EQ(kind, c.first == "missing.ply" ? drm::ErrorKind::Io : drm::ErrorKind::InvalidInput) << message;
        // The sentence the user reads names the file and what is wrong in it.
        EXPECT_EQ(message.rfind("cannot read " + dir.file(c.first) + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(c.second), std::string::npos) << message;
    }
}

// Every solid of an ASCII STL is read (CAD tools write one per part).
TEST(LoadMesh, AsciiStlReadsEverySolid) {
    ScratchDir dir;
    const std::string facet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
    const std::string moved = "FACET NORMAL 0 0 1\r OUTER LOOP\r  VERTEX 3 3 0\r  VERTEX 2 3 0\r  VERTEX 0 2 0\r ENDLOOP\rENDFACET\r";
    writeText(dir.file("two.stl"), "solid a\n" + facet + "endsolid a\nsolid empty\nendsolid\nSOLID b\r" + moved + "ENDSOLID b\r");
    writeText(dir.file("upper-cr.stl"), "SOLID b\r" + moved + "ENDSOLID b\r");
    EXPECT_EQ(loadMesh(dir.file("upper-cr.stl")).mesh.faceCount(), 1u);
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("two.stl"));
    EXPECT_EQ(loaded.mesh.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 3, 0, 2, 3, 0, 0, 2, 0}));
    EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_TRUE(hasNoteContaining(loaded, "3 solids are read as one mesh"));
    EXPECT_TRUE(hasNoteContaining(loaded, "facets' normals"));
}

TEST(LoadMesh, AsciiStlThatIsNotWholeIsRefused) {
    ScratchDir dir;
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"solid a\n" + facet, "the file ends inside a solid"},
        {"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "the file ends inside facet 0"},
        {"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid\n",
         "line 9: facet 0 has 4 vertices"},
        {"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n", "line 4: 'zero' is not a number"},
        {"solid a\nvertex 0 0 0\n", "line 2: 'vertex' outside a facet's outer loop"},
    };
    for (size_t i = 0; i < cases.size(); ++i) {
        const std::string name = dir.file("bad" + std::to_string(i) + ".stl");
        writeText(name, cases[i].first);
        EXPECT_NE(errorOf(name).find(cases[i].second), std::string::npos) << errorOf(name);
    }
}

}  // namespace
