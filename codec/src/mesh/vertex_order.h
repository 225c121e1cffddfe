// The optional vertex-order section: the permutation from the geometry
// coder's order back to the input order, for users who need their vertex
// indices kept (textures, per-vertex data stored elsewhere).
#ifndef DRM_VERTEX_ORDER_H
#define DRM_VERTEX_ORDER_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

// order[d] = input index of decoded vertex d; must be a permutation.
std::vector<uint8_t> encodeVertexOrder(const std::vector<uint32_t>& order);

// Throws Error unless the data holds a permutation of vertexCount indices.
std::vector<uint32_t> decodeVertexOrder(const uint8_t* data, size_t size, uint64_t vertexCount);

}  // namespace drm

#endif  // DRM_VERTEX_ORDER_H
