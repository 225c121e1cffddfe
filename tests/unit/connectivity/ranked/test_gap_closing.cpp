// Gap closing (connectivity/ranked/gap_closing.h) on fans built by hand:
// fanEnds finds the far vertex of the fan at each end of an open edge, the
// same with or without the traversal's fan pieces, and says where a fan
// ends on a coded boundary; gapClosingVertex takes a fan end only when the
// gap at its end of the edge is narrower than 60 degrees and the vertex is
// admissible, and of two such ends the narrower gap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "common.h"
#include "connectivity/admissibility.h"
#include "connectivity/ranked/gap_closing.h"
#include "connectivity/traversal.h"

namespace drm {
namespace {

// Vertex 0 at the centre (1000, 1000, 0), vertex k of `degrees` at 200 grid
// units in the direction of degrees[k - 1].
std::vector<int32_t> fanGrid(const std::vector<double>& degrees) {
    std::vector<int32_t> grid = {1000, 1000, 0};
    for (double d : degrees) {
        const double r = d * 3.14159265358979323846 / 180;
        grid.insert(grid.end(), {int32_t(std::lround(1000 + 200 * std::cos(r))),
                                 int32_t(std::lround(1000 + 200 * std::sin(r))), 0});
    }
    return grid;
}

// Triangles (0, k, k + 1) for k = 1 .. last - 1, counter-clockwise around
// vertex 0: the start triangle (0, 1, 2), then each across the edge (k, 0)
// of the one before.
void buildFan(Traversal& t, uint32_t last) {
    t.startComponent(0, 1, 2);
    for (uint32_t k = 2; k < last; ++k) t.attachApex(OpenEdge{k, 0, k - 1}, k + 1);
}

TEST(GapClosing, FanEndsWithAndWithoutFanPieces) {
    for (bool pieces : {false, true}) {
        SCOPED_TRACE(pieces ? "fan pieces" : "walked");
        Traversal t(8, 8, nullptr);
        if (pieces) t.trackFanPieces();
        buildFan(t, 5);  // (0,1,2) (0,2,3) (0,3,4) (0,4,5)
        const OpenEdge edge{0, 1, 2};  // the start triangle's edge 0->1
        const FanEnds ends = fanEnds(edge, t);
        EXPECT_EQ(ends.atI, 5u);  // around vertex 0, past 2, 3 and 4
        EXPECT_EQ(ends.atJ, kNoVertex);  // around vertex 1: the edge's own triangle alone
        EXPECT_FALSE(ends.boundaryAtI);
        EXPECT_FALSE(ends.boundaryAtJ);
        // Seen from the last triangle's edge (5, 0), the fan at vertex 0
        // ends at 1.
        const FanEnds back = fanEnds(OpenEdge{5, 0, 4}, t);
        EXPECT_EQ(back.atJ, 1u);
        EXPECT_EQ(back.atI, kNoVertex);
    }
}

TEST(GapClosing, AFanEndingOnACodedBoundaryHasNoFarVertex) {
    for (bool pieces : {false, true}) {
        SCOPED_TRACE(pieces ? "fan pieces" : "walked");
        Traversal t(8, 8, nullptr);
        if (pieces) t.trackFanPieces();
        buildFan(t, 5);
        t.closeAsBoundary(OpenEdge{5, 0, 4});
        const FanEnds ends = fanEnds(OpenEdge{0, 1, 2}, t);
        EXPECT_EQ(ends.atI, kNoVertex);
        EXPECT_TRUE(ends.boundaryAtI);
        EXPECT_FALSE(ends.boundaryAtJ);
    }
}

TEST(GapClosing, ANarrowGapIsClosedByTheFansFarVertex) {
    // Rim vertices at 0, 75, 150, 225 and 310 degrees: the gap between
    // vertex 1 (0 degrees) and vertex 5 is 50 degrees wide.
    const std::vector<int32_t> narrow = fanGrid({0, 75, 150, 225, 310});
    // At 290 degrees it is 70 degrees wide.
    const std::vector<int32_t> wide = fanGrid({0, 75, 150, 225, 290});
    Traversal t(8, 8, nullptr);
    buildFan(t, 5);
    const Admissibility admissible(t, true);
    const OpenEdge edge{0, 1, 2};
    const FanEnds ends = fanEnds(edge, t);
    ASSERT_EQ(ends.atI, 5u);
    EXPECT_EQ(gapClosingVertex(edge, ends, narrow, admissible), 5u);
    EXPECT_EQ(gapClosingVertex(edge, ends, wide, admissible), kNoVertex);
}

TEST(GapClosing, OfTwoNarrowGapsTheNarrowerAndOnlyAdmissibleVertices) {
    // The edge 0 -> 1 along x; vertex 3 seen from 0 at 50 degrees off the
    // edge, vertex 4 seen from 1 at 30 degrees off it, vertex 5 behind 0.
    const std::vector<int32_t> grid = {0,    0,  0,  // 0
                                       1000, 0,  0,  // 1
                                       500,  -800, 0,  // 2: the opposite vertex
                                       643,  766, 0,  // 3: 50 degrees at 0
                                       134,  500, 0,  // 4: 30 degrees at 1
                                       -500, 10, 0};  // 5: 179 degrees at 0
    Traversal t(8, 8, nullptr);
    t.startComponent(0, 1, 2);
    const Admissibility admissible(t, true);
    const OpenEdge edge{0, 1, 2};
    FanEnds ends;
    ends.atI = 3;
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), 3u);
    ends.atJ = 4;
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), 4u);  // 30 degrees is narrower
    // Gaps of 60 degrees or more are left alone: 4 seen from 0 is 75
    // degrees off the edge, 3 seen from 1 is 65.
    ends.atI = 4;
    ends.atJ = 3;
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), kNoVertex);
    ends.atJ = 4;
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), 4u);
    ends = FanEnds();
    ends.atI = 5;  // behind the edge's end: no gap to close
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), kNoVertex);
    ends.atI = 1;  // the edge's own end is never admissible
    EXPECT_EQ(gapClosingVertex(edge, ends, grid, admissible), kNoVertex);
    EXPECT_EQ(gapClosingVertex(edge, FanEnds(), grid, admissible), kNoVertex);
}

}  // namespace
}  // namespace drm
