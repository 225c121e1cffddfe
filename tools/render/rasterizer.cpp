// Triangle filling with edge functions and a z-buffer (see rasterizer.h).
#include "rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drm {
namespace render {

namespace {

// 8 bits of sub-pixel precision: fine enough that slivers keep their shape,
// small enough that edge functions of a 8192-pixel frame fit easily in 64 bits.
const int kSubpixelBits = 8;
const int64_t kOne = int64_t(1) << kSubpixelBits;
// Vertices further out than this are off any frame we make; clamping keeps
// the integer arithmetic in range (products stay below 2^62).
const double kFarPixels = 1 << 20;

struct FixedPoint {
    int64_t x, y;
};

FixedPoint snap(const ScreenPoint& p) {
    auto fixed = [](double v) { return int64_t(std::llround(std::max(-kFarPixels, std::min(kFarPixels, v)) * kOne)); };
    return {fixed(p.x), fixed(p.y)};
}

// Twice the signed area of (a, b, p); positive when p is to the right of
// a -> b on a y-down screen, i.e. inside a triangle whose area is positive.
int64_t edge(const FixedPoint& a, const FixedPoint& b, const FixedPoint& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The top-left rule: a centre exactly on an edge belongs to the triangle
// whose interior lies to the right of (dy < 0) or below (dy == 0, dx > 0)
// that edge. The neighbour across the edge walks it the other way round, so
// exactly one of the two owns the centre.
bool ownsItsEdge(const FixedPoint& a, const FixedPoint& b) {
    const int64_t dy = b.y - a.y, dx = b.x - a.x;
    return dy < 0 || (dy == 0 && dx > 0);
}

}  // namespace

Frame::Frame(int width, int height, uint32_t background)
    : width_(width),
      height_(height),
      pixels_(size_t(width) * size_t(height), background),
      depth_(size_t(width) * size_t(height), std::numeric_limits<float>::infinity()) {}

void Frame::fillTriangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c, uint32_t colour) {
    ScreenPoint corner[3] = {a, b, c};
    FixedPoint v[3] = {snap(a), snap(b), snap(c)};
    int64_t area = edge(v[0], v[1], v[2]);
    if (area == 0) return;
    if (area < 0) {  // a back face (or a front face seen from behind): same pixels, other winding
        std::swap(v[1], v[2]);
        std::swap(corner[1], corner[2]);
        area = -area;
    }

    // Pixels whose centres can be inside, clipped to the frame.
    const int64_t minX = std::min({v[0].x, v[1].x, v[2].x}), maxX = std::max({v[0].x, v[1].x, v[2].x});
    const int64_t minY = std::min({v[0].y, v[1].y, v[2].y}), maxY = std::max({v[0].y, v[1].y, v[2].y});
    // Centre of pixel i is (i + 1/2): i from ceil(min - 1/2) to floor(max - 1/2).
    auto firstPixel = [](int64_t lo) { return int64_t(std::ceil(double(lo - kOne / 2) / kOne)); };
    auto lastPixel = [](int64_t hi) { return int64_t(std::floor(double(hi - kOne / 2) / kOne)); };
    const int x0 = int(std::max<int64_t>(0, firstPixel(minX))), x1 = int(std::min<int64_t>(width_ - 1, lastPixel(maxX)));
    const int y0 = int(std::max<int64_t>(0, firstPixel(minY))), y1 = int(std::min<int64_t>(height_ - 1, lastPixel(maxY)));
    if (x0 > x1 || y0 > y1) return;

    // Edge i is opposite vertex i; its function is that vertex's barycentric
    // weight times `area`. Owned edges test >= 0, the others > 0 (>= 1).
    const FixedPoint* from[3] = {&v[1], &v[2], &v[0]};
    const FixedPoint* to[3] = {&v[2], &v[0], &v[1]};
    int64_t bias[3], stepX[3], stepY[3], rowStart[3];
    const FixedPoint start{int64_t(x0) * kOne + kOne / 2, int64_t(y0) * kOne + kOne / 2};
    for (int i = 0; i < 3; ++i) {
        bias[i] = ownsItsEdge(*from[i], *to[i]) ? 0 : -1;
        stepX[i] = -(to[i]->y - from[i]->y) * kOne;  // the function's change per pixel right...
        stepY[i] = (to[i]->x - from[i]->x) * kOne;   // ...and per pixel down
        rowStart[i] = edge(*from[i], *to[i], start);
    }
    const double inverseArea = 1.0 / double(area);
    for (int y = y0; y <= y1; ++y) {
        int64_t w[3] = {rowStart[0], rowStart[1], rowStart[2]};
        const size_t row = size_t(y) * size_t(width_);
        for (int x = x0; x <= x1; ++x) {
            if (w[0] + bias[0] >= 0 && w[1] + bias[1] >= 0 && w[2] + bias[2] >= 0) {
                const float depth = float(
                    (double(w[0]) * corner[0].depth + double(w[1]) * corner[1].depth + double(w[2]) * corner[2].depth) *
                    inverseArea);
                if (depth < depth_[row + size_t(x)]) {
                    depth_[row + size_t(x)] = depth;
                    pixels_[row + size_t(x)] = colour;
                }
            }
            for (int i = 0; i < 3; ++i) w[i] += stepX[i];
        }
        for (int i = 0; i < 3; ++i) rowStart[i] += stepY[i];
    }
}

}  // namespace render
}  // namespace drm
