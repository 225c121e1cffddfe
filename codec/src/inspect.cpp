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
    stats.vertices = header.vertexCount;
    stats.faces = header.faceCount;
    stats.components = header.startTriangles.size() / 3;
    stats.bits = header.grid.bits;
    stats.predictor = header.predictor;
    stats.curvature = header.curvature;
    stats.levers = header.levers;
    stats.geometry = header.geometryCoder;
    if (header.geometryCoder == GeometryCoder::Refine)
        stats.refineBits = readRefinePayload(parts.geometry, parts.geometrySize, header.grid.bits).lowBits;
    stats.headerBytes = parts.headerBytes;
    stats.connectivityBytes = parts.connectivitySize;
    stats.geometryBytes = parts.geometrySize;
    stats.vertexOrderBytes = parts.vertexOrderSize;
    stats.repairBytes = parts.repairsSize;
    stats.splitVertices = header.copyCount;
    for (const FileParts::Payload& p : parts.attributes)
        stats.attributeSizes.push_back({attributeSectionName(p.data, p.size), p.size});
    stats.attributeBytes = parts.attributes.empty() ? 0 : parts.attributeBytes;
    stats.totalBytes = size;
    return info;
}

}  // namespace drm
