// drm::inspect: what a file's header and section table say, without
// decoding a section (docs/library.md). Reads what decode() reads first
// (readFile), so it refuses the same malformed files.
#include "attribute_sections.h"
#include "drm/drm.h"
#include "file_format.h"
#include "geometry_refine.h"

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
    if (header.geometryCoder == GeometryCoder::Refine)
        stats.refineBits = readRefinePayload(parts.geometry, parts.geometrySize, header.grid.bits).lowBits;
    for (const FileParts::Payload& p : parts.attributes)
        stats.attributeSizes.push_back({attributeSectionName(p.data, p.size), p.size});
    return info;
}

}  // namespace drm
