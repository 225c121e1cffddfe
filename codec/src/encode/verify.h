// EncodeOptions::verify: decode the file just written and compare it with
// the input, corner by corner, through Encoded's vertex and face orders.
#ifndef DRM_VERIFY_H
#define DRM_VERIFY_H

#include <string>

#include "drmcodec/drmcodec.h"

namespace drm {

// "" if encoded.bytes decodes to the input (grid points, oriented faces,
// attributes within their quantization), else the first difference.
std::string findMismatch(const Mesh& input, const EncodeOptions& options, const Encoded& encoded);

}  // namespace drm

#endif  // DRM_VERIFY_H
