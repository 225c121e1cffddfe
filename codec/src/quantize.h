// Quantization of positions onto the cubic grid (paper, Section 3.1).
#ifndef DRM_QUANTIZE_H
#define DRM_QUANTIZE_H

#include "drm/drm.h"
#include "exact_math.h"

namespace drm {

constexpr int kMinBits = 1;
constexpr int kMaxBits = 21;  // keeps squared fixed-point distances within int64

inline int32_t gridMax(int bits) { return int32_t((int64_t(1) << bits) - 1); }

inline Vec3 gridPoint(const std::vector<int32_t>& q, uint32_t v) {
    return {double(q[3 * size_t(v)]), double(q[3 * size_t(v) + 1]), double(q[3 * size_t(v) + 2])};
}

}  // namespace drm

#endif  // DRM_QUANTIZE_H
