// The encoder's strategy (encode/attempt_plan.h) as its header states it:
// Auto chooses the connectivity coder unless an option only the ranks
// have is set; a mesh with hubs goes to the topological coder alone, as
// does ConnectivityCoder::Topological, unless the ranks are the fallback;
// the first vertex section is the spanning tree unless another coder (or
// refine with its low bits) is asked for; the connectivity is coded early
// only beside a second thread, for a coder that orders the vertices.
#include <gtest/gtest.h>

#include <cstdint>

#include "encode/attempt_plan.h"
#include "test_meshes.h"

namespace drm {
namespace {

TEST(AttemptPlan, AutoChoosesTheCoderUnlessOnlyTheRanksCanDoWhatIsAsked) {
    const Mesh sphere = drm_test::icosphere(2);
    EXPECT_TRUE(planAttempts(sphere, EncodeOptions()).coderChosen);
    struct Ask {
        const char* what;
        void (*set)(EncodeOptions&);
    };
    const Ask asks[] = {
        {"a geometry coder", [](EncodeOptions& o) { o.geometry = GeometryCoder::Raw; }},
        {"a predictor", [](EncodeOptions& o) { o.predictor = Predictor::Midpoint; }},
        {"curvature", [](EncodeOptions& o) { o.curvature = true; }},
        {"parts", [](EncodeOptions& o) { o.connectivityParts = 1; }},
        {"levers", [](EncodeOptions& o) { o.levers.gapClosing = false; }},
        {"the ranks", [](EncodeOptions& o) { o.connectivity = ConnectivityCoder::Ranks; }},
    };
    for (const Ask& a : asks) {
        EncodeOptions o;
        a.set(o);
        const AttemptPlan plan = planAttempts(sphere, o);
        EXPECT_FALSE(plan.coderChosen) << a.what;
        EXPECT_TRUE(plan.ranks) << a.what;
        EXPECT_FALSE(plan.hubs) << a.what;
    }
    // After the topological coder gave up, the ranks alone.
    const AttemptPlan fallback = planAttempts(sphere, EncodeOptions(), true);
    EXPECT_FALSE(fallback.coderChosen);
    EXPECT_TRUE(fallback.ranks);
}

TEST(AttemptPlan, HubsAndTheTopologicalCoderGoAlone) {
    const Mesh hub = drm_test::fan(3000);
    const AttemptPlan plan = planAttempts(hub, EncodeOptions());
    EXPECT_TRUE(plan.coderChosen);
    EXPECT_TRUE(plan.hubs);
    EXPECT_FALSE(plan.ranks);
    EncodeOptions ranks;
    ranks.connectivity = ConnectivityCoder::Ranks;
    EXPECT_TRUE(planAttempts(hub, ranks).ranks);
    EXPECT_FALSE(planAttempts(hub, ranks).hubs);
    EXPECT_TRUE(planAttempts(hub, EncodeOptions(), true).ranks);
    EncodeOptions topological;
    topological.connectivity = ConnectivityCoder::Topological;
    const Mesh sphere = drm_test::icosphere(2);
    EXPECT_FALSE(planAttempts(sphere, topological).ranks);
    EXPECT_FALSE(planAttempts(sphere, topological).coderChosen);
    EXPECT_TRUE(planAttempts(sphere, topological, true).ranks);
}

TEST(AttemptPlan, TheFirstVertexSection) {
    const Mesh sphere = drm_test::icosphere(2);
    struct Case {
        GeometryCoder asked;
        int refineBits;
        GeometryCoder first;
        int lowBits;
    };
    const Case cases[] = {
        {GeometryCoder::Auto, 0, GeometryCoder::SpanningTree, 0},
        {GeometryCoder::SpanningTree, 0, GeometryCoder::SpanningTree, 0},
        {GeometryCoder::Refine, 0, GeometryCoder::SpanningTree, 0},  // low bits left to the encoder
        {GeometryCoder::Refine, 3, GeometryCoder::Refine, 3},
        {GeometryCoder::Raw, 0, GeometryCoder::Raw, 0},
        {GeometryCoder::Sorted, 0, GeometryCoder::Sorted, 0},
    };
    for (const Case& c : cases) {
        EncodeOptions o;
        o.geometry = c.asked;
        o.refineBits = c.refineBits;
        const AttemptPlan plan = planAttempts(sphere, o);
        EXPECT_EQ(plan.firstCoder, c.first) << geometryCoderName(c.asked);
        EXPECT_EQ(plan.firstLowBits, c.lowBits) << geometryCoderName(c.asked);
    }
}

TEST(AttemptPlan, EarlyConnectivityNeedsASecondThreadAndACoderThatOrders) {
    const Mesh sphere = drm_test::icosphere(2);
    EncodeOptions two;
    two.threads = 2;
    EXPECT_TRUE(planAttempts(sphere, two).earlyConnectivity);
    EXPECT_EQ(planAttempts(sphere, two).firstSectionThreads, 2);  // a small mesh keeps its threads
    EncodeOptions one;
    one.threads = 1;
    EXPECT_FALSE(planAttempts(sphere, one).earlyConnectivity);
    EncodeOptions raw = two;
    raw.geometry = GeometryCoder::Raw;  // keeps the input's order: nothing to guess
    EXPECT_FALSE(planAttempts(sphere, raw).earlyConnectivity);
    EncodeOptions refine = two;
    refine.geometry = GeometryCoder::Refine;
    refine.refineBits = 2;  // a coarse grid first
    EXPECT_FALSE(planAttempts(sphere, refine).earlyConnectivity);
    EncodeOptions topological = two;
    topological.connectivity = ConnectivityCoder::Topological;  // no ranked attempt at all
    EXPECT_FALSE(planAttempts(sphere, topological).earlyConnectivity);
}

}  // namespace
}  // namespace drm
