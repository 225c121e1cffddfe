// Tests of the distance ranks' own features (boundary flags, connectivity
// parts, Morton numbering, start search, levers, face ranks) encode with
// the rank coder alone: with ConnectivityCoder::Auto a small or
// sliver-rich mesh may come out topological, which has none of them.
#ifndef DRM_TEST_RANKS_ONLY_H
#define DRM_TEST_RANKS_ONLY_H

#include "drmcodec/drmcodec.h"

namespace drm_test {

inline drm::EncodeOptions ranksOnly() {
    drm::EncodeOptions options;
    options.connectivity = drm::ConnectivityCoder::Ranks;
    return options;
}

}  // namespace drm_test

#endif  // DRM_TEST_RANKS_ONLY_H
