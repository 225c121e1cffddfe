// Running one codec on one mesh: sizes, best-of-N times, decoded counts.
#ifndef DRM_TOOLS_BENCH_MEASURE_H
#define DRM_TOOLS_BENCH_MEASURE_H

#include "peer.h"

#include <string>

namespace drm {
namespace peers {

struct Measurement {
    bool measured = false;          // false: the codec refused or failed; `error` says why
    std::string error;
    uint64_t totalBytes = 0;
    uint64_t connectivityBytes = 0;
    double encodeSeconds = 0;       // best of the runs
    double decodeSeconds = 0;
    DecodedCounts decoded;          // from the last decode
};

// load() once, then encode() `runs` times and decode() `runs` times, keeping
// each one's shortest steady_clock time: the least disturbed run on a shared
// machine. Exceptions become an unmeasured result with the message.
Measurement measure(Peer& peer, const drm::Mesh& mesh, int runs);

}  // namespace peers
}  // namespace drm

#endif  // DRM_TOOLS_BENCH_MEASURE_H
