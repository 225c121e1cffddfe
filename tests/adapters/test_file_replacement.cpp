// Replacing an existing file: what the user set on it survives (mode, owner
// where permitted), symbolic links are written through, files the user may
// not write are refused, and a refused or failed write changes nothing.
//
// Root may write any file, so the refusal is only observable as another
// user: ctest runs this binary a second time as `nobody` (adapter_tests.
// as_user, tests/adapters/run_as_user.sh), and the tests that need a
// non-root user skip themselves, saying so, when run as root.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include "scratch_dir.h"

namespace {

mode_t modeOf(const std::string& path) {
    struct stat info;
    EXPECT_EQ(::stat(path.c_str(), &info), 0) << path;
    return info.st_mode & 07777;
}

bool isLink(const std::string& path) {
    struct stat info;
    return ::lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode);
}

const std::vector<uint8_t> kNewBytes{'n', 'e', 'w'};

}  // namespace

TEST(FileReplacement, KeepsAPrivateFilePrivate) {
    ScratchDir dir;
    const std::string path = dir.file("private.drm");
    writeText(path, "old");
    ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
    drm::vcgio::writeFileAtomically(path, kNewBytes);
    EXPECT_EQ(readText(path), "new");
    EXPECT_EQ(modeOf(path), mode_t(0600));
}

TEST(FileReplacement, KeepsAnUnusualMode) {
    ScratchDir dir;
    const std::string path = dir.file("shared.drm");
    writeText(path, "old");
    ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
    drm::vcgio::writeFileAtomically(path, kNewBytes);
    EXPECT_EQ(modeOf(path), mode_t(0640));
}

TEST(FileReplacement, NewFileFollowsTheUmask) {
    ScratchDir dir;
    const mode_t old = ::umask(027);
    drm::vcgio::writeFileAtomically(dir.file("fresh.drm"), kNewBytes);
    ::umask(old);
    EXPECT_EQ(modeOf(dir.file("fresh.drm")), mode_t(0640));
}

TEST(FileReplacement, KeepsOwnerAndGroup) {
    ScratchDir dir;
    const std::string path = dir.file("owned.drm");
    writeText(path, "old");
    struct stat before;
    ASSERT_EQ(::stat(path.c_str(), &before), 0);
    if (::geteuid() == 0) {
        // Root may give a file away: hand it to nobody, and it must stay theirs.
        ASSERT_EQ(::chown(path.c_str(), 65534, 65534), 0);
        ASSERT_EQ(::stat(path.c_str(), &before), 0);
    }
    drm::vcgio::writeFileAtomically(path, kNewBytes);
    struct stat after;
    ASSERT_EQ(::stat(path.c_str(), &after), 0);
    EXPECT_EQ(after.st_uid, before.st_uid);
    EXPECT_EQ(after.st_gid, before.st_gid);
}

TEST(FileReplacement, WritesThroughASymbolicLink) {
    ScratchDir dir;
    ASSERT_EQ(::mkdir(dir.file("real").c_str(), 0755), 0);
    const std::string target = dir.file("real/mesh.drm");
    writeText(target, "old");
    ASSERT_EQ(::chmod(target.c_str(), 0600), 0);
    ASSERT_EQ(::symlink("real/mesh.drm", dir.file("link.drm").c_str()), 0);
    drm::vcgio::writeFileAtomically(dir.file("link.drm"), kNewBytes);
    EXPECT_TRUE(isLink(dir.file("link.drm"))) << "the link was replaced by a file";
    EXPECT_EQ(readText(target), "new");
    EXPECT_EQ(modeOf(target), mode_t(0600));
    EXPECT_EQ(dir.entries().size(), 2u) << "a temporary file was left behind";
}

TEST(FileReplacement, WritesThroughAChainOfLinksAndCreatesADanglingLinksTarget) {
    ScratchDir dir;
    ASSERT_EQ(::symlink("b.drm", dir.file("a.drm").c_str()), 0);
    ASSERT_EQ(::symlink(dir.file("c.drm").c_str(), dir.file("b.drm").c_str()), 0);
    drm::vcgio::writeFileAtomically(dir.file("a.drm"), kNewBytes);
    EXPECT_TRUE(isLink(dir.file("a.drm")));
    EXPECT_TRUE(isLink(dir.file("b.drm")));
    EXPECT_EQ(readText(dir.file("c.drm")), "new");
}

TEST(FileReplacement, RefusesALinkLoop) {
    ScratchDir dir;
    ASSERT_EQ(::symlink("b.drm", dir.file("a.drm").c_str()), 0);
    ASSERT_EQ(::symlink("a.drm", dir.file("b.drm").c_str()), 0);
    EXPECT_THROW(drm::vcgio::writeFileAtomically(dir.file("a.drm"), kNewBytes), drm::Error);
    EXPECT_EQ(dir.entries().size(), 2u);
}

TEST(FileReplacement, RefusesAReadOnlyFileInAWritableFolder) {
    if (::geteuid() == 0)
        GTEST_SKIP() << "root may write any file; adapter_tests.as_user runs this as nobody";
    ScratchDir dir;
    const std::string path = dir.file("locked.drm");
    writeText(path, "old");
    ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
    try {
        drm::vcgio::writeFileAtomically(path, kNewBytes);
        FAIL() << "a read-only file was replaced";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Io) << e.what();
        // The sentence the user reads (it says why, not only that it failed).
        const std::string message = e.what();
        EXPECT_NE(message.find("cannot write " + path + ": the file is read-only for you"), std::string::npos)
            << message;
    }
    EXPECT_EQ(readText(path), "old");
    EXPECT_EQ(modeOf(path), mode_t(0444));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"locked.drm"});
}

TEST(FileReplacement, RefusesAReadOnlyFileBehindALink) {
    if (::geteuid() == 0)
        GTEST_SKIP() << "root may write any file; adapter_tests.as_user runs this as nobody";
    ScratchDir dir;
    writeText(dir.file("locked.drm"), "old");
    ASSERT_EQ(::chmod(dir.file("locked.drm").c_str(), 0444), 0);
    ASSERT_EQ(::symlink("locked.drm", dir.file("link.drm").c_str()), 0);
    EXPECT_THROW(drm::vcgio::writeFileAtomically(dir.file("link.drm"), kNewBytes), drm::Error);
    EXPECT_EQ(readText(dir.file("locked.drm")), "old");
    EXPECT_TRUE(isLink(dir.file("link.drm")));
}

TEST(FileReplacement, AFailedWriteLeavesAPrivateFileAsItWas) {
    ScratchDir dir;
    const std::string path = dir.file("keep.drm");
    writeText(path, "old");
    ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
    EXPECT_THROW(drm::vcgio::writeFileAtomically(path, [](std::ostream&) { throw drm::Error("no output"); }),
                 drm::Error);
    EXPECT_EQ(readText(path), "old");
    EXPECT_EQ(modeOf(path), mode_t(0600));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.drm"});
}

TEST(FileReplacement, ReportsAFolderTheUserMayNotWrite) {
    if (::geteuid() == 0)
        GTEST_SKIP() << "root may write any folder; adapter_tests.as_user runs this as nobody";
    ScratchDir dir;
    ASSERT_EQ(::mkdir(dir.file("closed").c_str(), 0755), 0);
    writeText(dir.file("closed/mesh.drm"), "old");
    ASSERT_EQ(::chmod(dir.file("closed").c_str(), 0555), 0);  // the file stays writable, the folder not
    try {
        drm::vcgio::writeFileAtomically(dir.file("closed/mesh.drm"), kNewBytes);
        ADD_FAILURE() << "a file was written in a folder that refuses new files";
    } catch (const drm::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("cannot write " + dir.file("closed/mesh.drm") + ": the folder " + dir.file("closed") +
                               " does not let you create files in it (Permission denied)"),
                  std::string::npos)
            << message;
    }
    EXPECT_EQ(readText(dir.file("closed/mesh.drm")), "old");
    ASSERT_EQ(::chmod(dir.file("closed").c_str(), 0755), 0);  // so ScratchDir can remove it
}

// The OBJ's material library is a file the user did not name: a link in
// its place that leads out of the OBJ's folder is refused, and neither the
// link's target nor the OBJ is written; a link to a file beside it is
// written through, as a named file's link is.
TEST(FileReplacement, RefusesAMaterialLibraryLinkLeadingOutOfTheFolder) {
    ScratchDir dir;
    ASSERT_EQ(::mkdir(dir.file("out").c_str(), 0755), 0);
    writeText(dir.file("victim.txt"), "precious");
    ASSERT_EQ(::symlink(dir.file("victim.txt").c_str(), dir.file("out/mesh.mtl").c_str()), 0);
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh.triangles = {0, 1, 2};
    mesh.faceTexture = {0};
    mesh.textures = {"stone.png"};
    mesh.cornerTexCoords = {0, 0, 1, 0, 0, 1};
    try {
        drm::vcgio::saveObj(dir.file("out/mesh.obj"), mesh);
        ADD_FAILURE() << "the library was written through a link leading out of the folder";
    } catch (const drm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("outside the OBJ's folder"), std::string::npos) << e.what();
    }
    EXPECT_EQ(readText(dir.file("victim.txt")), "precious");
    EXPECT_FALSE(::access(dir.file("out/mesh.obj").c_str(), F_OK) == 0) << "the OBJ was written without its library";

    ASSERT_EQ(::unlink(dir.file("out/mesh.mtl").c_str()), 0);
    writeText(dir.file("out/library.mtl"), "old");
    ASSERT_EQ(::symlink("library.mtl", dir.file("out/mesh.mtl").c_str()), 0);
    drm::vcgio::saveObj(dir.file("out/mesh.obj"), mesh);
    EXPECT_TRUE(isLink(dir.file("out/mesh.mtl")));
    EXPECT_NE(readText(dir.file("out/library.mtl")).find("map_Kd stone.png"), std::string::npos);
}
