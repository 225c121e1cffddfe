#include "measure.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <limits>

namespace drm {
namespace peers {

Measurement measure(Peer& peer, const drm::Mesh& mesh, int runs) {
    using Clock = std::chrono::steady_clock;
    auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
    Measurement result;
    try {
        peer.load(mesh);
        Compressed compressed;
        result.encodeSeconds = std::numeric_limits<double>::infinity();
        for (int run = 0; run < runs; ++run) {
            const Clock::time_point start = Clock::now();
            compressed = peer.encode();
            result.encodeSeconds = std::min(result.encodeSeconds, seconds(Clock::now() - start));
        }
        result.decodeSeconds = std::numeric_limits<double>::infinity();
        for (int run = 0; run < runs; ++run) {
            const Clock::time_point start = Clock::now();
            result.decoded = peer.decode(compressed.bytes);
            result.decodeSeconds = std::min(result.decodeSeconds, seconds(Clock::now() - start));
        }
        result.totalBytes = compressed.bytes.size();
        result.connectivityBytes = compressed.connectivityBytes;
        result.measured = true;
    } catch (const std::exception& e) {
        result = Measurement();
        result.error = e.what();
    }
    return result;
}

}  // namespace peers
}  // namespace drm
