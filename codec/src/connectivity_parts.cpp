#include "connectivity_parts.h"

#include <string>

#include "container.h"
#include "drm/drm.h"

namespace drm {

std::vector<uint8_t> writeConnectivityParts(uint32_t split, uint64_t firstComponents, uint64_t firstFaces,
                                            const std::vector<uint8_t>& first, const std::vector<uint8_t>& second) {
    ByteWriter out;
    out.varint(split);
    out.varint(firstComponents);
    out.varint(firstFaces);
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
    const uint64_t firstSize = in.count("length of the first connectivity part", in.remaining());
    parts.first = in.bytes(size_t(firstSize), "first connectivity part");
    parts.firstSize = size_t(firstSize);
    parts.secondSize = in.remaining();
    parts.second = in.bytes(parts.secondSize, "second connectivity part");
    return parts;
}

}  // namespace drm
