// Attributes in and out of files: the readers give the values the file holds
// (checked against the file's own text), and what the writers write reads
// back identical (PLY) or identical per corner (OBJ, which holds per-corner
// values and no alpha or quality).
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_dir.h"

namespace {

using drm::vcgio::loadMesh;

std::string dataFile(const std::string& name) { return std::string(DRM_TEST_DATA_DIR) + "/attributes/" + name; }

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string metadataOf(const drm::Mesh& mesh, const std::string& key) {
    for (const auto& entry : mesh.metadata)
        if (entry.first == key) return entry.second;
    return "<none>";
}

bool hasNoteContaining(const drm::vcgio::LoadedMesh& loaded, const std::string& text) {
    for (const std::string& note : loaded.notes)
        if (note.find(text) != std::string::npos) return true;
    return false;
}

// A file the reader refuses is InvalidInput; the message, which names the
// file, the element and the attribute for the user, is what the tests read.
std::string errorOf(const std::string& path) {
    try {
        loadMesh(path);
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
        return e.what();
    }
    return "";
}

// The numbers on the line after `end_header` + `row` of an ASCII PLY.
std::vector<double> asciiPlyRow(const std::string& path, size_t row) {
    std::istringstream in(readText(path));
    std::string line;
    while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
    }
    for (size_t i = 0; i <= row; ++i) std::getline(in, line);
    std::istringstream numbers(line);
    std::vector<double> values;
    double value;
    while (numbers >> value) values.push_back(value);
    return values;
}

TEST(AttributeReaders, PlyVertexNormalsTexCoordsColoursAndTextureNames) {
    const std::string path = dataFile("vcolors.ply");
    const drm::vcgio::LoadedMesh loaded = loadMesh(path);
    const drm::Mesh& mesh = loaded.mesh;
    ASSERT_EQ(mesh.vertexCount(), 36u);
    ASSERT_EQ(mesh.normals.size(), 3u * 36);
    ASSERT_EQ(mesh.texCoords.size(), 2u * 36);
    ASSERT_EQ(mesh.colors.size(), 4u * 36);
    EXPECT_TRUE(mesh.cornerTexCoords.empty());
    // x y z nx ny nz s t red green blue alpha
    for (size_t v : {size_t(0), size_t(17), size_t(35)}) {
        const std::vector<double> row = asciiPlyRow(path, v);
        ASSERT_EQ(row.size(), 12u);
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(mesh.normals[3 * v + size_t(k)], float(row[3 + size_t(k)]));
        for (int k = 0; k < 2; ++k) EXPECT_FLOAT_EQ(mesh.texCoords[2 * v + size_t(k)], float(row[6 + size_t(k)]));
        for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.colors[4 * v + size_t(k)], uint8_t(row[8 + size_t(k)]));
    }
    ASSERT_EQ(mesh.textures.size(), 3u);
    EXPECT_NE(mesh.textures[0].find("bottom.tga"), std::string::npos);
    EXPECT_NE(mesh.textures[2].find("top.tga"), std::string::npos);
    EXPECT_FALSE(hasNoteContaining(loaded, "not kept")) << (loaded.notes.empty() ? "" : loaded.notes[0]);
}

TEST(AttributeReaders, PlyVertexPerCornerExport) {
    const drm::Mesh mesh = loadMesh(dataFile("wuson-piece.ply")).mesh;
    ASSERT_EQ(mesh.vertexCount(), 1200u);
    ASSERT_EQ(mesh.faceCount(), 400u);
    ASSERT_EQ(mesh.normals.size(), 3u * 1200);
    ASSERT_EQ(mesh.texCoords.size(), 2u * 1200);
    const std::vector<double> row = asciiPlyRow(dataFile("wuson-piece.ply"), 1);
    EXPECT_FLOAT_EQ(mesh.normals[3], float(row[3]));
    EXPECT_FLOAT_EQ(mesh.texCoords[3], float(row[7]));
}

TEST(AttributeReaders, ObjVertexColoursAndCornerNormals) {
    const drm::Mesh mesh = loadMesh(dataFile("cube_with_vertexcolors.obj")).mesh;
    ASSERT_EQ(mesh.vertexCount(), 8u);
    ASSERT_EQ(mesh.colors.size(), 32u);
    // v 0.0 0.0 0.0 0.48627 0.43137 0.47059
    EXPECT_EQ(mesh.colors[0], uint8_t(std::lround(0.48627 * 255)));
    EXPECT_EQ(mesh.colors[1], uint8_t(std::lround(0.43137 * 255)));
    EXPECT_EQ(mesh.colors[2], uint8_t(std::lround(0.47059 * 255)));
    EXPECT_EQ(mesh.colors[3], 255);
    // Vertex 1 takes normal 2 in one face and 6 in another: per corner.
    EXPECT_TRUE(mesh.normals.empty());
    ASSERT_EQ(mesh.cornerNormals.size(), 9u * 12);
    EXPECT_EQ(mesh.cornerNormals[0], 0.0f);  // f 1//2 7//2 5//2, vn 0 0 -1
    EXPECT_EQ(mesh.cornerNormals[2], -1.0f);
    EXPECT_EQ(mesh.cornerNormals[9 * 2 + 0], -1.0f);  // f 1//6 4//6 3//6, vn -1 0 0
    EXPECT_TRUE(mesh.cornerTexCoords.empty());
}

TEST(AttributeReaders, ObjTexCoordsMaterialAndItsLibrary) {
    const drm::vcgio::LoadedMesh loaded = loadMesh(dataFile("duck.obj"));
    const drm::Mesh& mesh = loaded.mesh;
    ASSERT_EQ(mesh.vertexCount(), 2108u);
    ASSERT_EQ(mesh.faceCount(), 4212u);
    ASSERT_EQ(mesh.cornerTexCoords.size(), 6u * 4212);
    EXPECT_TRUE(mesh.normals.size() == 3u * 2108 || mesh.cornerNormals.size() == 9u * 4212);
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0], "blinn3");
    ASSERT_EQ(mesh.faceMaterial.size(), 4212u);
    EXPECT_EQ(metadataOf(mesh, "obj.mtllib"), "duck.mtl");
    // The library's statements, without its comments.
    EXPECT_EQ(metadataOf(mesh, "obj.mtl"),
              "newmtl blinn3\nKd 1 1 1\nKa 0 0 0\nKs 0 0 0\nKe 0 0 0\nd 1\nNi 1\nNs 0.300000012\nillum 2\nmap_Kd ./duckCM.tga\n");
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_EQ(mesh.textures[0], "./duckCM.tga");
    EXPECT_TRUE(loaded.notes.empty()) << loaded.notes[0];
}

TEST(AttributeReaders, ObjFourMaterialsUsedFiveTexturesAndAZeroNormal) {
    const drm::Mesh mesh = loadMesh(dataFile("spider.obj")).mesh;
    // usemtl names four of the library's five materials; the library's
    // five texture names are all kept.
    EXPECT_EQ(mesh.materials.size(), 4u);
    EXPECT_EQ(mesh.textures.size(), 5u);
    ASSERT_EQ(mesh.faceTexture.size(), mesh.faceCount());
    ASSERT_EQ(mesh.faceMaterial.size(), mesh.faceCount());
    // The first usemtl is HLeibTex, whose map_Kd is .\SpiderTex.jpg.
    EXPECT_EQ(mesh.materials[mesh.faceMaterial[0]], "HLeibTex");
    EXPECT_EQ(mesh.textures[mesh.faceTexture[0]], ".\\SpiderTex.jpg");
    // `vn 0 0 0` is read as it is (the codec decides what to make of it).
    const std::vector<float>& normals = mesh.normals.empty() ? mesh.cornerNormals : mesh.normals;
    bool zero = false;
    for (size_t i = 0; i + 2 < normals.size(); i += 3)
        zero = zero || (normals[i] == 0 && normals[i + 1] == 0 && normals[i + 2] == 0);
    EXPECT_TRUE(zero);
}

TEST(AttributeReaders, ObjMissingLibraryKeepsItsNameWithANote) {
    ScratchDir dir;
    writeText(dir.file("m.obj"), "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtllib"), "gone.mtl");
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtl"), "<none>");
    EXPECT_TRUE(hasNoteContaining(loaded, "gone.mtl"));
    ASSERT_EQ(loaded.mesh.materials.size(), 1u);
}

TEST(AttributeReaders, NonFiniteNormalsAndTexCoordsAreNamed) {
    ScratchDir dir;
    writeText(dir.file("n.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
              "property list uchar int vertex_indices\nend_header\n0 0 0 0 0 1\n1 0 0 nan 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
    const std::string plyError = errorOf(dir.file("n.ply"));
    EXPECT_NE(plyError.find(dir.file("n.ply")), std::string::npos) << plyError;
    EXPECT_NE(plyError.find("vertex 1"), std::string::npos) << plyError;
    EXPECT_NE(plyError.find("normal"), std::string::npos) << plyError;

    writeText(dir.file("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt inf 0\nf 1/1 2/2 3/1\n");
    const std::string objError = errorOf(dir.file("t.obj"));
    EXPECT_NE(objError.find(dir.file("t.obj")), std::string::npos) << objError;
    EXPECT_NE(objError.find("line 5"), std::string::npos) << objError;
    EXPECT_NE(objError.find("texture coordinate"), std::string::npos) << objError;
}

TEST(AttributeReaders, CustomPlyPropertiesAndFaceNormalsAreNamed) {
    ScratchDir dir;
    writeText(dir.file("c.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "property float curvature\nelement face 1\nproperty list uchar int vertex_indices\n"
              "property float nx\nproperty float ny\nproperty float nz\nend_header\n"
              "0 0 0 1\n1 0 0 2\n0 1 0 3\n3 0 1 2 0 0 1\n");
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("c.ply"));
    EXPECT_TRUE(hasNoteContaining(loaded, "vertex.curvature"));
    EXPECT_TRUE(hasNoteContaining(loaded, "per-face normals"));
}

TEST(AttributeReaders, PlyFaceAttributesAndWedgeTexCoords) {
    ScratchDir dir;
    writeText(dir.file("f.ply"),
              "ply\nformat ascii 1.0\ncomment TextureFile a.png\ncomment TextureFile b.png\nelement vertex 4\n"
              "property float x\nproperty float y\nproperty float z\nproperty float quality\nelement face 2\n"
              "property list uchar int vertex_indices\nproperty list uchar float texcoord\nproperty int texnumber\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
              "property float quality\nend_header\n"
              "0 0 0 0.5\n1 0 0 1.5\n0 1 0 2.5\n1 1 0 3.5\n"
              "3 0 1 2 6 0 0 1 0 0 1 1 10 20 30 40 7.25\n3 1 3 2 6 0.5 0.5 1 1 0 1 0 50 60 70 80 -1\n");
    const drm::Mesh mesh = loadMesh(dir.file("f.ply")).mesh;
    ASSERT_EQ(mesh.quality.size(), 4u);
    EXPECT_EQ(mesh.quality[3], 3.5f);
    ASSERT_EQ(mesh.cornerTexCoords.size(), 12u);
    EXPECT_EQ(mesh.cornerTexCoords[6], 0.5f);
    EXPECT_EQ(mesh.cornerTexCoords[8], 1.0f);
    ASSERT_EQ(mesh.faceTexture.size(), 2u);
    EXPECT_EQ(mesh.faceTexture, (std::vector<uint32_t>{1, 0}));
    ASSERT_EQ(mesh.faceColors.size(), 8u);
    EXPECT_EQ(mesh.faceColors[7], 80);
    ASSERT_EQ(mesh.faceQuality.size(), 2u);
    EXPECT_EQ(mesh.faceQuality[0], 7.25f);
    EXPECT_EQ(mesh.textures, (std::vector<std::string>{"a.png", "b.png"}));
}

// Every array a PLY file holds, identical.
void expectSamePlyArrays(const drm::Mesh& a, const drm::Mesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.colors, b.colors);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.texCoords, b.texCoords);
    EXPECT_EQ(a.quality, b.quality);
    EXPECT_EQ(a.cornerTexCoords, b.cornerTexCoords);
    EXPECT_EQ(a.faceColors, b.faceColors);
    EXPECT_EQ(a.faceQuality, b.faceQuality);
    EXPECT_EQ(a.faceTexture, b.faceTexture);
    EXPECT_EQ(a.textures, b.textures);
}

// Per corner: the values a corner has, whether stored per vertex or per corner.
std::vector<float> cornerValues(const drm::Mesh& m, const std::vector<float>& perVertex,
                                const std::vector<float>& perCorner, size_t width) {
    if (!perCorner.empty()) return perCorner;
    std::vector<float> out;
    for (uint32_t v : m.triangles)
        for (size_t k = 0; k < width; ++k) out.push_back(perVertex.empty() ? 0.0f : perVertex[width * v + k]);
    return out;
}

class AttributeWriters : public ::testing::TestWithParam<const char*> {};

TEST_P(AttributeWriters, PlyRoundTripIsIdentical) {
    ScratchDir dir;
    const drm::Mesh original = loadMesh(dataFile(GetParam())).mesh;
    drm::vcgio::savePly(dir.file("out.ply"), original);
    const drm::Mesh back = loadMesh(dir.file("out.ply")).mesh;
    expectSamePlyArrays(original, back);
}

TEST_P(AttributeWriters, ObjRoundTripIsIdenticalPerCorner) {
    ScratchDir dir;
    const drm::Mesh original = loadMesh(dataFile(GetParam())).mesh;
    drm::vcgio::saveObj(dir.file("out.obj"), original);
    const drm::vcgio::LoadedMesh loaded = loadMesh(dir.file("out.obj"));
    const drm::Mesh& back = loaded.mesh;
    EXPECT_EQ(original.positions, back.positions);
    EXPECT_EQ(original.triangles, back.triangles);
    ASSERT_EQ(original.colors.size(), back.colors.size());
    for (size_t i = 0; i < original.colors.size(); ++i)
        if (i % 4 != 3) EXPECT_EQ(original.colors[i], back.colors[i]) << "colour byte " << i;
    EXPECT_EQ(cornerValues(original, original.texCoords, original.cornerTexCoords, 2),
              cornerValues(back, back.texCoords, back.cornerTexCoords, 2));
    EXPECT_EQ(cornerValues(original, original.normals, original.cornerNormals, 3),
              cornerValues(back, back.normals, back.cornerNormals, 3));
    // A mesh with textures but no materials gets a library made up for it
    // (a material per texture), so only given materials must come back.
    if (!original.materials.empty()) {
        EXPECT_EQ(original.materials, back.materials);
        EXPECT_EQ(original.faceMaterial, back.faceMaterial);
    }
    if (!original.metadata.empty()) {
        EXPECT_EQ(metadataOf(back, "obj.mtl"), metadataOf(original, "obj.mtl"));
    }
    if (!original.textures.empty()) {
        EXPECT_EQ(original.textures, back.textures);
    }
}

INSTANTIATE_TEST_SUITE_P(AttributeMeshes, AttributeWriters,
                         ::testing::Values("vcolors.ply", "cube_with_vertexcolors.obj", "duck.obj", "spider.obj",
                                           "wuson-piece.ply"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

TEST(AttributeWriters, PlyWithFaceDataReadsBack) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.quality = {1, 2, 3};
    mesh.faceColors = {9, 8, 7, 6};
    mesh.faceQuality = {0.125f};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1};
    mesh.textures = {"t.png"};
    drm::vcgio::savePly(dir.file("f.ply"), mesh);
    const drm::Mesh back = loadMesh(dir.file("f.ply")).mesh;
    expectSamePlyArrays(mesh, back);
}

TEST(AttributeWriters, PlyNamesWhatItCannotHold) {
    ScratchDir dir;
    const drm::Mesh duck = loadMesh(dataFile("duck.obj")).mesh;
    const std::vector<std::string> notes = drm::vcgio::savePly(dir.file("duck.ply"), duck);
    bool materials = false;
    for (const std::string& note : notes) materials = materials || note.find("materials") != std::string::npos;
    EXPECT_TRUE(materials);
}

TEST(AttributeWriters, ObjWritesItsLibraryBesideItAndLeavesAnIdenticalOne) {
    ScratchDir dir;
    const drm::Mesh duck = loadMesh(dataFile("duck.obj")).mesh;
    drm::vcgio::saveObj(dir.file("a.obj"), duck);
    EXPECT_EQ(readText(dir.file("a.mtl")), metadataOf(duck, "obj.mtl"));
    EXPECT_NE(readText(dir.file("a.obj")).find("mtllib a.mtl\n"), std::string::npos);
    // A second write finds the same library and leaves it; a different one
    // is replaced.
    const auto before = std::filesystem::last_write_time(dir.file("a.mtl"));
    drm::vcgio::saveObj(dir.file("a.obj"), duck);
    EXPECT_EQ(std::filesystem::last_write_time(dir.file("a.mtl")), before);
    writeText(dir.file("a.mtl"), "newmtl other\n");
    drm::vcgio::saveObj(dir.file("a.obj"), duck);
    EXPECT_EQ(readText(dir.file("a.mtl")), metadataOf(duck, "obj.mtl"));
    for (const std::string& name : dir.entries()) EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
}

TEST(AttributeWriters, ObjMakesALibraryForTexturesWithoutOne) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    mesh.triangles = {0, 1, 2, 1, 3, 2};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 1};
    mesh.textures = {"a.png", "b.png"};
    mesh.faceTexture = {0, 1};
    drm::vcgio::saveObj(dir.file("m.obj"), mesh);
    const drm::Mesh back = loadMesh(dir.file("m.obj")).mesh;
    EXPECT_EQ(back.textures, mesh.textures);
    EXPECT_EQ(back.faceTexture, mesh.faceTexture);
    EXPECT_EQ(back.cornerTexCoords, mesh.cornerTexCoords);
    EXPECT_EQ(metadataOf(back, "obj.mtllib"), "m.mtl");
}

TEST(AttributeWriters, SaveMeshChoosesByExtension) {
    ScratchDir dir;
    const drm::Mesh cube = loadMesh(dataFile("cube_with_vertexcolors.obj")).mesh;
    drm::vcgio::saveMesh(dir.file("x.PLY"), cube);
    drm::vcgio::saveMesh(dir.file("x.obj"), cube);
    EXPECT_EQ(readText(dir.file("x.PLY")).rfind("ply\n", 0), 0u);
    EXPECT_EQ(readText(dir.file("x.obj")).rfind("# written by drm", 0), 0u);
    EXPECT_THROW(drm::vcgio::saveMesh(dir.file("x.stl"), cube), drm::Error);
}

TEST(AttributeWriters, InconsistentArraysAreRefusedBeforeWriting) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.normals = {0, 0, 1};
    EXPECT_THROW(drm::vcgio::savePly(dir.file("bad.ply"), mesh), drm::Error);
    EXPECT_THROW(drm::vcgio::saveObj(dir.file("bad.obj"), mesh), drm::Error);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
