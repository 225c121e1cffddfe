// Decoder (paper, Table 2): read the vertex set, then replay the traversal,
// turning each rank back into the vertex that closes the triangle.
#include <algorithm>
#include <memory>
#include <string>

#include "attribute_sections.h"
#include "decoder.h"
#include "file_format.h"
#include "geometry_raw.h"
#include "geometry_refine.h"
#include "geometry_tree.h"
#include "edge_model.h"
#include "progress.h"
#include "quantize.h"
#include "rank_coder.h"
#include "repair_section.h"
#include "traversal.h"
#include "vertex_order.h"
#include "spatial_index.h"

namespace drm {

Decoded decodeCore(const uint8_t* data, size_t size, const DecodeOptions& options, FileParts* partsOut) {
    ProgressReporter progress(options.progress);
    progress.stage("reading", 0.0);
    FileParts& parts = *partsOut;
    parts = readFile(data, size);
    const FileHeader& header = parts.header;

    Decoded result;
    result.grid = header.grid;
    progress.stage("decoding vertices", 0.01);
    // Refine: the coarse grid now (the connectivity is ranked on it), the
    // low bits after the connectivity.
    RefinePayload refine;
    if (header.geometryCoder == GeometryCoder::Refine) {
        refine = readRefinePayload(parts.geometry, parts.geometrySize, header.grid.bits);
        result.quantized = decodeGeometryTree(refine.tree, refine.treeSize, header.vertexCount,
                                              header.grid.bits - refine.lowBits);
    } else {
        result.quantized = header.geometryCoder == GeometryCoder::Raw
                               ? unpackGrid(parts.geometry, parts.geometrySize, header.vertexCount, header.grid.bits)
                               : decodeGeometryTree(parts.geometry, parts.geometrySize, header.vertexCount,
                                                    header.grid.bits);
    }

    const size_t vertexCount = size_t(header.vertexCount);
    // A mesh that was cut into manifold pieces: the traversal also sees the
    // vertex copies, and the faces repeating a vertex are not in it.
    std::unique_ptr<RepairReader> repairs;
    std::vector<uint32_t> noCopies;
    if (header.hasRepairs) {
        repairs.reset(new RepairReader(parts.repairs, parts.repairsSize, header.vertexCount, header.copyCount,
                                       header.faceCount));
        for (uint32_t original : repairs->repairs().copyOf)
            for (int k = 0; k < 3; ++k) result.quantized.push_back(result.quantized[3 * size_t(original) + k]);
    }
    const std::vector<uint32_t>& copyOf = repairs ? repairs->repairs().copyOf : noCopies;
    const size_t looseCount = repairs ? repairs->repairs().looseCount() : 0;
    const size_t duplicateCount = repairs ? repairs->duplicateCount() : 0;
    const size_t faceCount = size_t(header.faceCount) - looseCount - duplicateCount;  // the traversal's faces
    const size_t traversalVertices = vertexCount + copyOf.size();
    // The face count is only a claim until the ranks deliver the faces: the
    // tables start small and grow as faces are decoded.
    const size_t expectedFaces = std::min<size_t>(faceCount, size_t(1) << 16);
    const std::unique_ptr<SpatialIndex> candidates =
        makeSpatialIndex(result.quantized, options.index, IndexRole::Traversal);
    Traversal traversal(traversalVertices, expectedFaces, candidates.get());
    EdgeModel model(result.quantized, header.grid.bits - refine.lowBits, header.predictor, header.curvature, header.levers,
                    faceCount, *candidates, traversal);
    RankDecoder coder(parts.connectivity, parts.connectivitySize, model.contextCount());
    Stats& stats = result.stats;

    progress.stage("decoding connectivity", 0.05);
    const size_t components = header.startTriangles.size() / 3;
    for (size_t c = 0; c < components; ++c) {
        const uint32_t* start = &header.startTriangles[3 * c];
        if (traversal.triangleCount() >= faceCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: more components than the header's " + std::to_string(faceCount) + " faces");
        try {
            traversal.startComponent(start[0], start[1], start[2]);
            result.faceRank.push_back(0);
        } catch (const Error& e) {
            throw Error(ErrorKind::Corrupt, "corrupt file: component " + std::to_string(c) + ": " + e.what());
        }
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            const uint32_t rank = coder.get(model.forecast(edge).context);
            if (coder.bytesPastEnd() > 0)
                throw Error(ErrorKind::Corrupt, "corrupt file: the connectivity section ends before the last face");
            if (rank >= stats.rankHistogram.size()) {
                if (rank > traversalVertices) throw Error(ErrorKind::Corrupt, "corrupt file: rank " + std::to_string(rank) + " exceeds the vertex count");
                stats.rankHistogram.resize(size_t(rank) + 1, 0);
            }
            ++stats.rankHistogram[rank];
            if (rank == 0) {
                traversal.closeAsBoundary(edge);
                continue;
            }
            if (traversal.triangleCount() >= faceCount)
                throw Error(ErrorKind::Corrupt, "corrupt file: the connectivity section describes more than the header's " +
                            std::to_string(faceCount) + " faces");
            try {
                const uint32_t apex = model.vertexOfRank(rank, edge);
                model.resolved(apex);
                traversal.attachApex(edge, apex);
                result.faceRank.push_back(rank);
            } catch (const Error& e) {
                throw Error(ErrorKind::Corrupt, "corrupt file: face " + std::to_string(traversal.triangleCount()) + ": " + e.what());
            }
            progress.tick(0.05 + 0.9 * double(traversal.triangleCount()) / double(faceCount));
        }
    }
    if (traversal.triangleCount() != faceCount)
        throw Error(ErrorKind::Corrupt, "corrupt file: decoded " + std::to_string(traversal.triangleCount()) + " faces, the header says " +
                    std::to_string(faceCount));

    result.mesh.triangles = traversal.takeTriangles();
    if (refine.lowBits > 0) {
        progress.stage("refining vertices", 0.95);
        std::vector<uint32_t> triangles = result.mesh.triangles;
        for (uint32_t& v : triangles)
            if (v >= vertexCount) v = copyOf[v - vertexCount];
        const std::vector<int32_t> coarse(result.quantized.begin(), result.quantized.begin() + 3 * vertexCount);
        const std::vector<int32_t> fine = decodeRefinement(refine, coarse, triangles);
        std::copy(fine.begin(), fine.end(), result.quantized.begin());
    }
    if (repairs) {
        // Undo the cut: copies back to their originals, turned faces back
        // over, then the repeated faces and the faces that repeat a vertex.
        repairs->readAfterTraversal(faceCount);
        const Repairs& r = repairs->repairs();
        std::vector<uint32_t>& t = result.mesh.triangles;
        undoCut(t, r, vertexCount);
        stats.flippedFaces = uint64_t(std::count(r.flipped.begin(), r.flipped.end(), 1));
        stats.repeatedFaces = duplicateCount;
        result.faceRank.resize(t.size() / 3, 0);
        result.quantized.resize(3 * vertexCount);
    }
    if (header.keepsVertexOrder) {
        // Back to the input numbering: decoded vertex d was input vertex order[d].
        const std::vector<uint32_t> order = decodeVertexOrder(parts.vertexOrder, parts.vertexOrderSize, vertexCount);
        std::vector<int32_t> inInputOrder(result.quantized.size());
        for (size_t d = 0; d < vertexCount; ++d)
            for (int k = 0; k < 3; ++k) inInputOrder[3 * size_t(order[d]) + k] = result.quantized[3 * d + k];
        result.quantized.swap(inInputOrder);
        for (uint32_t& v : result.mesh.triangles) v = order[v];
    }
    if (!parts.attributes.empty()) {
        progress.stage("decoding attributes", 0.97);
        decodeAttributeSections(parts, result);
    }
    size_t badVertex = 0;
    if (!dequantize(result.quantized, header.grid, result.mesh.positions, &badVertex))
        throw Error(ErrorKind::Corrupt, "corrupt file: vertex " + std::to_string(badVertex) +
                    " lies outside the range of single-precision floats");

    fillStatsFromHeader(stats, parts, size);  // leaves the decoded figures (ranks, repairs, attributes) alone
    stats.vertices = result.mesh.vertexCount();  // the file's vertices, or the split ones of a welded mesh
    stats.components = components;
    stats.boundaryEdges = stats.rankHistogram.empty() ? 0 : stats.rankHistogram[0];
    stats.refineBits = refine.lowBits;
    stats.looseFaces = looseCount;
    progress.stage("done", 1.0);
    return result;
}

}  // namespace drm
