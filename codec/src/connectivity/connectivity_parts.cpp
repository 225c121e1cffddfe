#include "connectivity/connectivity_parts.h"

#include <algorithm>
#include <string>

#include "container/byte_io.h"
#include "drmcodec/drmcodec.h"

namespace drm {

std::vector<uint8_t> writeConnectivityParts(const ConnectivityParts& layout, const std::vector<uint8_t>& first,
                                            const std::vector<uint8_t>& second) {
    ByteWriter out;
    out.varint(layout.split);
    out.varint(layout.firstComponents);
    out.varint(layout.firstFaces);
    out.varint(layout.keptInSecond.size());
    int64_t last = -1;
    for (uint32_t v : layout.keptInSecond) {
        out.varint(uint64_t(int64_t(v) - last - 1));
        last = v;
    }
    out.varint(first.size());
    out.bytes(first);
    out.bytes(second);
    return std::move(out.buffer());
}

ConnectivityParts readConnectivityParts(const uint8_t* data, size_t size, uint64_t vertices, uint64_t components,
                                        uint64_t faces) {
    ByteReader in(data, size, "connectivity section");
    ConnectivityParts parts;
    if (vertices < 2) throw Error(ErrorKind::Corrupt, "corrupt file: two connectivity parts over fewer than two vertices");
    const uint64_t split = in.count("connectivity split", vertices - 1);
    if (split == 0) throw Error(ErrorKind::Corrupt, "corrupt file: the connectivity's second part starts at vertex 0");
    parts.split = uint32_t(split);
    parts.firstComponents = in.count("components of the first connectivity part", components);
    parts.firstFaces = in.count("faces of the first connectivity part", faces);
    const uint64_t secondVertices = vertices - split;
    // Each kept vertex takes a byte at least: the count is bounded by
    // what is left before anything is allocated.
    const uint64_t kept = in.count("kept vertices of the second connectivity part", std::min<uint64_t>(secondVertices, in.remaining()));
    parts.keptInSecond.reserve(size_t(kept));
    uint64_t next = 0;  // the least the next kept vertex may be
    for (uint64_t k = 0; k < kept; ++k) {
        const uint64_t v = next + in.count("kept vertex gap", secondVertices - 1 - next);
        parts.keptInSecond.push_back(uint32_t(v));
        next = v + 1;
        if (next == secondVertices && k + 1 < kept)
            throw Error(ErrorKind::Corrupt, "corrupt file: more kept vertices than the second connectivity part has");
    }
    const uint64_t firstSize = in.count("length of the first connectivity part", in.remaining());
    parts.first = in.bytes(size_t(firstSize), "first connectivity part");
    parts.firstSize = size_t(firstSize);
    parts.secondSize = in.remaining();
    parts.second = in.bytes(parts.secondSize, "second connectivity part");
    return parts;
}

}  // namespace drm
