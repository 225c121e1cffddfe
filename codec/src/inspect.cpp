// drm::inspect: what a file's header and section table say, without
// decoding a section (docs/library.md). Reads what decode() reads first
// (readFile), so it refuses the same malformed files.
#include "attributes/attribute_sections.h"
#include "drmcodec/drmcodec.h"
#include "container/file_format.h"
#include "geometry/geometry_coders.h"
#include "stats.h"

namespace drm {

FileInfo inspect(const uint8_t* data, size_t size) {
    const FileParts parts = readFile(data, size);
    const FileHeader& header = parts.header;
    FileInfo info;
    info.formatVersion = parts.formatVersion;
    info.keepsVertexOrder = header.keepsVertexOrder;
    info.hasRepairs = header.hasRepairs;
    Stats& stats = info.stats;
    fillStatsFromHeader(stats, parts, size);
    // readFile has refused any id the table lacks.
    stats.refineBits = geometryCoderOf(header.geometryCoder)->refineBits(parts.geometry, parts.geometrySize, header.grid.bits);
    for (const FileParts::Payload& p : parts.attributes)
        stats.attributeSizes.push_back({attributeSectionName(p.data, p.size), p.size});
    return info;
}

}  // namespace drm
