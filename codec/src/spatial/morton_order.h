// The vertices in Morton order of their grid points: the order the
// connectivity numbers them in (docs/format.md, "Vertex numbering"), and
// the order coder 4 codes them in.
//
// The connectivity numbers its vertices by their positions alone (points
// sharing a grid point keep the geometry section's order), not by the
// order the vertex coder happens to decode them in. The ranks' ties are
// broken by index, so in the vertex coder's numbering
// (kFlagSectionNumbering) the encoder cannot rank a single edge before its
// vertex coder has finished; in Morton order, on a mesh whose points are
// all distinct, it ranks them while the vertex set is coded.
#ifndef DRM_MORTON_ORDER_H
#define DRM_MORTON_ORDER_H

#include <cstdint>
#include <vector>

namespace drm {

// grid: 3 non-negative coordinates per point, each below 2^21. Returns the
// point indices sorted by the Morton key of their points (morton.h);
// points with equal keys (the same grid point) keep their order in `grid`.
std::vector<uint32_t> mortonOrder(const std::vector<int32_t>& grid);

// Whether two points of grid lie on the same grid point, given
// order = mortonOrder(grid).
bool hasCoincidentPoints(const std::vector<int32_t>& grid, const std::vector<uint32_t>& order);

}  // namespace drm

#endif  // DRM_MORTON_ORDER_H
