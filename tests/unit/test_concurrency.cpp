// startBeside (concurrency.h), the encoder's second thread: the work's
// result and its exceptions come back through the future, the work runs
// beside the caller (it can wait for the caller), and a future dropped
// unread still waits for the work, so what the work refers to may be
// declared before it and be safe.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include "concurrency.h"
#include "drmcodec/drmcodec.h"

namespace drm {
namespace {

TEST(StartBeside, GivesTheWorksResult) {
    int input = 20;
    auto future = startBeside([&input] { return input + 22; });
    EXPECT_EQ(future.get(), 42);
    auto text = startBeside([] { return std::string("beside"); });
    EXPECT_EQ(text.get(), "beside");
}

TEST(StartBeside, RethrowsWhatTheWorkThrew) {
    auto future = startBeside([]() -> int { throw Error(ErrorKind::Cancelled, "cancelled"); });
    try {
        future.get();
        FAIL() << "nothing thrown";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Cancelled);
        EXPECT_STREQ(e.what(), "cancelled");
    }
}

TEST(StartBeside, RunsBesideTheCaller) {
    // The work waits for a flag only the caller sets after starting it: a
    // work run on the caller's thread would never see it.
    std::atomic<bool> go(false);
    auto future = startBeside([&go] {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (!go.load() && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
        return go.load();
    });
    go = true;
    EXPECT_TRUE(future.get());
}

TEST(StartBeside, ADroppedFutureWaitsForTheWork) {
    std::atomic<int> done(0);
    {
        auto future = startBeside([&done] {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            done = 1;
            return 0;
        });
    }
    EXPECT_EQ(done.load(), 1);
}

}  // namespace
}  // namespace drm
