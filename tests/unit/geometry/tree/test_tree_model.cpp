// The spanning-tree coder's model (geometry/tree/tree_model.h), shared by
// its encoder and decoder, against its stated definitions on small
// hand-made states: a vertex's candidates are the parent, the previous
// tree edge repeated from it, the reflections of the near decoded points
// through it and the parallelograms over pairs of them; each candidate's
// distance bucket (under a quarter, half or one spacing to a known point,
// or farther) and crowding (another candidate within a fifth of the
// spacing on every axis); repeats and the next flagged candidate; sign and
// magnitude contexts from the parent's and the previous vertex's
// residuals; the child-count contexts; the surface frame from the near
// points; the rough bits that decide where the frame serves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "geometry/tree/tree_model.h"

namespace drm {
namespace tree_coding {
namespace {

bool same(GridPoint a, GridPoint b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Root 0 at (100, 100, 100), vertex 1 (child of 0) at (104, 100, 100),
// vertex 2 (child of 0) at (100, 103, 100); cells of 256 units, so every
// point is in one cell.
CodingState smallState(bool flags, bool frame) {
    CodingState s(8, flags, frame);
    const GridPoint points[3] = {{100, 100, 100}, {104, 100, 100}, {100, 103, 100}};
    const uint32_t parents[3] = {kNoVertex, 0, 0};
    for (uint32_t v = 0; v < 3; ++v) {
        s.begin(parents[v]);
        s.place(v, points[v]);
    }
    return s;
}

TEST(TreeModel, CandidatesAreTheParentTheLastEdgeReflectionsAndParallelograms) {
    const CodingState s = smallState(true, false);
    // Vertex 3, a child of vertex 1; the previous vertex, 2, went from 0
    // by (0, 3, 0). Vertex 1's near decoded points: 0 (16 away, squared)
    // and 2 (25).
    const Predictions p = predict(s, 3, 1);
    const GridPoint expected[] = {
        {104, 100, 100},  // the parent
        {104, 103, 100},  // the previous edge from it
        {108, 100, 100},  // reflection of 0 through the parent
        {108, 97, 100},   // reflection of 2
        {104, 97, 100},   // parent + (0 - 2)
        {104, 103, 100},  // parent + (2 - 0)
    };
    ASSERT_EQ(p.count, 6);
    for (int c = 0; c < p.count; ++c) EXPECT_TRUE(same(p.candidate(c), expected[c])) << "candidate " << c;
    for (int c = p.count; c < kPaddedCandidates; ++c) EXPECT_EQ(p.xs[c], Predictions::kFar);
    EXPECT_EQ(p.nearest2, 16);
    EXPECT_EQ(p.spacing2, 25);
    EXPECT_EQ(p.crowdRadius, 1);  // a fifth of 5
    EXPECT_EQ(kMaxCandidates, 2 + kNearest + kNearest * (kNearest - 1));
    // A vertex whose parent has no other decoded point near: the parent,
    // twice (no previous edge from a root), nothing else.
    CodingState lone(8, true, false);
    lone.begin(kNoVertex);
    lone.place(0, GridPoint{5, 5, 5});
    const Predictions q = predict(lone, 1, 0);
    ASSERT_EQ(q.count, 2);
    EXPECT_TRUE(same(q.candidate(1), GridPoint{5, 5, 5}));
    EXPECT_EQ(q.spacing2, 0);
}

// The distance bucket by its definition: the squared distance from the
// candidate to the nearest known point (for the parent, its nearest near
// point) against the spacing.
int bucketByDefinition(const Predictions& p, int c) {
    if (p.spacing2 == 0) return kDistanceBuckets - 1;
    int64_t nearest = INT64_MAX;
    if (c == 0) nearest = p.nearest2;
    else
        for (const Predictions::Known& k : p.known) {
            const int64_t dx = p.xs[c] - k.x, dy = p.ys[c] - k.y, dz = p.zs[c] - k.z;
            nearest = std::min(nearest, dx * dx + dy * dy + dz * dz);
        }
    if (nearest * 16 < p.spacing2) return 0;  // under a quarter of the spacing
    if (nearest * 4 < p.spacing2) return 1;   // under half
    if (nearest < p.spacing2) return 2;       // under one
    return 3;
}

int crowdedByDefinition(const Predictions& p, int c) {
    for (int k = 0; k < p.count; ++k)
        if (k != c && std::abs(p.xs[k] - p.xs[c]) <= p.crowdRadius && std::abs(p.ys[k] - p.ys[c]) <= p.crowdRadius &&
            std::abs(p.zs[k] - p.zs[c]) <= p.crowdRadius)
            return 1;
    return 0;
}

TEST(TreeModel, FlagContextsFollowTheirDefinition) {
    // A denser state: a patch of points with some close pairs, queried
    // from several parents.
    CodingState s(3, true, false);
    std::vector<GridPoint> points;
    for (int i = 0; i < 40; ++i) points.push_back({50 + (i % 7) * 6 + (i % 3), 50 + (i / 7) * 5, 50 + (i % 5)});
    points.push_back({51, 50, 51});  // close to the first
    for (uint32_t v = 0; v < points.size(); ++v) {
        s.begin(v == 0 ? kNoVertex : v - 1);
        s.place(v, points[v]);
    }
    int crowdedSeen = 0;
    for (uint32_t parent = 0; parent + 1 < points.size(); ++parent) {
        const Predictions p = predict(s, uint32_t(points.size()), parent);
        for (int c = 0; c < p.count; ++c) {
            ASSERT_EQ(distanceBucket(p, c), bucketByDefinition(p, c)) << "parent " << parent << " candidate " << c;
            ASSERT_EQ(crowded(p, c), crowdedByDefinition(p, c)) << "parent " << parent << " candidate " << c;
            ASSERT_EQ(flagContextOf(p, c), 2 * bucketByDefinition(p, c) + crowdedByDefinition(p, c));
            crowdedSeen += crowded(p, c);
        }
    }
    EXPECT_GT(crowdedSeen, 0);
}

TEST(TreeModel, RepeatsHaveNoFlagOfTheirOwn) {
    const CodingState s = smallState(true, false);
    const Predictions p = predict(s, 3, 1);
    // Candidate 5 repeats candidate 1.
    for (int c = 0; c < p.count; ++c) EXPECT_EQ(repeatsEarlier(p, c), c == 5) << c;
    EXPECT_EQ(nextFlagged(p, 0), 1);
    EXPECT_EQ(nextFlagged(p, 3), 4);
    EXPECT_EQ(nextFlagged(p, 4), p.count);  // 4 is the last flags can name
}

TEST(TreeModel, SignAndMagnitudeContexts) {
    CodingState s = smallState(false, false);
    s.begin(1);  // vertex 3, child of 1
    s.signs[3 * 1 + 2] = kNegative;  // the parent's sign on z
    s.signs[3 * 3 + 1] = kPositive;  // this vertex's on y
    EXPECT_EQ(signContext(s, 3, 1, 2), 3 * kNegative + kPositive);
    EXPECT_EQ(signContext(s, 3, 1, 0), 3 * s.signs[3] + kNoSign);
    EXPECT_EQ(signOf(5), kPositive);
    EXPECT_EQ(signOf(-1), kNegative);
    EXPECT_EQ(signOf(0), kNoSign);
    // Magnitude: bit length of the mean of the previous vertex's and the
    // parent's residuals on the axis (rounded up), at most the last context.
    s.magnitude[3 * 2 + 0] = 6;   // previous vertex (2)
    s.magnitude[3 * 1 + 0] = 9;   // parent (1)
    EXPECT_EQ(magnitudeContext(s, 3, 1, 0), bitLength((6 + 9 + 1) / 2));
    s.magnitude[3 * 2 + 1] = 100000;
    EXPECT_EQ(magnitudeContext(s, 3, 1, 1), kMagnitudeContexts - 1);
    EXPECT_EQ(magnitudeContext(s, 3, 1, 2), 0);
    EXPECT_EQ(residualGroup(0), 0);
    EXPECT_EQ(residualGroup(3), 1);
}

TEST(TreeModel, ChildCountContextsByTheParentsOwnCount) {
    CodingState s(4, false, false);
    s.begin(kNoVertex);  // 0: a root
    for (uint32_t v = 1; v < 5; ++v) s.begin(v - 1);
    s.childCountOf = {1, 2, 3, 7};
    EXPECT_EQ(&s.childCountModel(0), &s.childCount[kChildCountContexts - 1]);  // roots apart
    EXPECT_EQ(&s.childCountModel(1), &s.childCount[0]);  // parent 0 has 1 child
    EXPECT_EQ(&s.childCountModel(2), &s.childCount[1]);  // 2
    EXPECT_EQ(&s.childCountModel(3), &s.childCount[2]);  // 3
    EXPECT_EQ(&s.childCountModel(4), &s.childCount[2]);  // 7: 3 or more
}

TEST(TreeModel, TheSurfaceFrameTurnsTheNearPointsNormalUp) {
    // Near points in the plane z = x through `at`: the normal (-1, 0, 1)
    // turned onto the third axis, so a point of the plane has no third
    // component and the normal no first or second, to within the
    // rotation's rounding (a few units).
    const GridPoint at{1000, 1000, 1000};
    const GridPoint near[] = {{1010, 1000, 1010}, {1000, 1012, 1000}, {990, 1003, 990}, {1004, 990, 1004}};
    const LocalFrame frame = surfaceFrame(at, near, 4);
    int64_t inPlane[3] = {300, 200, 300};
    frame.toFrame(inPlane);
    EXPECT_LE(std::llabs(inPlane[2]), 4);
    int64_t normal[3] = {-1000, 0, 1000};
    frame.toFrame(normal);
    EXPECT_LE(std::llabs(normal[0]), 4);
    EXPECT_LE(std::llabs(normal[1]), 4);
    // Fewer than two near points: the identity.
    int64_t v[3] = {7, -8, 9};
    surfaceFrame(at, near, 1).toFrame(v);
    EXPECT_EQ(v[0], 7);
    EXPECT_EQ(v[1], -8);
    EXPECT_EQ(v[2], 9);
}

TEST(TreeModel, TheSurfaceFrameIn64BitsIsTheSameFrame) {
    // Near points as far from `at` as cells of side 2^13 allow (2^14 - 1
    // on every axis), in every sign pattern, and nearer ones: the 64-bit
    // sums turn every cross product as the 128-bit ones do.
    ASSERT_TRUE(frameIn64Bits(13));
    ASSERT_FALSE(frameIn64Bits(14));
    const int32_t far = (1 << 14) - 1;
    const GridPoint at{1 << 20, 1 << 20, 1 << 20};
    uint32_t state = 12345;
    auto offset = [&](int32_t reach) {
        state = state * 1664525u + 1013904223u;
        const int32_t r = int32_t(state >> 8) % (2 * reach + 1) - reach;
        return (state & 1) != 0 ? r : (r < 0 ? -reach : reach);  // half at the limit
    };
    for (int trial = 0; trial < 2000; ++trial) {
        const int32_t reach = trial % 2 == 0 ? far : 1 + trial % 300;
        GridPoint near[kNearest];
        for (GridPoint& q : near) q = {at.x + offset(reach), at.y + offset(reach), at.z + offset(reach)};
        for (int m = 0; m <= kNearest; ++m) {
            const LocalFrame wide = surfaceFrame(at, near, m), narrow = surfaceFrame(at, near, m, 13);
            static const int64_t kProbes[3][3] = {{1000, 0, 0}, {0, 1000, 0}, {0, 0, 1000}};
            for (const auto& probe : kProbes) {
                int64_t a[3] = {probe[0], probe[1], probe[2]}, b[3] = {probe[0], probe[1], probe[2]};
                wide.toFrame(a);
                narrow.toFrame(b);
                ASSERT_EQ(a[0], b[0]);
                ASSERT_EQ(a[1], b[1]);
                ASSERT_EQ(a[2], b[2]);
            }
        }
    }
}

TEST(TreeModel, RoughBitsAndTheFramesAdvantage) {
    EXPECT_EQ(roughBits(GridPoint{0, 0, 0}), 0);
    EXPECT_EQ(roughBits(GridPoint{1, 0, 0}), 2);     // length 1 and a sign
    EXPECT_EQ(roughBits(GridPoint{-5, 4, 0}), 4 + 4);
    EXPECT_EQ(frameAdvantage(LocalFrame(), GridPoint{3, -7, 2}), 0);  // the identity gains nothing
    // A frame whose normal is the edge: two components vanish.
    EXPECT_GT(frameAdvantage(LocalFrame(5, 5, 0), GridPoint{500, 500, 0}), 0);
    EXPECT_TRUE(framed(true, 0));
    EXPECT_FALSE(framed(true, 1));
    EXPECT_FALSE(framed(false, 0));
}

TEST(TreeModel, KeptResidualCostsAreTheModelsPrices) {
    CodingState s(4, false, false);
    const ResidualCosts& kept = s.residualCosts(1, 2, 3);
    EXPECT_DOUBLE_EQ(kept(37), ResidualCosts(s.axis[1][2], 3)(37));
    // The models learn; the kept prices follow once a residual is counted
    // as coded in that context.
    for (int i = 0; i < 100; ++i) s.axis[1][2].zero[3].observe(1);
    ++s.residualsCoded[1][2][3];
    EXPECT_DOUBLE_EQ(s.residualCosts(1, 2, 3)(0), ResidualCosts(s.axis[1][2], 3)(0));
    EXPECT_DOUBLE_EQ(s.residualCosts(1, 2, 3)(37), ResidualCosts(s.axis[1][2], 3)(37));
    EXPECT_FALSE(s.frameNow());  // no frame allowed
    CodingState framedState(4, false, true);
    EXPECT_FALSE(framedState.frameNow());  // allowed, but no score yet
    framedState.frameScore = 1;
    EXPECT_TRUE(framedState.frameNow());
}

}  // namespace
}  // namespace tree_coding
}  // namespace drm
