// Decodes damaged inputs and checks each outcome against what drmcodec.h
// promises, counting failures instead of stopping at the first, so one run
// reports how many of thousands of inputs misbehave and names the first few.
#ifndef DRM_TEST_VERDICTS_H
#define DRM_TEST_VERDICTS_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm_test {

using Bytes = std::vector<uint8_t>;

// What one decode did. Exactly one of these holds: it threw drm::Error
// (kind, message, and whether that kind is one decode may throw), threw
// something else (foreign), or returned (meshProblem is "" for a
// well-formed mesh).
struct Outcome {
    bool threw = false;
    drm::ErrorKind kind = drm::ErrorKind::Internal;
    bool decodeRefusal = false;
    std::string message;
    std::string foreign;
    std::string meshProblem;
};

// Runs drm::decode under a watchdog that ends the process, naming label,
// if one decode takes over 20 seconds.
Outcome decodeGuarded(const Bytes& input, const std::string& label);

class Verdicts {
public:
    explicit Verdicts(std::string what) : what_(std::move(what)) {}
    ~Verdicts();  // reports the tally, and failures past the first few
    Verdicts(const Verdicts&) = delete;
    Verdicts& operator=(const Verdicts&) = delete;

    // decode must throw drm::Error of a kind a decoder may throw (Corrupt,
    // Unsupported), and, if given, of the expected kind.
    void refused(const Bytes& input, const std::string& label);
    void refused(const Bytes& input, const std::string& label, drm::ErrorKind expected);
    // decode may also return, provided the mesh is well formed: for damage
    // that no check can see, such as a changed coordinate.
    void refusedOrSound(const Bytes& input, const std::string& label);

    size_t failures() const { return failures_; }

private:
    void refusedAs(const Bytes& input, const std::string& label, const drm::ErrorKind* expected);
    bool judgeError(const Outcome& o, const std::string& label, const drm::ErrorKind* expected);
    void fail(const std::string& label, const std::string& problem);

    std::string what_;
    size_t inputs_ = 0, refusedCount_ = 0, decodedCount_ = 0, failures_ = 0;
};

}  // namespace drm_test

#endif  // DRM_TEST_VERDICTS_H
