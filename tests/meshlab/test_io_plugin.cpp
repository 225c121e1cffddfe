// The IO plugin's save and open, called as MeshLab's GUI calls them (a log,
// a progress callback that writes the status bar, a main window), without
// MeshLab running: what lands in the log and at which level, the status bar
// afterwards, error messages, and replacing files. meshlab_test.sh runs the
// same plugin inside meshlabserver.
//
// The read-only refusal needs a non-root user: ctest runs this binary again
// as nobody (io_plugin_tests.as_user); as root those tests skip, saying so.
#include "io_drm/io_drm.h"

#include "bridge/encode_parameters.h"

#include <drmcodec/drmcodec.h>
#include <drm_vcg/file_io.h>
#include <drm_vcg/vcg_mesh.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QMainWindow>
#include <QStatusBar>

#include <sys/stat.h>
#include <unistd.h>

#include "../adapters/scratch_dir.h"

namespace {

QApplication& application() {
    static int argc = 1;
    static char name[] = "io_plugin_tests";
    static char* argv[] = {name, nullptr};
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static QApplication app(argc, argv);
    return app;
}

drm::Mesh grid(int n) {
    drm::Mesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) mesh.positions.insert(mesh.positions.end(), {float(x), float(y), float((x * y) % 3)});
    auto at = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    return mesh;
}

// The status bar of the one main window, written by the progress callback
// as MeshLab's MainWindow::QCallBack does.
QMainWindow* g_window = nullptr;
int g_progressCalls = 0;
bool statusBarProgress(int /*percent*/, const char* text) {
    ++g_progressCalls;
    g_window->statusBar()->showMessage(text, 5000);
    return true;
}

struct Fixture {
    Fixture() : model(document.addNewMesh("", "grid")) {
        application();
        drm::vcgio::toVcg(grid(12), model->cm);
        // The normals MeshLab gives a mesh opened from a file without any.
        vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(model->cm);
        vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(model->cm);
        plugin.setLog(&log);
        plugin.initSaveParameter("DRM", *model, parameters);
    }
    MeshDocument document;
    MeshModel* model;
    GLLogStream log;
    DrmIOPlugin plugin;
    RichParameterList parameters;

    bool save(const std::string& path, vcg::CallBackPos* cb = nullptr, int mask = 0) {
        return plugin.save("DRM", QString::fromStdString(path), *model, mask, parameters, cb, nullptr);
    }
    // Log entries containing TEXT, with their level.
    std::vector<std::pair<int, std::string>> entries(const std::string& text) const {
        std::vector<std::pair<int, std::string>> found;
        for (const auto& entry : log.logStringList())
            if (entry.second.toStdString().find(text) != std::string::npos)
                found.emplace_back(entry.first, entry.second.toStdString());
        return found;
    }
};

mode_t modeOf(const std::string& path) {
    struct stat info;
    EXPECT_EQ(::stat(path.c_str(), &info), 0) << path;
    return info.st_mode & 07777;
}

}  // namespace

TEST(IoPlugin, SaveLogsTheSizeOfEveryPartAsInformation) {
    Fixture f;
    ScratchDir dir;
    ASSERT_TRUE(f.save(dir.file("grid.drm"))) << f.plugin.errorMsg().toStdString();
    const auto saved = f.entries("drm: saved grid.drm: ");
    ASSERT_EQ(saved.size(), 1u);
    EXPECT_EQ(saved[0].first, int(GLLogStream::FILTER));
    struct stat info;
    ASSERT_EQ(::stat(dir.file("grid.drm").c_str(), &info), 0);
    EXPECT_NE(saved[0].second.find(": " + std::to_string(info.st_size) + " bytes, "), std::string::npos)
        << saved[0].second;
    EXPECT_NE(saved[0].second.find(" bpv = header "), std::string::npos) << saved[0].second;
}

TEST(IoPlugin, ANoteAboutLostAttributesIsNotShownAsAWarning) {
    Fixture f;
    f.model->updateDataMask(MeshModel::MM_FACECOLOR);
    ScratchDir dir;
    ASSERT_TRUE(f.save(dir.file("grid.drm")));
    const auto notes = f.entries("drm: note: grid.drm does not keep the mesh's face colours");
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].first, int(GLLogStream::WARNING)) << "MeshLab shows WARNING entries in red, as errors";
    EXPECT_TRUE(f.entries("drm: note:").size() == 1u);
}

TEST(IoPlugin, NormalsMeshLabComputedAreLeftOutWithANote) {
    Fixture f;
    ScratchDir dir;
    ASSERT_TRUE(f.save(dir.file("grid.drm"), nullptr, vcg::tri::io::Mask::IOM_VERTNORMAL));
    EXPECT_EQ(f.entries("drm: note: grid.drm leaves out the vertex normals: they are the ones MeshLab computes").size(),
              1u);
    EXPECT_TRUE(f.entries("does not keep").empty()) << "computed normals are not lost data";
    EXPECT_TRUE(drm::decode(drm::vcgio::readFileBytes(dir.file("grid.drm"))).mesh.normals.empty());
}

TEST(IoPlugin, NormalsOfTheMeshsOwnAreKeptWhenTicked) {
    Fixture f;
    // One normal turned by about 1 degree: no longer the computed one.
    f.model->cm.vert[20].N() = (f.model->cm.vert[20].N().Normalize() + vcg::Point3f(0.02f, 0, 0)).Normalize();
    ScratchDir dir;
    ASSERT_TRUE(f.save(dir.file("own.drm"), nullptr, vcg::tri::io::Mask::IOM_VERTNORMAL));
    EXPECT_TRUE(f.entries("leaves out the vertex normals").empty());
    EXPECT_EQ(drm::decode(drm::vcgio::readFileBytes(dir.file("own.drm"))).mesh.normals.size(), 3u * 169u);
    ASSERT_TRUE(f.save(dir.file("unticked.drm")));
    EXPECT_EQ(f.entries("drm: note: unticked.drm does not keep the mesh's vertex normals (not ticked)").size(), 1u);
}

TEST(IoPlugin, SaveAndOpenLeaveTheStatusBarEmpty) {
    Fixture f;
    QMainWindow window;
    g_window = &window;
    g_progressCalls = 0;
    ScratchDir dir;
    ASSERT_TRUE(f.save(dir.file("grid.drm"), statusBarProgress));
    EXPECT_GT(g_progressCalls, 0) << "the codec's progress never reached the callback";
    EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty())
        << "left: " << window.statusBar()->currentMessage().toStdString();

    MeshDocument other;
    MeshModel* opened = other.addNewMesh("", "opened");
    int mask = 0;
    window.statusBar()->showMessage("reading", 5000);
    ASSERT_TRUE(f.plugin.open("DRM", QString::fromStdString(dir.file("grid.drm")), *opened, mask, RichParameterList(),
                              statusBarProgress, nullptr));
    EXPECT_EQ(opened->cm.fn, f.model->cm.fn);
    EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty());
    // A failed save clears it too.
    window.statusBar()->showMessage("ranking", 5000);
    EXPECT_FALSE(f.save(dir.file("no/such/folder/grid.drm"), statusBarProgress));
    EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty());
    g_window = nullptr;
}

TEST(IoPlugin, ABadOptionIsNamedByTheDialogsLabel) {
    Fixture f;
    f.parameters.setValue(drm_meshlab::kBitsParameter, IntValue(22));
    ScratchDir dir;
    EXPECT_FALSE(f.save(dir.file("grid.drm")));
    // MeshLab shows this text to the user: the text is the behaviour.
    EXPECT_NE(f.plugin.errorMsg().toStdString().find("Quantization bits must be between " +
                                                     std::to_string(drm::kMinQuantizationBits) + " and " +
                                                     std::to_string(drm::kMaxQuantizationBits) + ", not " +
                                                     std::to_string(drm::kMaxQuantizationBits + 1)),
              std::string::npos)
        << f.plugin.errorMsg().toStdString();
    EXPECT_EQ(dir.entries().size(), 0u);
}

TEST(IoPlugin, SaveKeepsTheModeAndWritesThroughALink) {
    Fixture f;
    ScratchDir dir;
    writeText(dir.file("target.drm"), "old");
    ASSERT_EQ(::chmod(dir.file("target.drm").c_str(), 0600), 0);
    ASSERT_EQ(::symlink("target.drm", dir.file("link.drm").c_str()), 0);
    ASSERT_TRUE(f.save(dir.file("link.drm"))) << f.plugin.errorMsg().toStdString();
    struct stat info;
    ASSERT_EQ(::lstat(dir.file("link.drm").c_str(), &info), 0);
    EXPECT_TRUE(S_ISLNK(info.st_mode));
    EXPECT_NE(readText(dir.file("target.drm")), "old");
    EXPECT_EQ(modeOf(dir.file("target.drm")), mode_t(0600));
}

TEST(IoPlugin, SaveRefusesAReadOnlyFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root may write any file; io_plugin_tests.as_user runs this as nobody";
    Fixture f;
    ScratchDir dir;
    writeText(dir.file("locked.drm"), "old");
    ASSERT_EQ(::chmod(dir.file("locked.drm").c_str(), 0444), 0);
    EXPECT_FALSE(f.save(dir.file("locked.drm")));
    EXPECT_NE(f.plugin.errorMsg().toStdString().find("cannot save locked.drm: cannot write "), std::string::npos)
        << f.plugin.errorMsg().toStdString();
    EXPECT_NE(f.plugin.errorMsg().toStdString().find("the file is read-only for you"), std::string::npos);
    EXPECT_EQ(readText(dir.file("locked.drm")), "old");
    EXPECT_EQ(modeOf(dir.file("locked.drm")), mode_t(0444));
}
