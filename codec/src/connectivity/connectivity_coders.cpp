#include "connectivity/connectivity_coders.h"

namespace drm {

namespace {

// Ranks: the paper's distance ranks over the traversal (ranked/), with the
// vertex set coded first by the header's geometry coder. Topological: the
// topological coder (topological/), positions in the order it meets them.
constexpr ConnectivityCoderEntry kConnectivityCoders[] = {
    {ConnectivityCoder::Ranks, "ranks", false, true},
    {ConnectivityCoder::Topological, "topological", true, false},
};

}  // namespace

const ConnectivityCoderEntry* connectivityCoderById(uint8_t id) {
    for (const ConnectivityCoderEntry& entry : kConnectivityCoders)
        if (uint8_t(entry.id) == id) return &entry;
    return nullptr;
}

const ConnectivityCoderEntry* connectivityCoderOf(ConnectivityCoder coder) {
    return coder == ConnectivityCoder::Auto ? nullptr : connectivityCoderById(uint8_t(coder));
}

}  // namespace drm
