// Flat shading for `drm render`: one colour per face. Qt-free.
#ifndef DRM_TOOLS_RENDER_SHADING_H
#define DRM_TOOLS_RENDER_SHADING_H

#include "camera.h"

#include <cstdint>

namespace drm {
namespace render {

struct Rgb {
    uint8_t r, g, b;
};

// Lambert under a headlight: a light fixed to the camera, a little above
// and left of the viewing direction so that faces square to the view are
// not all equally bright. Two-sided (|cos|), because meshes may be open
// and their inside is as worth seeing as their outside. A little ambient
// light keeps faces seen edge-on from going black.
class Headlight {
public:
    explicit Headlight(const Camera& camera);

    // `base` scaled by the light a face with corners a, b, c receives.
    // A degenerate face (no normal) gets the ambient light only.
    Rgb shade(const float* a, const float* b, const float* c, Rgb base) const;

private:
    double towardsLight_[3];
};

const double kAmbient = 0.18;

inline uint32_t packedRgb(Rgb c) { return 0xff000000u | (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; }

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_SHADING_H
