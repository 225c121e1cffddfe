// Arithmetic that must give the same bits on every machine.
//
// A .drm file is decoded by repeating the encoder's predictions, so every
// floating-point step of the decode path must round identically everywhere:
// only +, -, *, / and sqrt on IEEE doubles (all correctly rounded), no fused
// multiply-add (the codec is built with -ffp-contract=off) and no
// transcendental functions, whose last bits differ between C libraries.
#ifndef DRM_EXACT_MATH_H
#define DRM_EXACT_MATH_H

#include <cmath>
#include <cstdint>

#if defined(__FAST_MATH__)
#error "drm's codec must not be built with -ffast-math: decoded meshes would depend on the compiler"
#endif
#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ != 0
#error "drm's codec needs double arithmetic evaluated in double (SSE2 or equivalent), not x87"
#endif

namespace drm {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm2(Vec3 a) { return dot(a, a); }
inline double norm(Vec3 a) { return std::sqrt(norm2(a)); }

// Component of v orthogonal to the direction e (e need not be unit length).
// Returns v unchanged when e is zero.
inline Vec3 rejectFrom(Vec3 v, Vec3 e) {
    const double ee = norm2(e);
    if (ee == 0) return v;
    return v - e * (dot(v, e) / ee);
}

// Predicted points are snapped to a fixed-point grid of 1/kSubUnits of a
// quantization step before ranking, so that distances are exact integers.
constexpr int kSubUnitBits = 4;
constexpr int64_t kSubUnits = int64_t(1) << kSubUnitBits;

// A point in those fixed-point units.
struct FixedPoint {
    int64_t x = 0, y = 0, z = 0;
};

// Squared distance from p to the grid point whose three coordinates start
// at point, in fixed-point units: the one distance every search is decided
// by, whether the point is read from a grid (spatial_index.h) or from the
// copy a cell keeps (candidate_set.h).
inline int64_t fixedDistance2(const int32_t* point, const FixedPoint& p) {
    const int64_t dx = int64_t(point[0]) * kSubUnits - p.x;
    const int64_t dy = int64_t(point[1]) * kSubUnits - p.y;
    const int64_t dz = int64_t(point[2]) * kSubUnits - p.z;
    return dx * dx + dy * dy + dz * dz;
}

}  // namespace drm

#endif  // DRM_EXACT_MATH_H
