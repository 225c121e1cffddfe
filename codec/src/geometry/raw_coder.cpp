#include "geometry/raw_coder.h"

#include <string>

#include "drmcodec/drmcodec.h"

namespace drm {

std::vector<uint8_t> packGrid(const std::vector<int32_t>& grid, int bits) {
    std::vector<uint8_t> out;
    out.reserve((grid.size() * size_t(bits) + 7) / 8);
    uint64_t pending = 0;
    int pendingBits = 0;
    for (int32_t q : grid) {
        pending |= uint64_t(uint32_t(q)) << pendingBits;
        pendingBits += bits;
        while (pendingBits >= 8) {
            out.push_back(uint8_t(pending));
            pending >>= 8;
            pendingBits -= 8;
        }
    }
    if (pendingBits > 0) out.push_back(uint8_t(pending));
    return out;
}

std::vector<int32_t> unpackGrid(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    const uint64_t needed = (vertexCount * 3 * uint64_t(bits) + 7) / 8;
    if (needed != size)
        throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section has " + std::to_string(size) + " bytes, but " +
                    std::to_string(vertexCount) + " vertices at " + std::to_string(bits) + " bits need " +
                    std::to_string(needed));
    std::vector<int32_t> grid(size_t(vertexCount) * 3);
    const uint64_t mask = (uint64_t(1) << bits) - 1;
    uint64_t pending = 0;
    int pendingBits = 0;
    size_t next = 0;
    for (int32_t& q : grid) {
        while (pendingBits < bits) {
            pending |= uint64_t(data[next++]) << pendingBits;
            pendingBits += 8;
        }
        q = int32_t(pending & mask);
        pending >>= bits;
        pendingBits -= bits;
    }
    return grid;
}

}  // namespace drm
