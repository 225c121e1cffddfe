// Every point's k nearest other points, for the whole grid at once (the
// geometry tree's neighbour graph), in about two thirds of the instructions
// of one query at a time through the traversal's cell index, leftovers
// included. The points are sorted by cell, each cell gathers the points of
// the 3 x 3 x 3 block of cells around it once, and every point of the cell
// takes its k nearest from that block. The answer is certain when the k-th
// lies nearer than anything outside the block can (the point's clearance to
// the block's faces); the few points where it is not (sparse regions,
// outliers) are left to the caller's exact search.
#ifndef DRM_ALL_NEAREST_H
#define DRM_ALL_NEAREST_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

// grid: x, y, z per point (a point outside [0, 2^21) on any axis leaves
// every point uncertain). For every point v it can certify, fills
// neighbours[v * k + j] and, unless distance2 is null, (*distance2)[v * k +
// j] (squared distance in grid units) with the k points other than v
// nearest it, in increasing (distance, index) order: exactly what any exact search with
// ties by index gives. Returns the points it could not certify, in
// increasing order; their rows are left untouched. cellShift: cells are
// 2^cellShift grid units wide (any width gives the same answers, only more
// or fewer of them); -1 picks the narrowest at which the occupied cells
// hold k / 4 distinct positions on average, at least 2 (the fastest on the
// corpus: docs/tuning.md).
// threads: 2 or more splits the cells between two threads (same answers).
std::vector<uint32_t> nearestOfEachByCells(const std::vector<int32_t>& grid, size_t k, int cellShift,
                                           std::vector<uint32_t>& neighbours, std::vector<int64_t>* distance2,
                                           int threads = 1);

}  // namespace drm

#endif  // DRM_ALL_NEAREST_H
