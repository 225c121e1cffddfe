// The rank filter called as MeshLab's GUI calls it, without MeshLab running:
// the log pane gets the HTML legend with the palette's swatches, the help
// names the palette's colours, the status bar is empty afterwards, and a bad
// value is named by its label. (meshlab_test.sh runs the filter inside
// meshlabserver, where the legend is plain text.)
#include "filter_drm/filter_drm.h"

#include "bridge/encode_parameters.h"

#include <drmcodec/drmcodec.h>
#include <drm_vcg/rank_palette.h>
#include <drm_vcg/vcg_mesh.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QMainWindow>
#include <QStatusBar>

namespace {

QApplication& application() {
    static int argc = 1;
    static char name[] = "filter_plugin_tests";
    static char* argv[] = {name, nullptr};
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static QApplication app(argc, argv);
    return app;
}

// A bumpy grid: enough irregularity for ranks above 1.
drm::Mesh bumpyGrid(int n) {
    drm::Mesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            mesh.positions.insert(mesh.positions.end(),
                                  {float(x) + 0.3f * float((x * 7 + y * 13) % 5) / 5.0f, float(y),
                                   float((x * 31 + y * 17) % 7) * 0.2f});
    auto at = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    return mesh;
}

QMainWindow* g_window = nullptr;
bool statusBarProgress(int /*percent*/, const char* text) {
    if (g_window != nullptr) g_window->statusBar()->showMessage(text, 5000);
    return true;
}

struct Fixture {
    Fixture() : model(document.addNewMesh("", "bumpy")) {
        application();
        drm::vcgio::toVcg(bumpyGrid(16), model->cm);
        model->updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
        plugin.setLog(&log);
        action = plugin.actions().at(0);
        plugin.initParameterSet(action, *model, parameters);
    }
    MeshDocument document;
    MeshModel* model;
    GLLogStream log;
    DrmFilterPlugin plugin;
    QAction* action = nullptr;
    RichParameterList parameters;

    std::string allLog() const {
        std::string text;
        for (const auto& entry : log.logStringList()) text += entry.second.toStdString() + "\n";
        return text;
    }
};

}  // namespace

TEST(FilterPlugin, TheGuiLogGetsALegendWithThePalettesSwatches) {
    Fixture f;
    ASSERT_TRUE(f.plugin.applyFilter(f.action, f.document, f.parameters, nullptr)) << f.plugin.errorMsg().toStdString();
    const std::string log = f.allLog();
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket)
        EXPECT_NE(log.find("background-color:" + drm::vcgio::rankBucketHex(bucket)), std::string::npos)
            << "no swatch for " << drm::vcgio::rankBucketName(bucket) << " in:\n" << log;
    EXPECT_NE(log.find("Faces per colour</b> (" + std::to_string(f.model->cm.fn) + " faces)"), std::string::npos) << log;
    EXPECT_NE(log.find("Rank codes (0 = boundary edge): "), std::string::npos);
    // The pane collapses runs of spaces: the GUI's lines must not rely on them.
    for (const auto& entry : f.log.logStringList())
        if (entry.second.contains("Faces per colour"))
            EXPECT_FALSE(entry.second.contains("  ")) << entry.second.toStdString();
}

TEST(FilterPlugin, HelpNamesThePalettesColours) {
    Fixture f;
    const std::string help = f.plugin.filterInfo(DrmFilterPlugin::FP_RANK_COLOURS).toStdString();
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket)
        EXPECT_NE(help.find(drm::vcgio::rankBucketHex(bucket)), std::string::npos) << help;
}

TEST(FilterPlugin, LeavesTheStatusBarEmpty) {
    Fixture f;
    QMainWindow window;
    g_window = &window;
    ASSERT_TRUE(f.plugin.applyFilter(f.action, f.document, f.parameters, statusBarProgress));
    EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty())
        << "left: " << window.statusBar()->currentMessage().toStdString();
    g_window = nullptr;
}

TEST(FilterPlugin, ABadValueIsNamedByItsLabel) {
    Fixture f;
    f.parameters.setValue(drm_meshlab::kBitsParameter, IntValue(0));
    EXPECT_FALSE(f.plugin.applyFilter(f.action, f.document, f.parameters, nullptr));
    // MeshLab shows this text to the user: the text is the behaviour.
    EXPECT_NE(f.plugin.errorMsg().toStdString().find("Quantization bits must be between " +
                                                     std::to_string(drm::kMinQuantizationBits) + " and " +
                                                     std::to_string(drm::kMaxQuantizationBits) + ", not 0"),
              std::string::npos)
        << f.plugin.errorMsg().toStdString();
}
