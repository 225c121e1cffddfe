// Atomic writes: a file appears complete or not at all.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <stdexcept>

#include "scratch_dir.h"

TEST(WriteFileAtomically, WritesTheBytesAndLeavesNoTemporaryFile) {
    ScratchDir dir;
    drm::vcgio::writeFileAtomically(dir.file("a.bin"), std::vector<uint8_t>{1, 2, 3});
    EXPECT_EQ(readText(dir.file("a.bin")), std::string("\x01\x02\x03"));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.bin"});
}

TEST(WriteFileAtomically, LeavesTheExistingFileAloneWhenWritingFails) {
    ScratchDir dir;
    writeText(dir.file("keep.txt"), "precious");
    EXPECT_THROW(drm::vcgio::writeFileAtomically(dir.file("keep.txt"),
                                                 [](std::ostream& out) {
                                                     out << "half a fi";
                                                     throw std::runtime_error("disk on fire");
                                                 }),
                 std::runtime_error);
    EXPECT_EQ(readText(dir.file("keep.txt")), "precious");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.txt"});
}

TEST(WriteFileAtomically, ReportsAMissingFolder) {
    ScratchDir dir;
    try {
        drm::vcgio::writeFileAtomically(dir.file("no/such/folder/x.drm"), std::vector<uint8_t>{1});
        FAIL() << "expected drm::Error";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Io) << e.what();
        // The user's message names the file: checked as text.
        EXPECT_EQ(std::string(e.what()).rfind("cannot write " + dir.file("no/such/folder/x.drm") + ": ", 0), 0u)
            << e.what();
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(SavePly, RefusesABadMeshWithoutTouchingTheExistingFile) {
    ScratchDir dir;
    writeText(dir.file("out.ply"), "old");
    drm::Mesh broken;
    broken.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    broken.triangles = {0, 1, 7};
    EXPECT_THROW(drm::vcgio::savePly(dir.file("out.ply"), broken), drm::Error);
    EXPECT_EQ(readText(dir.file("out.ply")), "old");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.ply"});
}

TEST(ReadFileBytes, NamesTheFileWhenItIsMissing) {
    ScratchDir dir;
    try {
        drm::vcgio::readFileBytes(dir.file("missing.drm"));
        FAIL() << "expected drm::Error";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Io) << e.what();
        EXPECT_NE(std::string(e.what()).find("cannot read " + dir.file("missing.drm")), std::string::npos);  // names it
    }
}
