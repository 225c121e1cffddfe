// Views and the fitted orthographic projection (see camera.h).
#include "camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drm {
namespace render {

namespace {

struct NamedView {
    const char* name;
    View view;
};

const NamedView kViews[] = {
    {"front", View::Front}, {"back", View::Back},     {"left", View::Left}, {"right", View::Right},
    {"top", View::Top},     {"bottom", View::Bottom}, {"iso", View::Iso},
};

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// right = forward x up: a right-handed frame, so no view shows a mirror image.
Camera frameFrom(double fx, double fy, double fz, double ux, double uy, double uz) {
    Camera c{{0, 0, 0}, {ux, uy, uz}, {fx, fy, fz}};
    const double fLength = std::sqrt(dot(c.forward, c.forward));
    for (double& v : c.forward) v /= fLength;
    // Keep only the part of `up` across the viewing direction (the iso view's
    // up is Y tilted towards the screen).
    const double along = dot(c.up, c.forward);
    for (int k = 0; k < 3; ++k) c.up[k] -= along * c.forward[k];
    const double uLength = std::sqrt(dot(c.up, c.up));
    for (double& v : c.up) v /= uLength;
    c.right[0] = c.forward[1] * c.up[2] - c.forward[2] * c.up[1];
    c.right[1] = c.forward[2] * c.up[0] - c.forward[0] * c.up[2];
    c.right[2] = c.forward[0] * c.up[1] - c.forward[1] * c.up[0];
    return c;
}

}  // namespace

bool parseView(const std::string& name, View& view) {
    for (const NamedView& named : kViews)
        if (name == named.name) {
            view = named.view;
            return true;
        }
    return false;
}

const char* viewNames() { return "front|back|left|right|top|bottom|iso"; }

Camera cameraFor(View view) {
    switch (view) {
        case View::Front: return frameFrom(0, 0, -1, 0, 1, 0);
        case View::Back: return frameFrom(0, 0, 1, 0, 1, 0);
        case View::Left: return frameFrom(1, 0, 0, 0, 1, 0);    // from -X
        case View::Right: return frameFrom(-1, 0, 0, 0, 1, 0);  // from +X
        case View::Top: return frameFrom(0, -1, 0, 0, 0, -1);   // from +Y, the back of the model at the top
        case View::Bottom: return frameFrom(0, 1, 0, 0, 0, 1);  // from -Y, the front at the top
        case View::Iso: return frameFrom(-1, -1, -1, 0, 1, 0);  // from the +X, +Y, +Z corner
    }
    return frameFrom(0, 0, -1, 0, 1, 0);
}

ScreenPoint Projection::project(const float* position) const {
    const double p[3] = {position[0], position[1], position[2]};
    return {screenCentre[0] + scale * (dot(p, camera.right) - centre[0]),
            screenCentre[1] - scale * (dot(p, camera.up) - centre[1]),  // screen y grows downwards
            dot(p, camera.forward) - centreDepth};
}

Projection fitProjection(const std::vector<float>& positions, View view, const Rect& area, double margin) {
    Projection projection;
    projection.camera = cameraFor(view);
    const double inf = std::numeric_limits<double>::infinity();
    double low[3] = {inf, inf, inf}, high[3] = {-inf, -inf, -inf};
    for (size_t i = 0; i + 2 < positions.size(); i += 3) {
        const double p[3] = {positions[i], positions[i + 1], positions[i + 2]};
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        const double along[3] = {dot(p, projection.camera.right), dot(p, projection.camera.up),
                                 dot(p, projection.camera.forward)};
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], along[k]);
            high[k] = std::max(high[k], along[k]);
        }
    }
    projection.screenCentre[0] = area.x + area.width / 2;
    projection.screenCentre[1] = area.y + area.height / 2;
    if (!(low[0] <= high[0])) return projection;  // nothing finite to show
    projection.centre[0] = (low[0] + high[0]) / 2;
    projection.centre[1] = (low[1] + high[1]) / 2;
    projection.centreDepth = (low[2] + high[2]) / 2;
    const double free = 2 * margin * std::min(area.width, area.height);
    const double sx = (area.width - free) / (high[0] - low[0]);
    const double sy = (area.height - free) / (high[1] - low[1]);
    const double s = std::min(sx, sy);  // inf on a flat extent: the other axis decides
    projection.scale = (std::isfinite(s) && s > 0) ? s : 1;
    return projection;
}

}  // namespace render
}  // namespace drm
