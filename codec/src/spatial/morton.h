// Morton order of grid points: the bits of x, y and z interleaved (bit 3i
// of the key is bit i of x, 3i + 1 of y, 3i + 2 of z), for coordinates of
// up to 21 bits. A cell of any power-of-two width is then one run of keys.
#ifndef DRM_MORTON_H
#define DRM_MORTON_H

#include <cstdint>

namespace drm {

// x's low 21 bits spread out to every third bit, from bit 0.
inline uint64_t spreadMortonBits(uint64_t x) {
    x &= 0x1FFFFF;
    x = (x | x << 32) & 0x1F00000000FFFFull;
    x = (x | x << 16) & 0x1F0000FF0000FFull;
    x = (x | x << 8) & 0x100F00F00F00F00Full;
    x = (x | x << 4) & 0x10C30C30C30C30C3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
}

// spreadMortonBits' inverse: every third bit of k, from bit 0, packed.
inline uint32_t gatherMortonBits(uint64_t k) {
    k &= 0x1249249249249249ull;
    k = (k | k >> 2) & 0x10C30C30C30C30C3ull;
    k = (k | k >> 4) & 0x100F00F00F00F00Full;
    k = (k | k >> 8) & 0x1F0000FF0000FFull;
    k = (k | k >> 16) & 0x1F00000000FFFFull;
    k = (k | k >> 32) & 0x1FFFFF;
    return uint32_t(k);
}

inline uint64_t mortonKey(uint64_t x, uint64_t y, uint64_t z) {
    return spreadMortonBits(x) | spreadMortonBits(y) << 1 | spreadMortonBits(z) << 2;
}

// The key of grid point p (x, y, z: non-negative, below 2^21).
inline uint64_t mortonKeyOf(const int32_t* p) { return mortonKey(uint32_t(p[0]), uint32_t(p[1]), uint32_t(p[2])); }

}  // namespace drm

#endif  // DRM_MORTON_H
