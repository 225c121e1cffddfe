// `drm render`'s picture: a mesh, flat-shaded from one of seven views, with
// a title and an optional legend, as PNG bytes. The one header of the
// renderer the command sees; Qt stays behind it.
#ifndef DRM_TOOLS_RENDER_PICTURE_H
#define DRM_TOOLS_RENDER_PICTURE_H

#include "camera.h"
#include "shading.h"

#include <drmcodec/drmcodec.h>

#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace render {

struct LegendEntry {
    std::string label;
    Rgb colour;
    double share;  // of the faces, 0..1
};

struct Scene {
    const drm::Mesh* mesh = nullptr;
    // Unshaded colour of each face (one per face).
    std::vector<Rgb> faceColour;
    View view = View::Front;
    int width = 800, height = 600;
    std::string title;
    std::vector<LegendEntry> legend;  // none: no legend
};

const int kMinSide = 64;    // room for a title line and a legend
const int kMaxSide = 8192;  // about 0.8 GB of colour and depth buffers at most

// Renders the scene and encodes it as PNG. Throws drm::Error when the mesh
// has a face index out of range or a non-finite coordinate in a face, or
// when the PNG cannot be made.
std::vector<uint8_t> renderPng(const Scene& scene);

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_PICTURE_H
