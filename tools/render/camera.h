// Where `drm render` looks from, and the orthographic projection that fits
// a mesh into the picture. Qt-free.
#ifndef DRM_TOOLS_RENDER_CAMERA_H
#define DRM_TOOLS_RENDER_CAMERA_H

#include <string>
#include <vector>

namespace drm {
namespace render {

enum class View { Front, Back, Left, Right, Top, Bottom, Iso };

// Parses "front", "back", "left", "right", "top", "bottom", "iso"; false
// for anything else.
bool parseView(const std::string& name, View& view);

// The accepted names, for messages: "front|back|left|right|top|bottom|iso".
const char* viewNames();

// An orthonormal camera frame in model coordinates. Y is up in every view
// but top and bottom (most scanned and modelled meshes stand on Y); `front`
// looks down -Z, as OpenGL's default camera and MeshLab's do.
struct Camera {
    double right[3];
    double up[3];
    double forward[3];  // the viewing direction, from the camera into the scene
};

Camera cameraFor(View view);

// A point on screen: x right and y down in pixels (pixel centres at .5),
// depth along the viewing direction (smaller is nearer).
struct ScreenPoint {
    double x, y, depth;
};

struct Rect {
    double x, y, width, height;
};

// World to screen, orthographic: the same scale on both axes.
struct Projection {
    Camera camera;
    double scale = 1;              // pixels per model unit
    double centre[2] = {0, 0};     // (right, up) coordinates shown at...
    double screenCentre[2] = {0, 0};  // ...this pixel position
    // Subtracted from depths, so that a mesh far from the origin keeps its
    // depth differences in a float depth buffer.
    double centreDepth = 0;

    ScreenPoint project(const float* position) const;
};

// The projection that shows every vertex inside `area`, with `margin`
// (a fraction of the area's smaller side) left free on each side, centred.
// Non-finite positions are ignored; a single point gets a unit scale.
Projection fitProjection(const std::vector<float>& positions, View view, const Rect& area, double margin);

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_CAMERA_H
