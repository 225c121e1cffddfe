// Admissibility (connectivity/admissibility.h), the one rule of which
// vertices may close the triangle across an open edge, on traversals built
// by hand: the edge's own ends and culled vertices never, a vertex not yet
// in the mesh always; with the topological filter, no vertex whose new
// triangle would reuse a rebuilt directed edge or the twin of a coded
// boundary, the opposite vertex only as the start triangle's back face;
// and, past a part's seam, no triangle of three seam-side vertices.
#include <gtest/gtest.h>

#include <cstdint>

#include "connectivity/admissibility.h"
#include "connectivity/traversal.h"

namespace drm {
namespace {

TEST(Admissibility, TheEdgesEndsNeverAndUntouchedVerticesAlways) {
    Traversal t(6, 8, nullptr);
    t.startComponent(0, 1, 2);
    const Admissibility filter(t, true), plain(t, false);
    OpenEdge e;
    ASSERT_TRUE(t.popOpenEdge(e));
    ASSERT_EQ(e.vi, 0u);
    ASSERT_EQ(e.vj, 1u);
    ASSERT_EQ(e.opposite, 2u);
    for (const Admissibility* a : {&filter, &plain}) {
        EXPECT_FALSE((*a)(0, e));
        EXPECT_FALSE((*a)(1, e));
        EXPECT_TRUE((*a)(3, e));
        EXPECT_TRUE((*a)(5, e));
        // The start triangle's back face (1, 0, 2) closes a two-triangle
        // component: the opposite vertex is admissible while the component
        // has one triangle.
        EXPECT_TRUE((*a)(2, e));
    }
    EXPECT_EQ(&filter.traversal(), &t);
}

TEST(Admissibility, TheFilterRefusesReusedEdgesAndBoundaryTwins) {
    Traversal t(6, 8, nullptr);
    t.startComponent(0, 1, 2);
    const Admissibility filter(t, true), plain(t, false);
    OpenEdge e;
    ASSERT_TRUE(t.popOpenEdge(e));  // (0, 1): coded as a boundary
    t.closeAsBoundary(e);
    ASSERT_TRUE(t.popOpenEdge(e));  // (1, 2), opposite 0
    ASSERT_EQ(e.vi, 1u);
    ASSERT_EQ(e.vj, 2u);
    // Triangle (2, 1, 0) would add 1->0, the twin of the boundary edge 0->1.
    EXPECT_FALSE(filter(0, e));
    EXPECT_TRUE(plain(0, e));
    t.attachApex(e, 3);             // triangle (2, 1, 3)
    ASSERT_TRUE(t.popOpenEdge(e));  // its left edge (1, 3), opposite 2
    ASSERT_EQ(e.vi, 1u);
    ASSERT_EQ(e.vj, 3u);
    ASSERT_EQ(e.opposite, 2u);
    // (3, 1, 0) would add 1->0, the boundary's twin.
    EXPECT_FALSE(filter(0, e));
    EXPECT_TRUE(plain(0, e));
    // (3, 1, 2) would add 1->2, which triangle (0, 1, 2) holds; the
    // opposite vertex of a component of two triangles is refused too.
    EXPECT_FALSE(filter(2, e));
    EXPECT_TRUE(plain(2, e));
    EXPECT_TRUE(filter(4, e));
}

TEST(Admissibility, CulledVerticesNever) {
    // A closed tetrahedron rebuilt in full culls all four vertices; vertex
    // 4 is never touched.
    Traversal t(5, 4, nullptr);
    t.startComponent(0, 2, 1);
    OpenEdge e;
    ASSERT_TRUE(t.popOpenEdge(e));
    t.attachApex(e, 3);
    const uint32_t next[2] = {1, 3};
    for (int k = 0; k < 2; ++k) {
        ASSERT_TRUE(t.popOpenEdge(e));
        t.attachApex(e, next[k]);
    }
    ASSERT_FALSE(t.popOpenEdge(e));
    const Admissibility filter(t, true), plain(t, false);
    const OpenEdge anyEdge{0, 2, 1};
    for (uint32_t v = 0; v < 4; ++v) {
        ASSERT_TRUE(t.isCulled(v));
        EXPECT_FALSE(plain(v, anyEdge)) << v;
        EXPECT_FALSE(filter(v, anyEdge)) << v;
    }
    EXPECT_TRUE(plain(4, anyEdge));
    EXPECT_TRUE(filter(4, anyEdge));
}

TEST(Admissibility, PastTheSeamNoTriangleOfThreeSeamSideVertices) {
    Traversal t(10, 8, nullptr);
    Admissibility filter(t, true), plain(t, false);
    filter.setSeam(6);
    plain.setSeam(6);
    const OpenEdge seamSide{6, 7, 8}, across{5, 7, 8}, below{1, 2, 3};
    for (const Admissibility* a : {&filter, &plain}) {
        EXPECT_FALSE((*a)(9, seamSide));  // three vertices from the seam on
        EXPECT_FALSE((*a)(6 + 2, seamSide));
        EXPECT_TRUE((*a)(4, seamSide));  // the apex lies below the seam
        EXPECT_TRUE((*a)(9, across));    // one end below
        EXPECT_TRUE((*a)(9, below));
    }
    // Without a seam, the same edge takes any untouched vertex.
    const Admissibility whole(t, true);
    EXPECT_TRUE(whole(9, seamSide));
}

}  // namespace
}  // namespace drm
