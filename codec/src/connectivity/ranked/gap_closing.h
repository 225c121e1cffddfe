// Gap closing: a lever beyond the paper (method notes: -8%).
//
// When the fan of an end of the open edge is nearly complete, the triangle
// across the edge is very likely the one that closes the gap: its apex is the
// far vertex of the fan's other open edge. If the gap is narrower than 60
// degrees, that vertex is ranked first, ahead of the distance order.
#ifndef DRM_GAP_CLOSING_H
#define DRM_GAP_CLOSING_H

#include <vector>

#include "connectivity/admissibility.h"
#include "common.h"

namespace drm {

// The far vertices of the rebuilt fans around the edge's ends: walking
// around vi (resp. vj) away from the edge, the far end of the fan's last
// open edge. kNoVertex where the fan ends on a coded boundary, or where it
// is the edge's own triangle alone (its far end is the opposite vertex).
// These are the edge's front neighbours.
struct FanEnds {
    uint32_t atI = kNoVertex, atJ = kNoVertex;
    // Whether the fan at vi (vj) ends on a coded boundary.
    bool boundaryAtI = false, boundaryAtJ = false;
};
FanEnds fanEnds(const OpenEdge& edge, const Traversal& traversal);

// The admissible vertex that closes the narrower gap (under 60 degrees) at
// either end of edge, or kNoVertex; ends as fanEnds gives them.
uint32_t gapClosingVertex(const OpenEdge& edge, const FanEnds& ends, const std::vector<int32_t>& grid,
                          const Admissibility& admissible);

}  // namespace drm

#endif  // DRM_GAP_CLOSING_H
