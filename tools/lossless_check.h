// The lossless check shared by `drm verify` and `drm bench`.
#ifndef DRM_TOOLS_LOSSLESS_CHECK_H
#define DRM_TOOLS_LOSSLESS_CHECK_H

#include <drmcodec/drmcodec.h>

#include <string>

namespace drm {
namespace cli {

// Empty if `decoded` is `input` exactly, up to quantization: the decoded grid
// coordinates equal encode's `quantized` permuted by `vertexOrder`, and the
// decoded faces, mapped through vertexOrder, are the input's oriented faces
// (same multiset, each compared up to rotation). Otherwise the first
// difference, as a sentence.
// A mesh encoded with welding (Stats::weldedVertices > 0) has fewer decoded
// vertices: positions are then compared per corner, through faceOrder and
// faceRotation.
std::string findLosslessMismatch(const drm::Mesh& input, const drm::Encoded& encoded, const drm::Decoded& decoded);

// Empty if every attribute `options` asks to keep and `input` carries came
// back: colours, quality, face colours, face quality, materials and
// textures exactly, normals within normalAngleBound(options.normalBits),
// texture coordinates within half a quantization step of their range;
// name lists and metadata exactly. Compared per corner (and per face)
// through Encoded::faceOrder and faceRotation, reading per-vertex or
// per-corner arrays on either side, so it does not depend on how the codec
// stores them. Otherwise the first difference, as a sentence.
std::string findAttributeMismatch(const drm::Mesh& input, const drm::EncodeOptions& options,
                                  const drm::Encoded& encoded, const drm::Decoded& decoded);

// The largest angle, in degrees, between a normal and its decoded value
// that `normalBits` allows (0.2 degrees at 10 bits, as drmcodec.h states,
// doubling for each bit fewer).
double normalAngleBound(int normalBits);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_LOSSLESS_CHECK_H
