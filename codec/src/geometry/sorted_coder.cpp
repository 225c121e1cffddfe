#include "geometry/sorted_coder.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common.h"
#include "drmcodec/drmcodec.h"
#include "spatial/morton.h"
#include "spatial/morton_order.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

// Gaps are coded as w = gap + 1, 1 .. 2^63: bit lengths 1 .. 64.
constexpr uint32_t kLengths = 64;

AdaptiveFrequencies lengthModel() { return AdaptiveFrequencies(std::vector<uint16_t>(kLengths, 1)); }

}  // namespace

std::vector<uint8_t> encodeSortedPoints(const std::vector<int32_t>& grid, int bits, std::vector<uint32_t>& order) {
    if (bits < 1 || bits > kMaxQuantizationBits)
        throw Error(ErrorKind::Internal, "internal error: sorted points at " + std::to_string(bits) + " bits");
    const size_t n = grid.size() / 3;
    order = mortonOrder(grid);
    RangeEncoder coder;
    AdaptiveFrequencies lengths = lengthModel();
    uint64_t previous = 0;
    for (size_t d = 0; d < n; ++d) {
        const uint64_t key = mortonKeyOf(&grid[3 * size_t(order[d])]);
        const uint64_t w = key - previous + 1;
        const int length = bitLength(w);
        lengths.encode(coder, uint32_t(length - 1));
        coder.encodeWideBits(w, length - 1);
        previous = key;
    }
    return coder.finish();
}

std::vector<int32_t> decodeSortedPoints(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    if (bits < 1 || bits > kMaxQuantizationBits)
        throw Error(ErrorKind::Corrupt, "corrupt file: sorted points at " + std::to_string(bits) + " bits");
    // Every vertex codes one adaptive length, which no table gives a
    // probability above 1 - 63/65536: at least ~0.0014 bits, so at most
    // ~5,800 vertices a byte. A count far beyond that is refused before
    // anything is allocated.
    constexpr uint64_t kMaxVerticesPerByte = 8192;
    if (vertexCount > (uint64_t(size) + 8) * kMaxVerticesPerByte)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(vertexCount) +
                    " vertices cannot fit in a geometry section of " + std::to_string(size) + " bytes");
    const uint64_t keyLimit = uint64_t(1) << (3 * bits);  // keys lie below; 3 * 21 < 64
    RangeDecoder coder(data, size);
    AdaptiveFrequencies lengths = lengthModel();
    std::vector<int32_t> grid;
    grid.reserve(3 * size_t(std::min<uint64_t>(vertexCount, uint64_t(1) << 22)));
    uint64_t key = 0;
    for (uint64_t d = 0; d < vertexCount; ++d) {
        const int length = int(lengths.decode(coder)) + 1;
        const uint64_t w = (uint64_t(1) << (length - 1)) | coder.decodeWideBits(length - 1);
        if (coder.bytesPastEnd() > 0)
            throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section ends before vertex " + std::to_string(d));
        const uint64_t gap = w - 1;
        if (gap >= keyLimit - key)
            throw Error(ErrorKind::Corrupt, "corrupt file: geometry vertex " + std::to_string(d) + " falls outside the grid");
        key += gap;
        grid.push_back(int32_t(gatherMortonBits(key)));
        grid.push_back(int32_t(gatherMortonBits(key >> 1)));
        grid.push_back(int32_t(gatherMortonBits(key >> 2)));
    }
    return grid;
}

}  // namespace drm
