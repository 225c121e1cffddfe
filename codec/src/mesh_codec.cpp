// encode() and decode() as the library offers them: the core file
// (positions, connectivity, repairs: encoder.cpp, decoder.cpp), then the
// attribute sections over the decoded mesh, the welding of meshes with a
// vertex per corner, and the optional check of what was written.
#include <cmath>
#include <string>

#include "attributes/attribute_sections.h"
#include "decode/decoder.h"
#include "encode/encoder.h"
#include "mesh/face_correspondence.h"
#include "mesh/mesh_check.h"
#include "container/file_format.h"
#include "progress.h"
#include "mesh/quantize.h"
#include "stats.h"
#include "encode/verify.h"

namespace drm {

double maxNormalError(int normalBits) {
    // The encoder picks the best of the grid points around the folded
    // direction: measured worst case 1.41 cells (2 million random
    // directions, 4 to 16 bits); the bound allows 1.5.
    const double cell = 2.0 / double((uint32_t(1) << normalBits) - 1);
    return 1.5 * cell;
}

Encoded encode(const Mesh& mesh, const EncodeOptions& options) {
    ProgressReporter progress(options.progress);
    // Indices first: welding, vertex splitting and the corner tables all
    // index arrays by them before the connectivity coder would check them.
    checkIndices(mesh);
    checkAttributes(mesh, options);
    const uint32_t keep = attributesOf(mesh) & options.attributes;
    const Grid grid = makeGrid(mesh.positions, options.bits);  // checks bits, emptiness, finiteness
    Welding welding;
    bool welded = false;
    std::vector<int32_t> inputGrid;
    if (keep != 0) {
        inputGrid = quantize(mesh.positions, grid);
        welded = shouldWeld(mesh, inputGrid, options);
        if (welded) welding = weld(mesh, inputGrid);
    }
    const Mesh& core = welded ? welding.mesh : mesh;
    Attempt attempt = encodeConnectivity(core, options, progress, &grid);
    Encoded& result = attempt.encoded;

    std::vector<uint32_t> inInputIndices(attempt.decodedTriangles.size());
    for (size_t c = 0; c < inInputIndices.size(); ++c) inInputIndices[c] = result.vertexOrder[attempt.decodedTriangles[c]];
    matchFaces(core.triangles, inInputIndices, result.faceOrder, result.faceRotation);

    if (keep != 0) {
        progress.stage("coding attributes", 0.96);
        std::vector<int32_t> decodedGrid(3 * result.vertexOrder.size());
        for (size_t d = 0; d < result.vertexOrder.size(); ++d)
            for (int k = 0; k < 3; ++k) decodedGrid[3 * d + k] = result.quantized[3 * size_t(result.vertexOrder[d]) + k];
        DecodedLayout layout{attempt.decodedTriangles, decodedGrid, {}, result.faceOrder, result.faceRotation, welded};
        layout.vertexInput = result.vertexOrder;
        if (welded)
            for (uint32_t& v : layout.vertexInput) v = welding.representative[v];
        const AttributeEncoding attributes = encodeAttributeSections(mesh, options, layout);
        FileParts written;
        result.bytes = writeFile(attempt.header, attempt.connectivity, attempt.geometry, attempt.vertexOrder,
                                 attempt.repairs, attributes.sections, &written);
        Stats& stats = result.stats;
        fillStatsFromHeader(stats, written, result.bytes.size());  // the sizes, now with attribute sections
        stats.attributeSizes = attributes.sizes;
        if (welded) {
            result.vertexOrder = attributes.splitVertexInput;
            result.quantized = inputGrid;
            stats.weldedVertices = welding.merged();
            stats.vertices = result.vertexOrder.size();
        }
    }
    if (options.verify) {
        progress.stage("verifying", 0.98);
        const std::string mismatch = findMismatch(mesh, options, result);
        if (!mismatch.empty()) throw Error(ErrorKind::Internal, "internal error: the file written does not decode to the input: " + mismatch);
    }
    progress.stage("done", 1.0);
    return result;
}

Decoded decode(const uint8_t* data, size_t size, const Progress& progress) {
    DecodeOptions options;
    options.progress = progress;
    return decode(data, size, options);
}

Decoded decode(const uint8_t* data, size_t size, const DecodeOptions& options) {
    if (options.threads < 0)
        throw Error(ErrorKind::InvalidInput, "threads " + std::to_string(options.threads) + " is negative (0: as the machine allows)");
    FileParts parts;
    try {
        return decodeCore(data, size, options, &parts);
    } catch (const Error& e) {
        // Every refusal of a damaged file reads the same way, whichever
        // stage found the damage.
        const std::string message = e.what();
        const auto startsWith = [&message](const std::string& prefix) { return message.compare(0, prefix.size(), prefix) == 0; };
        const bool named = startsWith("corrupt file:") || startsWith("not a .drm file") || startsWith("empty file");
        if (e.kind() != ErrorKind::Corrupt || named) throw;
        throw Error(ErrorKind::Corrupt, "corrupt file: " + message);
    }
}

}  // namespace drm
