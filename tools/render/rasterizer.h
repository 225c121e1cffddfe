// Filling triangles into a colour buffer with a depth buffer: the software
// renderer behind `drm render`. Qt-free.
//
// Coverage is exact for the pixel centres: vertices are snapped to 1/256
// pixel, edge functions are evaluated in integers, and a pixel centre lying
// exactly on an edge goes to one triangle only (the top-left rule), so
// triangles sharing an edge leave no cracks and paint no pixel twice.
#ifndef DRM_TOOLS_RENDER_RASTERIZER_H
#define DRM_TOOLS_RENDER_RASTERIZER_H

#include "camera.h"

#include <cstdint>
#include <vector>

namespace drm {
namespace render {

// Row-major pixels, 0xAARRGGBB (what QImage::Format_RGB32 holds), and the
// depth of what each pixel shows.
class Frame {
public:
    Frame(int width, int height, uint32_t background);

    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<uint32_t>& pixels() const { return pixels_; }

    // Paints the pixels whose centres the triangle covers and where it is
    // nearer than what is there. Either winding: back faces are drawn too.
    // Points outside the frame are clipped; degenerate triangles draw nothing.
    void fillTriangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c, uint32_t colour);

private:
    int width_, height_;
    std::vector<uint32_t> pixels_;
    std::vector<float> depth_;  // float: half the memory, ample for ordering faces
};

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_RASTERIZER_H
