#include "predictor_selection.h"

#include <algorithm>
#include <limits>

#include "common.h"
#include "predictor.h"
#include "quantize.h"
#include "traversal.h"

namespace drm {

PredictorVotes countPredictorVotes(const std::vector<uint32_t>& t, size_t vertexCount, const MeshTopology& topology,
                                   const std::vector<int32_t>& grid) {
    const size_t faceCount = t.size() / 3;
    // Squared distance from each vertex to its nearest neighbour in the mesh.
    std::vector<double> nearestNeighbour2(vertexCount, std::numeric_limits<double>::infinity());
    for (size_t c = 0; c < t.size(); ++c) {
        const uint32_t a = t[c], b = t[c - c % 3 + (c + 1) % 3];
        const double d2 = norm2(gridPoint(grid, a) - gridPoint(grid, b));
        nearestNeighbour2[a] = std::min(nearestNeighbour2[a], d2);
        nearestNeighbour2[b] = std::min(nearestNeighbour2[b], d2);
    }

    PredictorVotes votes;
    Traversal traversal(vertexCount, faceCount, nullptr);
    std::vector<uint8_t> attached(faceCount, 0);
    for (size_t f = 0; f < faceCount; ++f) {
        if (attached[f]) continue;
        attached[f] = 1;
        traversal.startComponent(t[3 * f], t[3 * f + 1], t[3 * f + 2]);
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            uint32_t face = 0;
            const uint32_t apex = topology.apexAcross(edge.vi, edge.vj, &face);
            if (apex == kNoVertex) {
                traversal.closeAsBoundary(edge);
                continue;
            }
            const Vec3 a = gridPoint(grid, edge.vi), b = gridPoint(grid, edge.vj);
            const Vec3 o = gridPoint(grid, edge.opposite), target = gridPoint(grid, apex);
            const double parallelogram = norm2(parallelogramApex(a, b, o) - target);
            const double midpoint = norm2(midpointApex(a, b, o) - target);
            const bool parallelogramHits = parallelogram < nearestNeighbour2[apex];
            const bool midpointHits = midpoint < nearestNeighbour2[apex];
            if (parallelogramHits) ++votes.parallelogram;
            if (midpointHits) ++votes.midpoint;
            if (!parallelogramHits && !midpointHits) {
                if (parallelogram < midpoint) ++votes.parallelogram;
                else ++votes.midpoint;
            }
            traversal.attachApex(edge, apex);
            attached[face] = 1;
        }
    }
    return votes;
}

}  // namespace drm
