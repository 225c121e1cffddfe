// Quantization of positions onto the cubic grid (paper, Section 3.1).
#ifndef DRM_QUANTIZE_H
#define DRM_QUANTIZE_H

#include "drmcodec/drmcodec.h"
#include "exact_math.h"

#include <string>
#include <vector>

namespace drm {

constexpr int kMinBits = kMinQuantizationBits;  // drmcodec.h
constexpr int kMaxBits = kMaxQuantizationBits;

inline int32_t gridMax(int bits) { return int32_t((int64_t(1) << bits) - 1); }

// What is wrong with a grid a file could hold, or "" if nothing: the one
// definition the encoder (before writing) and the reader (on a header)
// share. The bits are in range, the origin is finite (also as a float),
// the step is finite and positive.
std::string gridProblem(const Grid& grid);

// origin + q * step per coordinate, rounded to float: the decoded
// positions. Returns false (and the first failing vertex in *badVertex)
// if a coordinate leaves the range of float; the encoder checks its own
// grid points with it so that the decoder never meets that.
bool dequantize(const std::vector<int32_t>& q, const Grid& grid, std::vector<float>& positions, size_t* badVertex);

inline Vec3 gridPoint(const std::vector<int32_t>& q, uint32_t v) {
    return {double(q[3 * size_t(v)]), double(q[3 * size_t(v) + 1]), double(q[3 * size_t(v) + 2])};
}

}  // namespace drm

#endif  // DRM_QUANTIZE_H
