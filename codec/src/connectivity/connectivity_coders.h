// The connectivity coders a file can name: one table keyed by the id its
// header stores (the connectivity coder byte, docs/format.md). The header
// reader refuses ids the table lacks; the decoder picks its stage by the
// same id (decode/decoder.cpp).
#ifndef DRM_CONNECTIVITY_CODERS_H
#define DRM_CONNECTIVITY_CODERS_H

#include <cstdint>

#include "drmcodec/drmcodec.h"

namespace drm {

struct ConnectivityCoderEntry {
    ConnectivityCoder id;
    const char* name;  // as options and `drm info` name it
    // Its streams hold the positions as well, in the order they meet them:
    // the header's geometry coder is not used for the vertex set.
    bool codesPositions;
    // The header may split its section into two parts (connectivity_parts.h).
    bool splitsInTwoParts;
};

// The entry for an id as stored, or null.
const ConnectivityCoderEntry* connectivityCoderById(uint8_t id);
// The entry for a coder (null for ConnectivityCoder::Auto, an option only).
const ConnectivityCoderEntry* connectivityCoderOf(ConnectivityCoder coder);

}  // namespace drm

#endif  // DRM_CONNECTIVITY_CODERS_H
