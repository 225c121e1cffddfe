// Geometry coder 4 ("sorted"): the vertex set with no order of its own.
// The vertices are put in Morton order of their grid points and each is
// coded as the gap from the one before, its bit length in an adaptive table
// and the bits below its leading one. A point set that is no surface (a
// soup of scattered triangles) predicts no better from its neighbours than
// from nothing, and then this costs what the set itself holds: about
// log2(C(cells, n)) / n bits a vertex, less than the tree or raw bits take
// on such a set (the corpus mesh soup). The decoded order is the Morton
// order, ties by input index.
#ifndef DRM_SORTED_CODER_H
#define DRM_SORTED_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

// grid: 3 coordinates per vertex, each in [0, 2^bits), bits 1..21. The
// section's bytes, and order[d], the input vertex that decoded vertex d is.
std::vector<uint8_t> encodeSortedPoints(const std::vector<int32_t>& grid, int bits, std::vector<uint32_t>& order);

// The grid, in decoded order. Throws Error (Corrupt) on a section that does
// not hold exactly vertexCount points on the grid.
std::vector<int32_t> decodeSortedPoints(const uint8_t* data, size_t size, uint64_t vertexCount, int bits);

}  // namespace drm

#endif  // DRM_SORTED_CODER_H
