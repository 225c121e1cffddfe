// CRC-32 as used by zip, PNG and Ethernet (IEEE 802.3: reflected, polynomial
// 0xEDB88320, initial value and final xor 0xFFFFFFFF). The file format uses
// it to tell corrupt data from a decoding bug.
#ifndef DRM_CRC32_H
#define DRM_CRC32_H

#include <cstddef>
#include <cstdint>

namespace drm {

// The CRC of data, continuing from the CRC of what came before it:
// crc32(b, nb, crc32(a, na)) == crc32 of a followed by b. Start with 0.
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

}  // namespace drm

#endif  // DRM_CRC32_H
