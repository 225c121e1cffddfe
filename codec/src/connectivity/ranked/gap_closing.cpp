#include "connectivity/ranked/gap_closing.h"

#include "exact_math.h"
#include "mesh/quantize.h"

namespace drm {
namespace {

// Walks the rebuilt fan around `center` from the triangle (center, start, o)
// in the direction that leaves through edges into center, and returns the far
// vertex of the fan's last open edge, or kNoVertex if the fan ends on a
// coded boundary (then *boundary is set). `clockwise` picks the walking direction:
//  false: from (vi, vj, o) at vi, the edge into vi is (o, vi); its twin (vi, o)
//         holds the next triangle (vi, o, o2), whose edge into vi is (o2, vi)...
//  true:  the mirror walk at vj, through edges out of vj.
// O(valence): a traversal that keeps its fan pieces answers at once.
uint32_t walkedFanEnd(const Traversal& t, uint32_t center, uint32_t o, bool clockwise, bool* boundary) {
    uint32_t far = o;
    // A manifold fan has at most valence-many triangles; the bound guards
    // against cycling on inputs the checks should already have refused.
    for (size_t step = 0; step < t.vertexCount(); ++step) {
        const uint32_t next = clockwise ? t.thirdVertex(far, center) : t.thirdVertex(center, far);
        if (next == Traversal::kNoTriangle) return far;
        if (next == Traversal::kBoundary) {
            *boundary = true;
            return kNoVertex;
        }
        far = next;
    }
    return kNoVertex;
}

// Cosine of the angle at `at` between the directions to p and q, compared
// against cos 60 = 1/2 without a square root: dot > 0 and dot^2 > |u|^2|v|^2/4.
bool narrowerThan60(Vec3 at, Vec3 p, Vec3 q, double* cosine2) {
    const Vec3 u = p - at, v = q - at;
    const double d = dot(u, v), uu = norm2(u), vv = norm2(v);
    if (d <= 0 || uu == 0 || vv == 0) return false;
    *cosine2 = (d * d) / (uu * vv);
    return *cosine2 > 0.25;
}

}  // namespace

FanEnds fanEnds(const OpenEdge& edge, const Traversal& t) {
    // A fan piece of one triangle leaves the opposite vertex as the "gap"
    // vertex: that is the back face, not a gap.
    FanEnds ends;
    if (!t.tracksFanPieces()) {
        ends.atI = walkedFanEnd(t, edge.vi, edge.opposite, false, &ends.boundaryAtI);
        ends.atJ = walkedFanEnd(t, edge.vj, edge.opposite, true, &ends.boundaryAtJ);
        if (ends.atI == edge.opposite) ends.atI = kNoVertex;
        if (ends.atJ == edge.opposite) ends.atJ = kNoVertex;
        return ends;
    }
    // Around vi the piece starts at (vi, vj) (the edge's own triangle);
    // around vj it ends there. Where its far edge was coded as boundary,
    // the fan ends on the boundary.
    const uint32_t endAtI = t.fanEndFrom(edge.vi, edge.vj), startAtJ = t.fanStartTo(edge.vi, edge.vj);
    ends.atI = endAtI == Traversal::kNoTriangle ? kNoVertex : endAtI;
    ends.atJ = startAtJ == Traversal::kNoTriangle ? kNoVertex : startAtJ;
    if (ends.atI != kNoVertex && t.thirdVertex(edge.vi, ends.atI) == Traversal::kBoundary) {
        ends.atI = kNoVertex;
        ends.boundaryAtI = true;
    }
    if (ends.atJ != kNoVertex && t.thirdVertex(ends.atJ, edge.vj) == Traversal::kBoundary) {
        ends.atJ = kNoVertex;
        ends.boundaryAtJ = true;
    }
    if (ends.atI == edge.opposite) ends.atI = kNoVertex;
    if (ends.atJ == edge.opposite) ends.atJ = kNoVertex;
    return ends;
}

uint32_t gapClosingVertex(const OpenEdge& edge, const FanEnds& ends, const std::vector<int32_t>& grid,
                          const Admissibility& admissible) {
    const uint32_t atI = ends.atI, atJ = ends.atJ;
    const Vec3 a = gridPoint(grid, edge.vi), b = gridPoint(grid, edge.vj);
    uint32_t best = kNoVertex;
    double bestCosine2 = 0;
    double cosine2 = 0;
    if (atI != kNoVertex && admissible(atI, edge) &&
        narrowerThan60(a, b, gridPoint(grid, atI), &cosine2)) {
        best = atI;
        bestCosine2 = cosine2;
    }
    if (atJ != kNoVertex && admissible(atJ, edge) &&
        narrowerThan60(b, a, gridPoint(grid, atJ), &cosine2) && (best == kNoVertex || cosine2 > bestCosine2)) {
        best = atJ;
    }
    return best;
}

}  // namespace drm
