// Each index is coded as its difference from the previous one: input orders
// and the tree order both follow the surface, so differences are mostly
// small. A difference is zigzag-mapped, then coded as its bit length (an
// adaptive symbol) and the bits below the leading one.
#include "common.h"
#include "mesh/vertex_order.h"

#include <string>

#include "drmcodec/drmcodec.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

constexpr uint32_t kLengths = 34;  // bit lengths 0..33 of zigzagged 33-bit differences

uint64_t zigzag(int64_t d) { return d >= 0 ? uint64_t(d) * 2 : uint64_t(-d) * 2 - 1; }
int64_t unzigzag(uint64_t z) { return (z & 1) ? -int64_t((z + 1) / 2) : int64_t(z / 2); }


AdaptiveFrequencies lengthModel() { return AdaptiveFrequencies(std::vector<uint16_t>(kLengths, 1)); }

}  // namespace

std::vector<uint8_t> encodeVertexOrder(const std::vector<uint32_t>& order) {
    RangeEncoder coder;
    AdaptiveFrequencies lengths = lengthModel();
    int64_t previous = -1;
    for (uint32_t index : order) {
        const uint64_t z = zigzag(int64_t(index) - previous - 1);
        const int n = bitLength(z);
        lengths.encode(coder, uint32_t(n));
        coder.encodeWideBits(z, n - 1);  // the bits below the leading one
        previous = index;
    }
    return coder.finish();
}

std::vector<uint32_t> decodeVertexOrder(const uint8_t* data, size_t size, uint64_t vertexCount) {
    std::vector<uint32_t> order(static_cast<size_t>(vertexCount));
    std::vector<uint8_t> seen(static_cast<size_t>(vertexCount), 0);
    RangeDecoder coder(data, size);
    AdaptiveFrequencies lengths = lengthModel();
    int64_t previous = -1;
    for (uint32_t& index : order) {
        const int n = int(lengths.decode(coder));
        const uint64_t z = n == 0 ? 0 : (uint64_t(1) << (n - 1)) | coder.decodeWideBits(n - 1);
        const int64_t value = previous + 1 + unzigzag(z);
        if (value < 0 || uint64_t(value) >= vertexCount || seen[size_t(value)])
            throw Error(ErrorKind::Corrupt, "corrupt file: the vertex order section is not a permutation");
        if (coder.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: the vertex order section ends early");
        seen[size_t(value)] = 1;
        index = uint32_t(value);
        previous = value;
    }
    return order;
}

}  // namespace drm
