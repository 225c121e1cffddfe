// ProgressReporter (progress.h): a stage reports at once with its name,
// ticks report every 4096th call only (tickWith works the fraction out only
// then), a callback that says stop turns into an Error of kind Cancelled,
// no callback costs nothing and never cancels, and the fraction reported
// never falls.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "progress.h"

namespace drm {
namespace {

struct Calls {
    std::vector<std::pair<double, std::string>> seen;
    Progress callback() {
        return [this](double fraction, const char* stage) {
            seen.emplace_back(fraction, stage);
            return true;
        };
    }
};

TEST(ProgressReporter, AStageReportsAtOnce) {
    Calls calls;
    const Progress callback = calls.callback();
    ProgressReporter progress(callback);
    progress.stage("ranking", 0.25);
    progress.stage("coding", 0.5);
    ASSERT_EQ(calls.seen.size(), 2u);
    EXPECT_EQ(calls.seen[0], std::make_pair(0.25, std::string("ranking")));
    EXPECT_EQ(calls.seen[1], std::make_pair(0.5, std::string("coding")));
}

TEST(ProgressReporter, TheFractionNeverFalls) {
    Calls calls;
    const Progress callback = calls.callback();
    ProgressReporter progress(callback);
    progress.stage("first attempt", 0.05);
    progress.stage("first attempt, vertices", 0.9);
    progress.stage("second attempt", 0.05);
    progress.stage("done", 1.0);
    ASSERT_EQ(calls.seen.size(), 4u);
    EXPECT_EQ(calls.seen[2], std::make_pair(0.9, std::string("second attempt")));
    EXPECT_EQ(calls.seen[3].first, 1.0);
}

TEST(ProgressReporter, TicksReportEvery4096thCallUnderTheLastStage) {
    Calls calls;
    const Progress callback = calls.callback();
    ProgressReporter progress(callback);
    progress.stage("walking", 0);
    for (int i = 1; i <= 3 * 4096 + 5; ++i) progress.tick(double(i));
    ASSERT_EQ(calls.seen.size(), 4u);
    for (int k = 1; k <= 3; ++k) {
        EXPECT_EQ(calls.seen[size_t(k)].first, double(k * 4096));
        EXPECT_EQ(calls.seen[size_t(k)].second, "walking");
    }
}

TEST(ProgressReporter, TickWithWorksTheFractionOutOnlyWhenItReports) {
    Calls calls;
    const Progress callback = calls.callback();
    ProgressReporter progress(callback);
    int evaluated = 0;
    for (int i = 0; i < 2 * 4096; ++i)
        progress.tickWith([&evaluated] {
            ++evaluated;
            return 0.5;
        });
    EXPECT_EQ(evaluated, 2);
    EXPECT_EQ(calls.seen.size(), 2u);
}

TEST(ProgressReporter, StopIsACancelledError) {
    int called = 0;
    const Progress stop = [&called](double, const char*) {
        ++called;
        return false;
    };
    ProgressReporter progress(stop);
    for (int i = 0; i < 4095; ++i) progress.tick(0.1);  // not reported: no chance to stop
    EXPECT_EQ(called, 0);
    try {
        progress.tick(0.1);
        FAIL() << "the 4096th tick did not stop";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Cancelled);
    }
    EXPECT_THROW(progress.stage("anything", 0.9), Error);
}

TEST(ProgressReporter, NoCallbackNeverCancelsNorWorksFractionsOut) {
    const Progress none;
    ProgressReporter progress(none);
    int evaluated = 0;
    progress.stage("start", 0);
    for (int i = 0; i < 3 * 4096; ++i) {
        progress.tick(0.5);
        progress.tickWith([&evaluated] {
            ++evaluated;
            return 0.5;
        });
    }
    EXPECT_EQ(evaluated, 0);
}

}  // namespace
}  // namespace drm
