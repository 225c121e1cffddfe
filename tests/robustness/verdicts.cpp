#include "verdicts.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <exception>

#include "decode_checks.h"
#include "drmcodec/drmcodec.h"
#include "watchdog.h"

namespace drm_test {
namespace {

// Only the first few failures of a kind are spelled out: a broken check
// can fail thousands of inputs the same way.
constexpr size_t kFailuresShown = 10;

Watchdog& watchdog() {
    static Watchdog dog(std::chrono::seconds(20), ::testing::TempDir() + "drm-decode-hang.drm");
    return dog;
}

}  // namespace

Outcome decodeGuarded(const Bytes& input, const std::string& label) {
    Outcome o;
    watchdog().arm(label, input);
    try {
        const drm::Decoded decoded = drm::decode(input);
        o.meshProblem = decodedMeshProblem(decoded);
    } catch (const drm::Error& e) {
        o.threw = true;
        o.kind = e.kind();
        o.decodeRefusal = isDecodeRefusal(e);
        o.message = e.what();
    } catch (const std::exception& e) {
        // drmcodec.h allows only drm::Error: std::bad_alloc from a size taken
        // from the file, or std::out_of_range, is a decoder bug.
        o.foreign = e.what();
    }
    watchdog().disarm();
    return o;
}

Verdicts::~Verdicts() {
    if (failures_ > kFailuresShown)
        ADD_FAILURE() << what_ << ": " << failures_ - kFailuresShown << " more failures not shown";
    std::printf("[ verdicts ] %s: %zu inputs, %zu refused, %zu decoded, %zu failures\n", what_.c_str(), inputs_,
                refusedCount_, decodedCount_, failures_);
}

void Verdicts::fail(const std::string& label, const std::string& problem) {
    if (++failures_ <= kFailuresShown) ADD_FAILURE() << what_ << ": " << label << ": " << problem;
}

bool Verdicts::judgeError(const Outcome& o, const std::string& label, const drm::ErrorKind* expected) {
    if (!o.foreign.empty()) {
        fail(label, "decode threw an exception other than drm::Error: " + o.foreign);
        return false;
    }
    if (!o.threw) return true;
    ++refusedCount_;
    if (!o.decodeRefusal)
        fail(label, std::string("decode threw an error of kind ") + drm::errorKindName(o.kind) + ": \"" + o.message +
                        "\"");
    else if (expected && o.kind != *expected)
        fail(label, std::string("decode threw an error of kind ") + drm::errorKindName(o.kind) + ", not " +
                        drm::errorKindName(*expected) + ": \"" + o.message + "\"");
    else if (o.kind == drm::ErrorKind::Corrupt && o.message.rfind("corrupt file: ", 0) != 0 &&
             o.message.rfind("not a .drm file", 0) != 0 && o.message.rfind("empty file", 0) != 0)
        fail(label, "a damaged file's message does not say so first: \"" + o.message + "\"");
    return true;
}

void Verdicts::refused(const Bytes& input, const std::string& label) { refusedAs(input, label, nullptr); }

void Verdicts::refused(const Bytes& input, const std::string& label, drm::ErrorKind expected) {
    refusedAs(input, label, &expected);
}

void Verdicts::refusedAs(const Bytes& input, const std::string& label, const drm::ErrorKind* expected) {
    ++inputs_;
    const Outcome o = decodeGuarded(input, label);
    if (!judgeError(o, label, expected) || o.threw) return;
    ++decodedCount_;
    fail(label, "decode returned instead of throwing drm::Error" +
                    (o.meshProblem.empty() ? std::string() : " (and the mesh is malformed: " + o.meshProblem + ")"));
}

void Verdicts::refusedOrSound(const Bytes& input, const std::string& label) {
    ++inputs_;
    const Outcome o = decodeGuarded(input, label);
    if (!judgeError(o, label, nullptr) || o.threw) return;
    ++decodedCount_;
    if (!o.meshProblem.empty()) fail(label, "decode returned a malformed mesh: " + o.meshProblem);
}

}  // namespace drm_test
