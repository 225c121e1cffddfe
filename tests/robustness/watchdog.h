// Turns a hang into a test failure that names the input.
//
// A decode that never returns would otherwise stall the test until ctest's
// timeout, with no word on which of thousands of corrupted inputs did it.
// One background thread watches the decode in progress; past the deadline
// it prints the input's label, writes its bytes to dumpPath and ends the
// process (a hung call cannot be abandoned safely any other way).
#ifndef DRM_TEST_WATCHDOG_H
#define DRM_TEST_WATCHDOG_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace drm_test {

class Watchdog {
public:
    Watchdog(std::chrono::seconds limit, std::string dumpPath)
        : limit_(limit), dumpPath_(std::move(dumpPath)), thread_([this] { watch(); }) {}
    ~Watchdog() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }

    void arm(const std::string& label, const std::vector<uint8_t>& input) {
        std::lock_guard<std::mutex> lock(mutex_);
        label_ = label;
        input_ = input;
        deadline_ = std::chrono::steady_clock::now() + limit_;
        armed_ = true;
    }
    void disarm() {
        std::lock_guard<std::mutex> lock(mutex_);
        armed_ = false;
    }

private:
    void watch() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!stop_) {
            wake_.wait_for(lock, std::chrono::milliseconds(200));
            if (!armed_ || std::chrono::steady_clock::now() < deadline_) continue;
            const char* path = dumpPath_.c_str();
            if (FILE* f = std::fopen(path, "wb")) {
                std::fwrite(input_.data(), 1, input_.size(), f);
                std::fclose(f);
            }
            std::fprintf(stderr, "\nFAILED: drm::decode ran for over %lld s on \"%s\" (input written to %s)\n",
                         static_cast<long long>(limit_.count()), label_.c_str(), path);
            std::fflush(stderr);
            std::_Exit(3);
        }
    }

    const std::chrono::seconds limit_;
    const std::string dumpPath_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    bool armed_ = false;
    std::string label_;
    std::vector<uint8_t> input_;
    std::chrono::steady_clock::time_point deadline_;
    std::thread thread_;  // last: starts once everything it reads exists
};

}  // namespace drm_test

#endif  // DRM_TEST_WATCHDOG_H
