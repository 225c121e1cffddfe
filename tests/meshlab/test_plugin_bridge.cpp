// The plugins' shared layer without MeshLab running: the sentences and HTML
// they log, the progress labels, the status bar, the dialog's parameters.
// (meshlab_test.sh runs the plugins inside the real MeshLab.)
#include "bridge/computed_normals.h"
#include "bridge/encode_parameters.h"
#include "bridge/encoding.h"
#include "bridge/host.h"
#include "bridge/log_text.h"
#include "bridge/progress_bridge.h"

#include <drmcodec/drmcodec.h>
#include <drm_vcg/rank_palette.h>
#include <drm_vcg/vcg_mesh.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QMainWindow>
#include <QStatusBar>

#include <limits>
#include <string>
#include <vector>

namespace {

// An n x n grid of quads (two triangles each), plus a fin: a third face on
// one inner edge, which the codec must cut apart (a repair).
drm::Mesh gridWithFin(int n) {
    drm::Mesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            mesh.positions.push_back(float(x));
            mesh.positions.push_back(float(y));
            mesh.positions.push_back(float((x * 7 + y * 3) % 5) * 0.1f);
        }
    auto at = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
            mesh.triangles.insert(mesh.triangles.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    const uint32_t apex = uint32_t(mesh.positions.size() / 3);
    mesh.positions.insert(mesh.positions.end(), {1.5f, 1.5f, 3.0f});
    mesh.triangles.insert(mesh.triangles.end(), {at(1, 1), at(2, 2), apex});
    return mesh;
}

uint64_t sumOfParts(const drm::Stats& stats) {
    uint64_t sum = 0;
    for (const drm_meshlab::SizePart& part : drm_meshlab::sizeParts(stats)) sum += part.bytes;
    return sum;
}

QApplication& application() {
    static int argc = 1;
    static char name[] = "plugin_bridge_tests";
    static char* argv[] = {name, nullptr};
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static QApplication app(argc, argv);
    return app;
}

}  // namespace

TEST(SaveLog, PartsAddUpToTheFileWithVertexOrderAndRepairs) {
    drm::EncodeOptions options;
    options.keepVertexOrder = true;
    const drm::Encoded encoded = drm::encode(gridWithFin(20), options);
    const drm::Stats& stats = encoded.stats;
    ASSERT_GT(stats.vertexOrderBytes, 0u);
    ASSERT_GT(stats.repairBytes, 0u);
    EXPECT_EQ(sumOfParts(stats), stats.totalBytes);
    EXPECT_EQ(stats.totalBytes, encoded.bytes.size());
    const std::string summary = drm_meshlab::statsSummary(stats);
    for (const char* part : {"header ", "connectivity ", "geometry ", "vertex order ", "repairs "})
        EXPECT_NE(summary.find(std::string(" ") + part), std::string::npos) << part << " missing: " << summary;
    EXPECT_NE(summary.find(std::to_string(stats.totalBytes) + " bytes, " +
                           drm_meshlab::twoDecimals(stats.totalBitsPerVertex()) + " bpv = header "),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("vertex order " + std::to_string(stats.vertexOrderBytes) + " B ("), std::string::npos)
        << summary;
}

TEST(SaveLog, ATopologicalFileNamesItsCoderNotAPredictor) {
    drm::EncodeOptions options;
    options.connectivity = drm::ConnectivityCoder::Topological;
    const std::string topological = drm_meshlab::statsSummary(drm::encode(gridWithFin(20), options).stats);
    EXPECT_NE(topological.find(" bits, topological connectivity: "), std::string::npos) << topological;
    EXPECT_EQ(topological.find("predictor"), std::string::npos) << topological;
    options.connectivity = drm::ConnectivityCoder::Ranks;
    const std::string ranks = drm_meshlab::statsSummary(drm::encode(gridWithFin(20), options).stats);
    EXPECT_NE(ranks.find(" predictor: "), std::string::npos) << ranks;
}

TEST(SaveLog, APlainMeshListsOnlyItsParts) {
    drm::Mesh mesh = gridWithFin(12);
    mesh.triangles.resize(mesh.triangles.size() - 3);
    mesh.positions.resize(mesh.positions.size() - 3);
    const drm::Stats stats = drm::encode(mesh).stats;
    EXPECT_EQ(sumOfParts(stats), stats.totalBytes);
    const std::string summary = drm_meshlab::statsSummary(stats);
    EXPECT_EQ(summary.find("vertex order"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("repairs"), std::string::npos) << summary;
}

TEST(SaveLog, AttributeSectionsAreParts) {
    drm::Stats stats;
    stats.vertices = 100;
    stats.headerBytes = 30;
    stats.connectivityBytes = 10;
    stats.geometryBytes = 150;
    stats.attributeSizes = {{"colours", 40}, {"normals", 70}};
    stats.attributeBytes = 116;
    stats.totalBytes = 30 + 10 + 150 + 116;
    EXPECT_EQ(sumOfParts(stats), stats.totalBytes);
    const std::string text = drm_meshlab::sizeBreakdown(stats);
    EXPECT_NE(text.find("colours 40 B (3.20)"), std::string::npos) << text;
    EXPECT_NE(text.find("normals 70 B (5.60)"), std::string::npos) << text;
}

TEST(RankPalette, FilterHelpAndLegendUseThePalettesColours) {
    const std::string help = drm_meshlab::rankFilterHelpHtml();
    const std::vector<uint64_t> faces = {2, 950, 30, 10, 8};
    const std::string legend = drm_meshlab::rankLegendHtml(faces);
    std::string text;
    for (const std::string& line : drm_meshlab::rankLegendText(faces)) text += line + "\n";
    for (int bucket = 0; bucket < drm::vcgio::kRankBucketCount; ++bucket) {
        const std::string hex = drm::vcgio::rankBucketHex(bucket);
        EXPECT_NE(help.find("background-color:" + hex), std::string::npos) << hex << " no swatch in the help";
        EXPECT_NE(help.find(drm::vcgio::rankBucketColourName(bucket)), std::string::npos);
        EXPECT_NE(legend.find("background-color:" + hex), std::string::npos) << hex << " no swatch";
        EXPECT_NE(text.find(hex), std::string::npos) << hex << " not in the text legend";
    }
    const drm::vcgio::RankColour rank1 = drm::vcgio::rankColour(1);
    EXPECT_EQ(drm::vcgio::rankBucketHex(1), "#b4c0ce");
    EXPECT_EQ(rank1.r, 0xb4);
    EXPECT_EQ(help.find("#8c9aae"), std::string::npos);
}

TEST(RankPalette, HtmlLegendKeepsItsColumnsInAPaneThatCollapsesSpaces) {
    const std::string legend = drm_meshlab::rankLegendHtml({2, 950, 30, 10, 8});
    EXPECT_EQ(legend.find("  "), std::string::npos) << "runs of spaces collapse in the log pane";
    EXPECT_EQ(legend.find("<table"), std::string::npos) << "the log pane (QPlainTextEdit) lays out no tables";
    EXPECT_NE(legend.find("1000 faces"), std::string::npos);
    EXPECT_NE(legend.find("rank&nbsp;1&nbsp;"), std::string::npos) << "a label may break across lines: " << legend;
    EXPECT_NE(legend.find("95.00%"), std::string::npos);
    // One line per colour after the heading.
    size_t breaks = 0;
    for (size_t at = legend.find("<br>"); at != std::string::npos; at = legend.find("<br>", at + 1)) ++breaks;
    EXPECT_EQ(breaks, size_t(drm::vcgio::kRankBucketCount));
}

namespace {
std::vector<std::pair<int, std::string>> g_calls;
bool recordCall(int pos, const char* text) {
    g_calls.emplace_back(pos, text);
    return true;
}
}  // namespace

TEST(Progress, MeshlabserverGetsEachStageOnceOnALineOfItsOwn) {
    g_calls.clear();
    const drm::Progress progress = drm_meshlab::progressTo(recordCall, drm_meshlab::ProgressStyle::Lines);
    for (const char* stage : {"checking mesh", "checking mesh", "coding vertices", "ranking", "ranking"})
        progress(0.5, stage);
    ASSERT_EQ(g_calls.size(), 3u);
    EXPECT_EQ(g_calls[0].second, "drm: checking mesh\n");
    EXPECT_EQ(g_calls[1].second, "drm: coding vertices\n");
    EXPECT_EQ(g_calls[2].second, "drm: ranking\n");
    // meshlabserver drops a call repeating the last position.
    EXPECT_NE(g_calls[0].first, g_calls[1].first);
    EXPECT_NE(g_calls[1].first, g_calls[2].first);
}

TEST(Progress, StagesThatComeBackAreShownOnce) {
    g_calls.clear();
    // The encoder's attempts (both predictors) go through stages again.
    const drm::Progress progress = drm_meshlab::progressTo(recordCall, drm_meshlab::ProgressStyle::Lines);
    for (const char* stage : {"predictor", "ranking", "writing", "predictor", "ranking", "writing"})
        progress(0.5, stage);
    ASSERT_EQ(g_calls.size(), 3u);
    EXPECT_EQ(g_calls[2].second, "drm: writing\n");
}

TEST(Progress, TheGuiGetsPercentagesAndBareLabels) {
    g_calls.clear();
    const drm::Progress progress = drm_meshlab::progressTo(recordCall, drm_meshlab::ProgressStyle::StatusBar);
    progress(0.0, "checking mesh");
    progress(0.001, "checking mesh");
    progress(0.5, "ranking");
    ASSERT_EQ(g_calls.size(), 2u);
    EXPECT_EQ(g_calls[1], std::make_pair(50, std::string("ranking")));
}

TEST(Host, ClearStatusBarEmptiesTheMainWindowsStatusBar) {
    application();
    QMainWindow window;
    window.statusBar()->showMessage("ranking", 5000);
    ASSERT_EQ(window.statusBar()->currentMessage(), QString("ranking"));
    drm_meshlab::clearStatusBar();
    EXPECT_TRUE(window.statusBar()->currentMessage().isEmpty());
    EXPECT_FALSE(drm_meshlab::inMeshlabserver());
}

TEST(ExportDialog, VerifyIsOffByDefaultAndReachesTheEncoder) {
    RichParameterList parameters;
    drm_meshlab::addVerify(parameters);
    EXPECT_FALSE(drm_meshlab::encodeOptionsFrom(parameters).verify);
    parameters.setValue(drm_meshlab::kVerifyParameter, BoolValue(true));
    EXPECT_TRUE(drm_meshlab::encodeOptionsFrom(parameters).verify);
}

TEST(ExportDialog, HelpIsShortAndErrorsUseTheLabels) {
    RichParameterList parameters;
    drm_meshlab::addQuantizationAndPredictor(parameters);
    drm_meshlab::addKeepVertexOrder(parameters);
    drm_meshlab::addVerify(parameters);
    for (const RichParameter& p : parameters) {
        // The save dialog shows the help in a column about 45 characters
        // wide and cuts it after two lines.
        EXPECT_LE(p.toolTip().size(), 90) << p.name().toStdString() << ": " << p.toolTip().toStdString();
        EXPECT_GT(p.toolTip().size(), 20);
    }
    EXPECT_EQ(parameters.getParameterByName(drm_meshlab::kKeepVertexOrderParameter).toolTip().indexOf("a few"), -1);
    parameters.setValue(drm_meshlab::kBitsParameter, IntValue(0));
    try {
        drm_meshlab::encodeOptionsFrom(parameters);
        FAIL() << "0 bits accepted";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput);
        // The sentence MeshLab shows, naming the dialog's label and drmcodec.h's range.
        EXPECT_EQ(std::string(e.what()), "Quantization bits must be between " + std::to_string(drm::kMinQuantizationBits) +
                                             " and " + std::to_string(drm::kMaxQuantizationBits) + ", not 0");
    }
}

namespace {

// A cube of 24 vertices, four per side (as a file with a normal per side
// stores it), with the normals MeshLab computes when it opens it.
void makeSidedCube(CMeshO& cm) {
    drm::Mesh mesh;
    const int sides[6][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                                {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
                                {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
    for (int side = 0; side < 6; ++side) {
        for (int k = 0; k < 4; ++k)
            for (int axis = 0; axis < 3; ++axis) mesh.positions.push_back(float(sides[side][k][axis]));
        const uint32_t first = uint32_t(4 * side);
        mesh.triangles.insert(mesh.triangles.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    drm::vcgio::toVcg(mesh, cm);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(cm);
}

}  // namespace

TEST(ComputedNormals, MeshLabsOwnNormalsAreRecognised) {
    CMeshO cm;
    makeSidedCube(cm);
    EXPECT_TRUE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
    // Welded into 8 corners, each vertex would get the mean of three sides:
    // the sides' normals are then the file's own.
    EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, drm_meshlab::gridStep(cm, 12)));
}

TEST(ComputedNormals, ATurnedNormalIsTheMeshsOwn) {
    const double turn = 2 * drm_meshlab::kComputedNormalTolerance;
    {
        CMeshO cm;
        makeSidedCube(cm);
        cm.vert[5].N() = (cm.vert[5].N().Normalize() + vcg::Point3f(float(turn), 0, 0)).Normalize();
        EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
    }
    {
        CMeshO cm;
        makeSidedCube(cm);
        cm.vert[5].N() = (cm.vert[5].N().Normalize() + vcg::Point3f(float(turn / 4), 0, 0)).Normalize();
        EXPECT_TRUE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0)) << "within the tolerance";
    }
    {
        CMeshO cm;
        makeSidedCube(cm);
        cm.vert[5].N() = vcg::Point3f(0, 0, 0);
        EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
    }
}

TEST(ComputedNormals, PositionsTheGridMayMergeKeepTheNormals) {
    CMeshO cm;
    makeSidedCube(cm);
    const double step = drm_meshlab::gridStep(cm, 12);
    EXPECT_NEAR(step, 1.0 / 4095, 1e-12);
    // Corners of two sides moved apart by less than a step: one grid point,
    // so the file may make them one vertex (and MeshLab one normal).
    const float nudge = float(step / 4);
    for (CVertexO& v : cm.vert)
        if (v.P() == vcg::Point3f(1, 1, 1)) {
            v.P()[0] -= nudge;
            break;
        }
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(cm);
    EXPECT_TRUE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
    EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, step));
}

TEST(ComputedNormals, ANonFinitePositionKeepsTheNormals) {
    CMeshO cm;
    makeSidedCube(cm);
    cm.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
}

TEST(ComputedNormals, APointCloudsNormalsAreItsOwn) {
    CMeshO cm;
    makeSidedCube(cm);
    for (CFaceO& f : cm.face) vcg::tri::Allocator<CMeshO>::DeleteFace(cm, f);
    EXPECT_FALSE(drm_meshlab::normalsAreComputedFromFaces(cm, 0.0));
}
