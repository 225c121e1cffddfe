#include "stats.h"

#include <algorithm>

namespace drm {

void fillStatsFromHeader(Stats& stats, const FileParts& parts, size_t fileSize) {
    const FileHeader& header = parts.header;
    stats.vertices = header.vertexCount;
    stats.faces = header.faceCount;
    stats.components = header.componentCount;
    stats.bits = header.grid.bits;
    stats.predictor = header.predictor;
    stats.curvature = header.curvature;
    stats.levers = header.levers;
    stats.geometry = header.geometryCoder;
    stats.connectivity = header.connectivityCoder;
    stats.mortonNumbering = header.mortonNumbering;
    stats.connectivityParts = header.twoParts ? 2 : 1;
    stats.headerBytes = parts.headerBytes;
    stats.connectivityBytes = parts.connectivitySize;
    stats.geometryBytes = parts.geometrySize;
    stats.vertexOrderBytes = parts.vertexOrderSize;
    stats.repairBytes = parts.repairsSize;
    stats.splitVertices = header.copyCount;
    stats.attributeBytes = parts.attributes.empty() ? 0 : parts.attributeBytes;
    stats.totalBytes = fileSize;
}

void fillStatsFromTraversal(Stats& stats, int refineBits, const Repairs& repairs) {
    stats.boundaryEdges = stats.rankHistogram.empty() ? 0 : stats.rankHistogram[0];
    stats.refineBits = refineBits;
    stats.flippedFaces = uint64_t(std::count(repairs.flipped.begin(), repairs.flipped.end(), 1));
    stats.repeatedFaces = repairs.duplicateOf.size();
    stats.looseFaces = repairs.looseCount();
}

}  // namespace drm
