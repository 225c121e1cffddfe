#include "connectivity/ranked/predictor_selection.h"

#include <algorithm>
#include <limits>

#include "common.h"
#include "connectivity/ranked/predictor.h"
#include "mesh/quantize.h"

namespace drm {
namespace {

// More faces than this vote in a sample (below).
constexpr size_t kVotingFaces = size_t(1) << 17;

}  // namespace

PredictorVotes countPredictorVotes(const std::vector<uint32_t>& t, size_t vertexCount, const MeshTopology& topology,
                                   const std::vector<int32_t>& grid) {
    const size_t faceCount = t.size() / 3;
    // Squared distance from each vertex to its nearest neighbour in the
    // mesh, over every face's edges: read from each vertex's own edges out
    // (the same edges; in vertex order the far ends lie near, where the
    // faces in input order would send each update anywhere).
    std::vector<double> nearestNeighbour2(vertexCount, std::numeric_limits<double>::infinity());
    for (size_t a = 0; a < vertexCount; ++a)
        for (uint32_t e = topology.start[a]; e < topology.start[a + 1]; ++e) {
            const uint32_t b = topology.out[e].to;
            const double d2 = norm2(gridPoint(grid, uint32_t(a)) - gridPoint(grid, b));
            nearestNeighbour2[a] = std::min(nearestNeighbour2[a], d2);
            nearestNeighbour2[b] = std::min(nearestNeighbour2[b], d2);
        }

    // Each face votes once, through one of its edges (the k-th for the
    // voting face number k modulo 3), with its third vertex as the opposite and the
    // apex of the face across as the target: as the traversal attaches
    // each face through one edge, but without running it: the same winner
    // as the traversal's votes on every corpus mesh at 12 bits, in well
    // under half the instructions.
    //
    // Over kVotingFaces faces, every stride-th face votes, at most
    // kVotingFaces and at least half as many (each face's look-ups land
    // anywhere in memory); the share of parallelogram votes then moves by
    // about a thousandth at most (docs/tuning.md).
    const size_t stride = std::max<size_t>(1, (faceCount + kVotingFaces - 1) / kVotingFaces);
    PredictorVotes votes;
    for (size_t f = 0; f < faceCount; f += stride) {
        const size_t k = (f / stride) % 3;
        const uint32_t vi = t[3 * f + k], vj = t[3 * f + (k + 1) % 3], opposite = t[3 * f + (k + 2) % 3];
        const uint32_t apex = topology.apexAcross(vi, vj, nullptr);
        if (apex == kNoVertex) continue;
        const Vec3 a = gridPoint(grid, vi), b = gridPoint(grid, vj);
        const Vec3 o = gridPoint(grid, opposite), target = gridPoint(grid, apex);
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
    }
    return votes;
}

}  // namespace drm
