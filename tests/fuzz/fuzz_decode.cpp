// libFuzzer target: drm::decode on arbitrary bytes.
//
// drmcodec.h promises that decode throws drm::Error for bad data and never
// crashes or reads out of bounds. So drm::Error is the only exception caught
// here: anything else escapes and libFuzzer reports it, as it reports
// AddressSanitizer and UndefinedBehaviorSanitizer findings, timeouts and
// allocations past -malloc_limit_mb. Two more promises are checked and abort
// when broken: error messages say what kind of failure they are, and a
// returned mesh only refers to vertices it has.
//
// section_mutator.cpp keeps most mutated inputs' checksums valid, so that
// mutations reach the header, rank and geometry decoders.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "decode_checks.h"
#include "drmcodec/drmcodec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const drm::Decoded decoded = drm::decode(data, size);
        const std::string problem = drm_test::decodedMeshProblem(decoded);
        if (!problem.empty()) {
            std::fprintf(stderr, "drm::decode returned a malformed mesh: %s\n", problem.c_str());
            std::abort();
        }
    } catch (const drm::Error& e) {
        if (!drm_test::isDecodeRefusal(e)) {
            std::fprintf(stderr, "drm::Error of kind %s: \"%s\"\n", drm::errorKindName(e.kind()), e.what());
            std::abort();
        }
    }
    return 0;
}
