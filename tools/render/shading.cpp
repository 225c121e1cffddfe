// Two-sided Lambert under a headlight (see shading.h).
#include "shading.h"

#include <cmath>

namespace drm {
namespace render {

Headlight::Headlight(const Camera& camera) {
    // Mostly from the viewer; the small tilt gives relief on flat-on faces.
    double length = 0;
    for (int k = 0; k < 3; ++k) {
        towardsLight_[k] = -camera.forward[k] + 0.35 * camera.up[k] - 0.25 * camera.right[k];
        length += towardsLight_[k] * towardsLight_[k];
    }
    for (double& v : towardsLight_) v /= std::sqrt(length);
}

Rgb Headlight::shade(const float* a, const float* b, const float* c, Rgb base) const {
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double diffuse = 0;
    if (length > 0 && std::isfinite(length))
        diffuse = std::fabs(n[0] * towardsLight_[0] + n[1] * towardsLight_[1] + n[2] * towardsLight_[2]) / length;
    const double light = kAmbient + (1 - kAmbient) * diffuse;
    auto scaled = [light](uint8_t channel) { return uint8_t(std::lround(channel * light)); };
    return {scaled(base.r), scaled(base.g), scaled(base.b)};
}

}  // namespace render
}  // namespace drm
