// The lossless check shared by `drm verify` and `drm bench`.
#ifndef DRM_TOOLS_LOSSLESS_CHECK_H
#define DRM_TOOLS_LOSSLESS_CHECK_H

#include <drm/drm.h>

#include <string>

namespace drm {
namespace cli {

// Empty if `decoded` is `input` exactly, up to quantization: the decoded grid
// coordinates equal encode's `quantized` permuted by `vertexOrder`, and the
// decoded faces, mapped through vertexOrder, are the input's oriented faces
// (same multiset, each compared up to rotation). Otherwise the first
// difference, as a sentence.
std::string findLosslessMismatch(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_LOSSLESS_CHECK_H
