#include "container/crc32.h"

#include <array>

namespace drm {

namespace {

// remainder[b] is the CRC register after shifting the byte b through it,
// so each input byte costs one lookup instead of eight bit steps.
constexpr std::array<uint32_t, 256> makeTable() {
    std::array<uint32_t, 256> table{};
    for (uint32_t b = 0; b < 256; ++b) {
        uint32_t r = b;
        for (int bit = 0; bit < 8; ++bit) r = (r & 1) ? (r >> 1) ^ 0xEDB88320u : r >> 1;
        table[b] = r;
    }
    return table;
}

constexpr std::array<uint32_t, 256> kTable = makeTable();

}  // namespace

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc) {
    // The register holds the complement of the running CRC; undoing the
    // final xor on entry is what makes the function resumable.
    uint32_t r = ~crc;
    for (size_t i = 0; i < size; ++i) r = kTable[(r ^ data[i]) & 0xFFu] ^ (r >> 8);
    return ~r;
}

}  // namespace drm
