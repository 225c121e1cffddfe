// Which input face each decoded face is, and at which corner it starts:
// the decoder gives faces in traversal order, each possibly rotated, so the
// attribute coders (and Encoded::faceOrder) need the correspondence.
#ifndef DRM_FACE_CORRESPONDENCE_H
#define DRM_FACE_CORRESPONDENCE_H

#include <cstdint>
#include <vector>

namespace drm {

// input and decoded hold the same oriented triangles over the same vertex
// numbers, in any order and rotation. Fills faceOrder[i] (input face of
// decoded face i) and rotation[i] (decoded corner k = input corner
// (k + rotation[i]) % 3). Faces over the same vertices pair up in order.
// Throws Error("internal error ...") if the two do not hold the same faces.
void matchFaces(const std::vector<uint32_t>& input, const std::vector<uint32_t>& decoded,
                std::vector<uint32_t>& faceOrder, std::vector<uint8_t>& rotation);

}  // namespace drm

#endif  // DRM_FACE_CORRESPONDENCE_H
