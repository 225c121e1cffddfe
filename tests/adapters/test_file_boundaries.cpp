// What files the readers and writers touch, and names that must not change
// a file's structure: a mesh someone sends must not make drm read a file
// outside its folder (and ship it inside a .drm), nor a .drm make decoding
// write anything but the outputs named. Canary files check both.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "scratch_dir.h"

namespace {

using drm::vcgio::loadMesh;
using drm::vcgio::LoadedMesh;

const char kCanaryText[] = "canary: this file must stay as it is\n";

std::string metadataOf(const drm::Mesh& mesh, const std::string& key) {
    for (const auto& entry : mesh.metadata)
        if (entry.first == key) return entry.second;
    return "<none>";
}

bool hasNoteContaining(const LoadedMesh& loaded, const std::string& text) {
    for (const std::string& note : loaded.notes)
        if (note.find(text) != std::string::npos) return true;
    return false;
}

std::string errorOfWriting(const std::function<void()>& write) {
    try {
        write();
    } catch (const drm::Error& e) {
        return e.what();
    }
    return "";
}

std::vector<std::string> sorted(std::vector<std::string> names) {
    std::sort(names.begin(), names.end());
    return names;
}

// One triangle with a material, as a decoded .drm gives it.
drm::Mesh triangleWithMaterial(const std::string& material) {
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.materials = {material};
    mesh.faceMaterial = {0};
    return mesh;
}

const char kTriangleObj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";

// --- Reading: the material library only inside the OBJ's folder ---

std::string outsidePathName(const ::testing::TestParamInfo<std::string>& info) {
    static const char* const names[] = {"parent", "absolute", "link_out", "parent_after_sub", "backslash_parent"};
    return names[info.index];
}

class LibraryOutsideFolder : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryOutsideFolder, IsNotRead) {
    ScratchDir dir;
    std::filesystem::create_directory(dir.file("model"));
    writeText(dir.file("secret.mtl"), "newmtl red\nmap_Kd stolen.png\n");
    std::string mtllib = GetParam();
    if (mtllib == "ABSOLUTE") mtllib = dir.file("secret.mtl");
    if (mtllib == "LINK") {
        ASSERT_EQ(::symlink(dir.file("secret.mtl").c_str(), dir.file("model/link.mtl").c_str()), 0);
        mtllib = "link.mtl";
    }
    writeText(dir.file("model/m.obj"), "mtllib " + mtllib + "\n" + kTriangleObj);
    const LoadedMesh loaded = loadMesh(dir.file("model/m.obj"));
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtl"), "<none>");
    EXPECT_TRUE(loaded.mesh.textures.empty());
    EXPECT_TRUE(hasNoteContaining(loaded, "outside the OBJ's folder")) << (loaded.notes.empty() ? "" : loaded.notes[0]);
}

INSTANTIATE_TEST_SUITE_P(Paths, LibraryOutsideFolder,
                         ::testing::Values("../secret.mtl", "ABSOLUTE", "LINK", "sub/../../secret.mtl", "..\\secret.mtl"),
                         outsidePathName);

TEST(LibraryInsideFolder, IsReadFromASubfolder) {
    ScratchDir dir;
    std::filesystem::create_directory(dir.file("materials"));
    writeText(dir.file("materials/lib.mtl"), "newmtl red\nKd 1 0 0\nmap_Kd red.png\n");
    writeText(dir.file("m.obj"), std::string("mtllib materials/lib.mtl\n") + kTriangleObj);
    const LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtl"), "newmtl red\nKd 1 0 0\nmap_Kd red.png\n");
    EXPECT_EQ(loaded.mesh.textures, std::vector<std::string>{"red.png"});
    EXPECT_TRUE(loaded.notes.empty()) << loaded.notes[0];
}

TEST(LibraryInsideFolder, KeepsTheStatementsItParsedNotTheText) {
    ScratchDir dir;
    writeText(dir.file("lib.mtl"),
              "# exported by a tool\r\nnewmtl red   # shiny\r\nKd 1  0 0\r\nsecret text from elsewhere\r\n"
              "Ns not-a-number\r\nmap_Kd -s 1 1 1 -clamp on my texture{1}~é.png\r\n");
    writeText(dir.file("m.obj"), std::string("mtllib lib.mtl # the library\n") + kTriangleObj);
    const LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtllib"), "lib.mtl");
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtl"), "newmtl red\nKd 1 0 0\nmap_Kd -s 1 1 1 -clamp on my texture{1}~é.png\n");
    EXPECT_EQ(loaded.mesh.textures, std::vector<std::string>{"my texture{1}~é.png"});
    EXPECT_TRUE(hasNoteContaining(loaded, "line 4 (secret)"));
    EXPECT_TRUE(hasNoteContaining(loaded, "line 5 (Ns)"));
}

// --- Writing: exactly the outputs named ---

TEST(ObjWriter, WritesOnlyTheObjAndItsLibraryWhateverNameTheMeshHolds) {
    for (const std::string& stored : {std::string(".profile"), std::string("../canary.txt"), std::string("/tmp/x.mtl"),
                                      std::string("out.obj")}) {
        ScratchDir dir;
        std::filesystem::create_directory(dir.file("out"));
        writeText(dir.file("canary.txt"), kCanaryText);
        writeText(dir.file("out/.profile"), kCanaryText);
        drm::Mesh mesh = triangleWithMaterial("red");
        mesh.metadata = {{"obj.mtllib", stored}, {"obj.mtl", "newmtl red\nKd 1 0 0\n"}};
        drm::vcgio::saveObj(dir.file("out/mesh.obj"), mesh);
        EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"canary.txt", "out"})) << stored;
        EXPECT_EQ(readText(dir.file("canary.txt")), kCanaryText) << stored;
        EXPECT_EQ(readText(dir.file("out/.profile")), kCanaryText) << stored;
        std::vector<std::string> written;
        for (const auto& entry : std::filesystem::directory_iterator(dir.file("out")))
            written.push_back(entry.path().filename().string());
        EXPECT_EQ(sorted(written), (std::vector<std::string>{".profile", "mesh.mtl", "mesh.obj"})) << stored;
        EXPECT_NE(readText(dir.file("out/mesh.obj")).find("mtllib mesh.mtl\n"), std::string::npos) << stored;
        EXPECT_EQ(readText(dir.file("out/mesh.mtl")), "newmtl red\nKd 1 0 0\n") << stored;
    }
}

TEST(ObjWriter, WritesOnlyMaterialStatementsFromAStoredLibrary) {
    // A hand-made .drm can hold any text as its library: it is parsed
    // again, so only material statements reach the file.
    ScratchDir dir;
    drm::Mesh mesh = triangleWithMaterial("red");
    mesh.metadata = {{"obj.mtl", "newmtl red\n#!/bin/sh\nrm -rf ~\nKd 1 0 0\n"}};
    drm::vcgio::saveObj(dir.file("m.obj"), mesh);
    EXPECT_EQ(readText(dir.file("m.mtl")), "newmtl red\nKd 1 0 0\n");
}

TEST(ObjWriter, WithoutAStoredLibraryNamesNone) {
    ScratchDir dir;
    drm::Mesh mesh = triangleWithMaterial("red");
    mesh.metadata = {{"obj.mtllib", "gone.mtl"}};
    const std::vector<std::string> notes = drm::vcgio::saveObj(dir.file("m.obj"), mesh);
    EXPECT_EQ(readText(dir.file("m.obj")).find("mtllib"), std::string::npos);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"m.obj"});
    ASSERT_FALSE(notes.empty());
    EXPECT_NE(notes[0].find("gone.mtl"), std::string::npos);
}

TEST(ObjWriter, ReadsNoSpecialFileAtTheLibrarysPlace) {
    // A FIFO where OUT.mtl goes is neither read (which would wait for a
    // writer for ever) nor replaced.
    ScratchDir dir;
    ASSERT_EQ(::mkfifo(dir.file("m.mtl").c_str(), 0600), 0);
    drm::Mesh mesh = triangleWithMaterial("red");
    mesh.metadata = {{"obj.mtl", "newmtl red\n"}};
    const std::string error = errorOfWriting([&] { drm::vcgio::saveObj(dir.file("m.obj"), mesh); });
    EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
    EXPECT_EQ(sorted(dir.entries()), std::vector<std::string>{"m.mtl"});
}

TEST(ObjWriter, AFailedObjLeavesAnExistingLibraryAsItWas) {
    ScratchDir dir;
    writeText(dir.file("m.mtl"), kCanaryText);
    ASSERT_EQ(::symlink(dir.file("missing/m.obj").c_str(), dir.file("m.obj").c_str()), 0);
    drm::Mesh mesh = triangleWithMaterial("red");
    mesh.metadata = {{"obj.mtl", "newmtl red\n"}};
    EXPECT_FALSE(errorOfWriting([&] { drm::vcgio::saveObj(dir.file("m.obj"), mesh); }).empty());
    EXPECT_EQ(readText(dir.file("m.mtl")), kCanaryText);
    EXPECT_EQ(sorted(dir.entries()), (std::vector<std::string>{"m.mtl", "m.obj"}));
}

TEST(ObjWriter, RefusesABackslashInItsFileName) {
    ScratchDir dir;
    const std::string error =
        errorOfWriting([&] { drm::vcgio::saveObj(dir.file("x\\y.obj"), triangleWithMaterial("red")); });
    EXPECT_NE(error.find("'\\'"), std::string::npos) << error;
    EXPECT_TRUE(dir.entries().empty());
}

// --- Names that would change a file's structure are refused ---

TEST(ObjWriter, RefusesAMaterialNameThatWouldAddStatements) {
    ScratchDir dir;
    const drm::Mesh mesh = triangleWithMaterial("blinn3\nf 1 2 3\nv 1e30 0 0");
    const std::string error = errorOfWriting([&] { drm::vcgio::saveObj(dir.file("m.obj"), mesh); });
    EXPECT_NE(error.find("blinn3\\nf 1 2 3"), std::string::npos) << error;
    EXPECT_NE(error.find("line break"), std::string::npos) << error;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ObjWriter, RefusesNamesThatReadBackDifferently) {
    for (const std::string& name : {std::string(" red"), std::string("red "), std::string("red # c"), std::string("#red")}) {
        ScratchDir dir;
        const std::string error =
            errorOfWriting([&] { drm::vcgio::saveObj(dir.file("m.obj"), triangleWithMaterial(name)); });
        EXPECT_NE(error.find("cannot be written in OBJ"), std::string::npos) << "'" << name << "': " << error;
        EXPECT_TRUE(dir.entries().empty()) << name;
    }
}

TEST(ObjWriter, RefusesATextureNameThatWouldAddStatements) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1};
    mesh.textures = {"a.png\nnewmtl evil"};
    const std::string error = errorOfWriting([&] { drm::vcgio::saveObj(dir.file("m.obj"), mesh); });
    EXPECT_NE(error.find("texture file name"), std::string::npos) << error;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(PlyWriter, RefusesATextureNameThatWouldEndTheComment) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1};
    mesh.textures = {"a.png\nelement vertex 9"};
    const std::string error = errorOfWriting([&] { drm::vcgio::savePly(dir.file("m.ply"), mesh); });
    EXPECT_NE(error.find("cannot be written in PLY"), std::string::npos) << error;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(Readers, RefuseNamesWithControlCharacters) {
    ScratchDir dir;
    writeText(dir.file("t.ply"), "ply\nformat ascii 1.0\ncomment TextureFile a\fb.png\nelement vertex 3\nproperty float x\n"
                                 "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    writeText(dir.file("m.obj"), std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\x1b]0;x\x07b\nf 1 2 3\n"));
    for (const char* name : {"t.ply", "m.obj"}) {
        try {
            loadMesh(dir.file(name));
            ADD_FAILURE() << name << " was read";
        } catch (const drm::Error& e) {
            EXPECT_NE(std::string(e.what()).find("control character"), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos) << "the message holds the raw name";
        }
    }
}

TEST(PlyReader, NamesDataPastItsLastElement) {
    ScratchDir dir;
    writeText(dir.file("m.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n");
    const LoadedMesh loaded = loadMesh(dir.file("m.ply"));
    EXPECT_EQ(loaded.mesh.faceCount(), 1u);
    EXPECT_TRUE(hasNoteContaining(loaded, "goes on past the last element its header declares: 4 characters"));
}

TEST(PlyWriter, KeepsTextureNamesWithBlanksAtTheirEnds) {
    ScratchDir dir;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1};
    mesh.textures = {" lead.png", "trail.png ", "a  b#c.png"};
    mesh.faceTexture = {1};
    drm::vcgio::savePly(dir.file("m.ply"), mesh);
    EXPECT_EQ(loadMesh(dir.file("m.ply")).mesh.textures, mesh.textures);
}

TEST(ObjReader, NamesTheLibrariesItDoesNotRead) {
    ScratchDir dir;
    writeText(dir.file("a.mtl"), "newmtl red\n");
    writeText(dir.file("b.mtl"), "newmtl blue\n");
    writeText(dir.file("m.obj"), std::string("mtllib a.mtl\nmtllib b.mtl\n") + kTriangleObj);
    const LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_EQ(metadataOf(loaded.mesh, "obj.mtl"), "newmtl red\n");
    EXPECT_TRUE(hasNoteContaining(loaded, "only the first material library, a.mtl, is read"));
}

TEST(LibraryInsideFolder, ManyUnknownStatementsAreCountedNotListed) {
    ScratchDir dir;
    std::string junk;
    for (int i = 0; i < 20000; ++i) junk += "x y\n";
    writeText(dir.file("lib.mtl"), junk + "newmtl red\n");
    writeText(dir.file("m.obj"), std::string("mtllib lib.mtl\n") + kTriangleObj);
    const LoadedMesh loaded = loadMesh(dir.file("m.obj"));
    EXPECT_TRUE(hasNoteContaining(loaded, "line 5 (x) and 19995 more"));
}

TEST(ObjWriter, KeepsNamesWithBlanksBracesTildesAndUtf8) {
    ScratchDir dir;
    drm::Mesh mesh = triangleWithMaterial("my mat{1}~café");
    mesh.metadata = {{"obj.mtl", "newmtl my mat{1}~café\nmap_Kd PROGRA~1/tex {1}é.png\n"}};
    drm::vcgio::saveObj(dir.file("m.obj"), mesh);
    const drm::Mesh back = loadMesh(dir.file("m.obj")).mesh;
    EXPECT_EQ(back.materials, mesh.materials);
    EXPECT_EQ(back.textures, std::vector<std::string>{"PROGRA~1/tex {1}é.png"});
}

TEST(ObjWriter, NamesThePointNormalsItCannotHold) {
    ScratchDir dir;
    drm::Mesh points;
    points.positions = {0, 0, 0, 1, 0, 0};
    points.normals = {0, 0, 1, 0, 1, 0};
    const std::vector<std::string> notes = drm::vcgio::saveObj(dir.file("p.obj"), points);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("the vertices' normals are not in"), std::string::npos) << notes[0];
}

// --- OBJ statements as other tools write them ---

TEST(ObjReader, TrailingCommentsAndCrOnlyLines) {
    ScratchDir dir;
    writeText(dir.file("m.obj"), "# made by hand\rv 0 0 0 # first\rv 1 0 0\rv 0 1 0\rusemtl red # shiny\rf 1 2 3 # one\r");
    const drm::Mesh mesh = loadMesh(dir.file("m.obj")).mesh;
    EXPECT_EQ(mesh.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
    EXPECT_EQ(mesh.triangles, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(mesh.materials, std::vector<std::string>{"red"});
}

TEST(ObjReader, ByteOrderMarks) {
    ScratchDir dir;
    writeText(dir.file("utf8.obj"), std::string("\xEF\xBB\xBF") + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(loadMesh(dir.file("utf8.obj")).mesh.faceCount(), 1u);
    writeText(dir.file("utf16.obj"), std::string("\xFE\xFF\0v\0 \0" "0", 7));
    try {
        loadMesh(dir.file("utf16.obj"));
        FAIL() << "UTF-16 text was read";
    } catch (const drm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("UTF-16"), std::string::npos) << e.what();
    }
}

TEST(ObjReader, ANonFiniteColourIsRefused) {
    ScratchDir dir;
    writeText(dir.file("m.obj"), "v 0 0 0 1 0 0\nv 1 0 0 nan 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    try {
        loadMesh(dir.file("m.obj"));
        FAIL() << "a NaN colour was read";
    } catch (const drm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("line 2: the colour of vertex 2 is not finite"), std::string::npos) << e.what();
    }
}

TEST(ObjReader, WhatItDoesNotKeepIsNamed) {
    ScratchDir dir;
    writeText(dir.file("w.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0 0.5\nf 1/1 2/1 3/1\n");
    EXPECT_TRUE(hasNoteContaining(loadMesh(dir.file("w.obj")), "third (w) component"));
    writeText(dir.file("n.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n");
    EXPECT_TRUE(hasNoteContaining(loadMesh(dir.file("n.obj")), "normals (vn) are used by no face"));
}

// --- An output that is an input ---

TEST(RefuseOverwritingInput, SamePathLinkAndHardLink) {
    ScratchDir dir;
    writeText(dir.file("a.ply"), kCanaryText);
    ASSERT_EQ(::symlink(dir.file("a.ply").c_str(), dir.file("link.ply").c_str()), 0);
    ASSERT_EQ(::link(dir.file("a.ply").c_str(), dir.file("hard.ply").c_str()), 0);
    for (const char* output : {"a.ply", "link.ply", "hard.ply"}) {
        const std::string error =
            errorOfWriting([&] { drm::vcgio::refuseOverwritingInput(dir.file("a.ply"), dir.file(output)); });
        EXPECT_NE(error.find("it is the input"), std::string::npos) << output << ": " << error;
    }
    writeText(dir.file("b.ply"), kCanaryText);
    EXPECT_NO_THROW(drm::vcgio::refuseOverwritingInput(dir.file("a.ply"), dir.file("b.ply")));
    EXPECT_NO_THROW(drm::vcgio::refuseOverwritingInput(dir.file("a.ply"), dir.file("new.drm")));
}

}  // namespace
