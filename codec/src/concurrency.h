// Work the encoder runs beside its own (EncodeOptions::threads).
#ifndef DRM_CONCURRENCY_H
#define DRM_CONCURRENCY_H

#include <future>
#include <system_error>
#include <type_traits>
#include <utility>

namespace drm {

// Starts work() on a thread of its own and returns its future; where no
// thread can be had (std::async throws std::system_error), the work runs
// when the future is waited for, on the waiting thread, and gives the same
// result. The future's get() rethrows what work() threw; a future
// destroyed unread still waits for the thread, so what work() refers to
// must outlive it (declare it first).
template <class Work>
std::future<std::invoke_result_t<Work&>> startBeside(Work work) {
    try {
        return std::async(std::launch::async, work);
    } catch (const std::system_error&) {
        return std::async(std::launch::deferred, std::move(work));
    }
}

}  // namespace drm

#endif  // DRM_CONCURRENCY_H
