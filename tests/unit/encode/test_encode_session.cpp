// What the encoder's attempts share (encode/encode_session.h): the second
// thread and the search threads follow EncodeOptions::threads (0: as the
// machine allows), and the limits on early connectivity are ordered as
// their use needs (a section beside the early connectivity is narrowed
// only on meshes that have one).
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "encode/encode_session.h"

namespace drm {
namespace {

TEST(EncodeSession, ThreadsFollowTheOptions) {
    EncodeOptions o;
    o.threads = 1;
    EXPECT_FALSE(secondThreadAllowed(o));
    EXPECT_EQ(threadsFor(o), 1);
    o.threads = 2;
    EXPECT_TRUE(secondThreadAllowed(o));
    EXPECT_EQ(threadsFor(o), 2);
    o.threads = 7;
    EXPECT_TRUE(secondThreadAllowed(o));
    EXPECT_EQ(threadsFor(o), 7);
    o.threads = 0;  // as the machine allows
    const unsigned cores = std::thread::hardware_concurrency();
    EXPECT_EQ(secondThreadAllowed(o), cores > 1);
    EXPECT_EQ(threadsFor(o), int(std::max(1u, cores)));
}

TEST(EncodeSession, LimitsAreOrdered) {
    EXPECT_LT(kSectionThreadsBesideUpToVertices, kEarlyConnectivityUpToVertices);
    const ComponentStarts starts;
    EXPECT_EQ(starts.order, ComponentStarts::Order::SmallestVertices);
    EXPECT_EQ(starts.firstVertex, kNoVertex);
}

}  // namespace
}  // namespace drm
