// Rasterize, annotate, encode (see picture.h).
#include "picture.h"

#include "legend.h"
#include "rasterizer.h"

#include <QBuffer>
#include <QByteArray>
#include <QGuiApplication>
#include <QImage>

#include <cmath>
#include <memory>

namespace drm {
namespace render {

namespace {

const uint32_t kBackground = 0xffffffffu;  // white, as a figure in a paper
const double kMargin = 0.04;               // of the mesh area's smaller side

// QPainter needs fonts for the title and the legend, and Qt serves fonts only
// while a QGuiApplication exists. The "offscreen" platform needs no display,
// so `drm render` works on a server or in CI. Qt's own warnings are
// dropped while it lives: the command's stderr is drm's alone (one error
// line on failure), and nothing Qt might say here changes the picture.
class OffscreenGui {
public:
    OffscreenGui() {
        if (QCoreApplication::instance()) return;  // someone else's: use it as it is
        previousHandler_ = qInstallMessageHandler(quiet);
        app_.reset(new QGuiApplication(argc_, argv_));
    }
    ~OffscreenGui() {
        if (!app_) return;
        app_.reset();
        qInstallMessageHandler(previousHandler_);
    }
    OffscreenGui(const OffscreenGui&) = delete;
    OffscreenGui& operator=(const OffscreenGui&) = delete;

private:
    static void quiet(QtMsgType, const QMessageLogContext&, const QString&) {}

    char program_[4] = "drm";
    char option_[10] = "-platform";
    char platform_[10] = "offscreen";
    char* argv_[4] = {program_, option_, platform_, nullptr};
    int argc_ = 3;  // QGuiApplication keeps a reference: it must outlive the app
    QtMessageHandler previousHandler_ = nullptr;
    std::unique_ptr<QGuiApplication> app_;
};

void checkMesh(const drm::Mesh& mesh) {
    const size_t vertices = mesh.vertexCount();
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[3 * f + size_t(k)];
            if (v >= vertices)
                throw drm::Error(drm::ErrorKind::InvalidInput, "face " + std::to_string(f) + " uses vertex " + std::to_string(v) + ", but there are only " +
                                 std::to_string(vertices) + " vertices");
            const float* p = &mesh.positions[3 * size_t(v)];
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                throw drm::Error(drm::ErrorKind::InvalidInput, "vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
        }
}

void drawMesh(const Scene& scene, const QRect& area, Frame& frame) {
    const drm::Mesh& mesh = *scene.mesh;
    const Projection projection = fitProjection(
        mesh.positions, scene.view, Rect{double(area.x()), double(area.y()), double(area.width()), double(area.height())},
        kMargin);
    std::vector<ScreenPoint> screen(mesh.vertexCount());
    for (size_t v = 0; v < screen.size(); ++v) screen[v] = projection.project(&mesh.positions[3 * v]);
    const Headlight light(projection.camera);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* corner = &mesh.triangles[3 * f];
        const Rgb colour = light.shade(&mesh.positions[3 * size_t(corner[0])], &mesh.positions[3 * size_t(corner[1])],
                                       &mesh.positions[3 * size_t(corner[2])], scene.faceColour[f]);
        frame.fillTriangle(screen[corner[0]], screen[corner[1]], screen[corner[2]], packedRgb(colour));
    }
}

}  // namespace

std::vector<uint8_t> renderPng(const Scene& scene) {
    if (!scene.mesh || scene.faceColour.size() != scene.mesh->faceCount())
        throw drm::Error(drm::ErrorKind::Internal, "internal error: one colour per face is needed to render");
    if (scene.width < kMinSide || scene.height < kMinSide || scene.width > kMaxSide || scene.height > kMaxSide)
        throw drm::Error(drm::ErrorKind::InvalidInput, "picture size " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                         " is out of range");
    checkMesh(*scene.mesh);

    OffscreenGui gui;
    const Annotations annotations(scene.width, scene.height, scene.title, scene.legend);
    Frame frame(scene.width, scene.height, kBackground);
    drawMesh(scene, annotations.meshArea(), frame);

    QImage image(scene.width, scene.height, QImage::Format_RGB32);
    for (int y = 0; y < scene.height; ++y)
        std::copy(frame.pixels().begin() + ptrdiff_t(y) * scene.width,
                  frame.pixels().begin() + ptrdiff_t(y + 1) * scene.width, reinterpret_cast<uint32_t*>(image.scanLine(y)));
    annotations.draw(image);

    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    // Quality 0 asks Qt's PNG writer for its strongest compression: the
    // pictures go into the repository.
    if (!image.save(&buffer, "PNG", 0)) throw drm::Error(drm::ErrorKind::InvalidInput, "Qt could not encode the picture as PNG");
    return std::vector<uint8_t>(png.begin(), png.end());
}

}  // namespace render
}  // namespace drm
