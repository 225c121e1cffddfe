// The simplest lossless geometry section: every grid coordinate in `bits`
// bits, packed LSB first: the fallback for tiny sets, and the coder that
// keeps the input's numbering (the decoded vertex order is the input order).
#ifndef DRM_RAW_CODER_H
#define DRM_RAW_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

std::vector<uint8_t> packGrid(const std::vector<int32_t>& grid, int bits);
// Throws Error unless size is exactly what vertexCount vertices need.
std::vector<int32_t> unpackGrid(const uint8_t* data, size_t size, uint64_t vertexCount, int bits);

}  // namespace drm

#endif  // DRM_RAW_CODER_H
