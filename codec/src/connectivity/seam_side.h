// The two connectivity parts (connectivity_parts.h): which edges lie on a
// part's seam side. The boundary flag gives them classes of their own, and
// their size step stops at its first ball: both ask this one test, so that
// the two cannot drift apart.
#ifndef DRM_SEAM_SIDE_H
#define DRM_SEAM_SIDE_H

#include <algorithm>
#include <cstdint>

#include "common.h"
#include "exact_math.h"
#include "spatial/morton.h"
#include "connectivity/traversal.h"

namespace drm {

struct SeamSide {
    // Part 1: its split; an edge whose two ends are both at or past it (no
    // such vertex may close it: the apex, if any, lies below).
    uint32_t seam = kNoVertex;
    // Part 2: the Morton key of its vertex 0; a prediction whose grid point
    // (on a grid of `bits` bits per axis) has a smaller key lies in part
    // 1's region, across the seam.
    bool secondPart = false;
    uint64_t firstPartBelow = 0;
    int bits = 0;

    // prediction: snapped (snapPrediction), in fixed point.
    bool contains(const OpenEdge& edge, const FixedPoint& prediction) const {
        if (seam != kNoVertex) return edge.vi >= seam && edge.vj >= seam;
        return secondPart && mortonKeyOf(prediction) < firstPartBelow;
    }

private:
    uint64_t mortonKeyOf(const FixedPoint& p) const {
        const int64_t top = (int64_t(1) << bits) - 1;
        auto gridOf = [&](int64_t c) { return uint64_t(std::min(std::max<int64_t>(c >> kSubUnitBits, 0), top)); };
        return mortonKey(gridOf(p.x), gridOf(p.y), gridOf(p.z));
    }
};

}  // namespace drm

#endif  // DRM_SEAM_SIDE_H
