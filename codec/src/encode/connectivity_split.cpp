#include "encode/connectivity_split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "connectivity/connectivity_parts.h"
#include "encode/rank_stream.h"

namespace drm {

// Whether this attempt may split its connectivity in two parts
// (splitFaces has the last word).
bool maySplitConnectivity(const NumberedMesh& numbered, const EncodeOptions& options) {
    const size_t faces = numbered.triangles.size() / 3;
    if (numbered.vertexCount < 2 || faces == 0) return false;
    if (options.connectivityParts == 2) return true;
    return options.connectivityParts == 0 && numbered.mortonNumbering && faces >= kTwoPartsFromFaces;
}
namespace {

// Unless asked for two parts whatever they cost, a mesh whose shortest seam
// has more edges than this share of its faces stays whole: a short seam
// costs a fraction of a per cent of the file (the second part's tables
// learning anew, the seam's edges coded as boundary edges on both sides),
// a long one on a CAD mesh several per cent (docs/tuning.md).
constexpr double kLongestSeamPerFace = 0.009;

// Where two parts split the numbered vertices: of the indices that leave
// 45 to 55 % of the faces in the first part, the one with the fewest seam
// edges (each is coded as a boundary edge in both parts), the one nearest
// the middle of equals. On a mesh of several pieces the seam can then run
// between them.
//
// An edge (u, w) between faces whose smallest vertices are a <= b lies on
// the seam of a split at m when a < m <= b (its faces fall in different
// parts; both of its ends are then from m on, since b <= min(u, w)): so
// every split's seam is counted at once, from a difference array.
struct Split {
    uint32_t at = 1;
    int64_t seamEdges = 0;
    bool even = true;  // 45 to 55 % of the faces in part 1
};
Split splitIndex(const NumberedMesh& numbered, const std::vector<uint32_t>& smallest) {
    const size_t faces = smallest.size(), n = numbered.vertexCount;
    const MeshTopology& topology = numbered.topology;
    std::vector<int64_t> below(n + 1, 0), seamChange(n + 2, 0);
    for (uint32_t v : smallest) ++below[v + 1];
    for (size_t i = 1; i <= n; ++i) below[i] += below[i - 1];  // faces whose smallest vertex lies below i
    // Each interior edge once, from the side where it runs up (a boundary
    // edge, met from one side only, is on no seam), in vertex order: the
    // edge back is then looked up among near vertices' edges.
    for (uint32_t u = 0; u < n; ++u)
        for (uint32_t e = topology.start[u]; e < topology.start[u + 1]; ++e) {
            const uint32_t w = topology.out[e].to, f = topology.out[e].face;
            if (u > w) continue;
            const uint32_t other = topology.faceOf(w, u);
            if (other == kNoIndex) continue;
            const uint32_t a = std::min(smallest[f], smallest[other]), b = std::max(smallest[f], smallest[other]);
            ++seamChange[a + 1];  // on the seam for m in a + 1 .. b
            --seamChange[b + 1];
        }
    uint32_t best = 0;
    int64_t bestSeam = INT64_MAX, seam = 0;
    double bestOff = 1;
    for (size_t m = 1; m < n; ++m) {
        seam += seamChange[m];
        const double off = std::abs(double(below[m]) / double(faces) - 0.5);
        if (off > 0.05) continue;
        if (seam < bestSeam || (seam == bestSeam && off < bestOff)) {
            best = uint32_t(m);
            bestSeam = seam;
            bestOff = off;
        }
    }
    if (best != 0) return {best, bestSeam};
    // No index splits the faces that evenly (a few huge fans): the median.
    Split median;
    median.even = false;
    seam = 0;
    for (median.at = 1; median.at < n - 1 && 2 * size_t(below[median.at]) < faces; ++median.at) seam += seamChange[median.at];
    median.seamEdges = seam + seamChange[median.at];
    return median;
}

}  // namespace

bool splitFaces(const NumberedMesh& numbered, bool whateverItCosts, SplitFaces& parts) {
    const std::vector<uint32_t>& t = numbered.triangles;
    const size_t faces = t.size() / 3, n = numbered.vertexCount;
    std::vector<uint32_t> smallest(faces);
    for (size_t f = 0; f < faces; ++f) smallest[f] = smallestVertex(t, uint32_t(f));
    const Split at = splitIndex(numbered, smallest);
    if (!whateverItCosts && (!at.even || double(at.seamEdges) > kLongestSeamPerFace * double(faces)))
        return false;  // a long seam, or parts too uneven to gain much from a second thread
    for (uint32_t v : smallest) parts.firstFaces += v < at.at ? 1 : 0;
    const uint32_t m = parts.split = at.at;
    parts.secondGrid.assign(numbered.decodedGrid.begin() + 3 * size_t(m), numbered.decodedGrid.end());
    // Part 2's vertices with two fans or more: as many of their part 2
    // edges out without a part 2 face on the other side (each fan that is
    // not closed ends on one).
    const MeshTopology& topology = numbered.topology;
    auto inSecond = [&](uint32_t face) { return face != kNoIndex && smallest[face] >= m; };
    for (size_t v = m; v < n; ++v) {
        int open = 0;
        for (uint32_t e = topology.start[v]; e < topology.start[v + 1]; ++e)
            if (inSecond(topology.out[e].face) && !inSecond(topology.faceOf(topology.out[e].to, uint32_t(v)))) ++open;
        if (open >= 2) parts.keptInSecond.push_back(uint32_t(v - m));
    }
    return true;
}

}  // namespace drm
