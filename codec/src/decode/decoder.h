// The decoder (decoder.cpp): the whole file, attributes included; the
// parts of the file are left in *parts for callers that check more.
#ifndef DRM_DECODER_H
#define DRM_DECODER_H

#include "drmcodec/drmcodec.h"
#include "container/file_format.h"

namespace drm {

Decoded decodeCore(const uint8_t* data, size_t size, const DecodeOptions& options, FileParts* parts);

}  // namespace drm

#endif  // DRM_DECODER_H
