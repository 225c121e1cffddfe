// An exact integer rotation of grid vectors into a local frame whose third
// axis is a surface normal: the vertex coder codes the residual from the
// parent (the whole tree edge) in it, where the edge's component along the
// normal is small and the two in the tangent plane carry its length.
//
// A rotation of integer vectors is made exactly invertible by writing each
// plane rotation as three shears (lifting steps), each rounded to an
// integer: x += round(a y), y += round(b x), x += round(a y), with
// a = -tan(theta / 2) and b = sin(theta). The inverse undoes the steps in
// reverse order with the same rounded terms, so every integer vector comes
// back exactly whatever the rounding did. Everything is integer arithmetic
// (the slopes are 16-bit fixed point), the same on every machine.
//
// A normal fixes the third axis only; the first two may also be turned
// about it (alignFirstAxis) so that the first points along a direction the
// coder knows, the way the surface was last walked.
#ifndef DRM_LOCAL_FRAME_H
#define DRM_LOCAL_FRAME_H

#include <algorithm>
#include <cstdint>

#include "common.h"

namespace drm {

class LocalFrame {
public:
    // The identity: no normal known.
    LocalFrame() = default;

    // The frame that turns `normal` onto the third axis (any length; the
    // zero vector gives the identity). Components must stay below 2^62 in
    // magnitude.
    explicit LocalFrame(int64_t nx, int64_t ny, int64_t nz) {
        // Bring the direction to 19-20 bits: squares and slopes then fit in
        // 64, and the integer lengths below are exact to 2^-19 (a short
        // normal like (3, 7, 6) would turn several degrees off).
        if (nx == 0 && ny == 0 && nz == 0) return;
        hasNormal_ = true;
        // The loops below halve or double one step at a time; most of the
        // way is taken first in one shift, which the loops then finish
        // exactly as they would alone: fewer halvings than the largest
        // component's excess bit length never bring it below the limit
        // (floor(v / 2^k) is k halvings), and doubling the largest component
        // 20 - its bit length times brings it to 2^19 or over, one less not.
        shiftToNormalBits(nx, ny, nz);
        while (magnitude(nx) >= kNormalLimit || magnitude(ny) >= kNormalLimit || magnitude(nz) >= kNormalLimit) {
            nx = halve(nx);
            ny = halve(ny);
            nz = halve(nz);
        }
        while (magnitude(nx) < kNormalLimit / 2 && magnitude(ny) < kNormalLimit / 2 && magnitude(nz) < kNormalLimit / 2) {
            nx *= 2;
            ny *= 2;
            nz *= 2;
        }
        // First about the third axis: (nx, ny) onto the first axis. Then in
        // the plane of the third and first axes: (nz, |(nx, ny)|) onto the
        // third.
        azimuth_ = PlaneRotation(nx, ny);
        polar_ = PlaneRotation(nz, int64_t(integerSqrt(uint64_t(nx * nx + ny * ny))));
    }

    // Turns the frame about its normal so that the part of `d` in the
    // tangent plane lies along the first axis, pointing its way: d, scaled
    // so that its largest component's bit length is 20 (shifted up, or
    // floor-shifted down, all components alike: a negative one may then
    // reach -2^20), is turned into the frame, and a third plane rotation
    // turns its first two components onto the first axis.
    // Nothing changes in the identity frame (no normal), nor for a d along
    // the normal or zero. Components of d must stay below 2^62.
    void alignFirstAxis(int64_t dx, int64_t dy, int64_t dz) {
        if (!hasNormal_ || (dx == 0 && dy == 0 && dz == 0)) return;
        shiftToNormalBits(dx, dy, dz);
        int64_t v[3] = {dx, dy, dz};
        azimuth_.forward(v[0], v[1]);
        polar_.forward(v[2], v[0]);
        tangent_ = PlaneRotation(v[0], v[1]);
    }

    // World -> frame, and back. Vector components must stay below 2^40 in
    // magnitude (residuals of 21-bit coordinates are below 2^23).
    void toFrame(int64_t v[3]) const {
        azimuth_.forward(v[0], v[1]);
        polar_.forward(v[2], v[0]);
        tangent_.forward(v[0], v[1]);
    }
    void fromFrame(int64_t v[3]) const {
        tangent_.inverse(v[0], v[1]);
        polar_.inverse(v[2], v[0]);
        azimuth_.inverse(v[0], v[1]);
    }

private:
    static constexpr int kNormalBits = 20;
    static constexpr int64_t kNormalLimit = int64_t(1) << kNormalBits;
    static constexpr int kFractionBits = 16;
    static uint64_t magnitude(int64_t v) { return v < 0 ? uint64_t(-v) : uint64_t(v); }
    static int64_t halve(int64_t v) { return v >= 0 ? v / 2 : -((-v + 1) / 2); }  // floor(v / 2)
    // Shifts a non-zero vector, all components alike, so that its largest
    // component's bit length is kNormalBits: multiplied by a power of two,
    // or floor-divided by one (a negative component may then reach
    // -2^kNormalBits).
    static void shiftToNormalBits(int64_t& x, int64_t& y, int64_t& z) {
        const int length = bitLength(std::max(magnitude(x), std::max(magnitude(y), magnitude(z))));
        if (length > kNormalBits) {
            const int k = length - kNormalBits;
            x = floorShift(x, k);
            y = floorShift(y, k);
            z = floorShift(z, k);
        } else if (length < kNormalBits) {
            const int64_t scale = int64_t(1) << (kNormalBits - length);
            x *= scale;
            y *= scale;
            z *= scale;
        }
    }
    // floor(v / 2^k), for 0 <= k < 63 and |v| below 2^62.
    static int64_t floorShift(int64_t v, int k) {
        return v >= 0 ? v >> k : -((-v + (int64_t(1) << k) - 1) >> k);
    }
    // round(v / 2^16), halves up, for either sign.
    static int64_t roundFixed(int64_t v) {
        const int64_t biased = v + (int64_t(1) << (kFractionBits - 1));
        return biased >= 0 ? biased >> kFractionBits : -((-biased + (int64_t(1) << kFractionBits) - 1) >> kFractionBits);
    }
    // Exact quotient rounded to nearest, for den > 0.
    static int64_t divideRounded(int64_t num, int64_t den) {
        return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
    }

    // The rotation of a plane that turns the direction (du, dv) onto the
    // first axis. Angles beyond a quarter turn first turn half way round
    // (negating both coordinates, exact), so the slopes stay within one.
    struct PlaneRotation {
        bool half = false;
        int64_t a = 0, b = 0;  // slopes of the shears, 16-bit fixed point

        PlaneRotation() = default;
        PlaneRotation(int64_t du, int64_t dv) {
            if (du < 0) {
                half = true;
                du = -du;
                dv = -dv;
            }
            const int64_t length = int64_t(integerSqrt(uint64_t(du * du + dv * dv)));
            if (dv == 0 || length == 0) return;  // already on the axis
            // Rotating by -theta, where (du, dv) = length (cos theta, sin theta):
            // a = tan(theta / 2) = dv / (length + du), b = -sin(theta).
            const int64_t scaled = dv * (int64_t(1) << kFractionBits);  // not dv << 16: dv may be negative
            a = divideRounded(scaled, length + du);
            b = -divideRounded(scaled, length);
        }
        void forward(int64_t& u, int64_t& v) const {
            if (half) {
                u = -u;
                v = -v;
            }
            u += roundFixed(a * v);
            v += roundFixed(b * u);
            u += roundFixed(a * v);
        }
        void inverse(int64_t& u, int64_t& v) const {
            u -= roundFixed(a * v);
            v -= roundFixed(b * u);
            u -= roundFixed(a * v);
            if (half) {
                u = -u;
                v = -v;
            }
        }
    };

    PlaneRotation azimuth_, polar_;
    PlaneRotation tangent_;   // about the normal (alignFirstAxis); the identity until then
    bool hasNormal_ = false;  // false: the identity frame
};


}  // namespace drm

#endif  // DRM_LOCAL_FRAME_H
