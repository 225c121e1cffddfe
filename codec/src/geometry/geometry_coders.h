// The geometry coders, one table keyed by the id the header stores (the
// geometry coder byte, docs/format.md). The encoder, the decoder, the file
// reader, inspect() and the name parser all go through it, so a new coder
// is a new file and one more row here, not an edit of each of them.
//
// A coder codes the vertex set in at most two passes around the
// connectivity: before it, the grid the connectivity is ranked on (and the
// decoded vertex order); after it, optionally, what it codes across the
// decoded triangles (Refine's low bits).
#ifndef DRM_GEOMETRY_CODERS_H
#define DRM_GEOMETRY_CODERS_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "geometry/refine_coder.h"
#include "geometry/tree/tree_coder.h"

namespace drm {

// What the decoder has from a geometry section before the connectivity.
struct VertexSet {
    std::vector<int32_t> grid;  // 3 per vertex, decoded order: the grid the connectivity is ranked on
    int lowBits = 0;            // bits per coordinate still to come after the connectivity
    RefinePayload refinement;   // where they are (when lowBits > 0)
};

struct GeometryCoderEntry {
    GeometryCoder id;  // the byte the header stores
    const char* name;  // geometryCoderName / parseGeometryCoder: "tree", "refine", "sorted", "raw"

    // Encoder, first pass: grid holds the coordinates to code (3 per vertex,
    // input order) at `bits` bits. The section bytes and the decoded order.
    // `trials` (may be null) carries a tree coder's work on the same grid
    // from one call to the next (GeometryTreeTrials).
    GeometryEncoding (*encode)(const std::vector<int32_t>& grid, int bits, NeighbourIndex index,
                               GeometryTreeTrials* trials, int threads);
    // The coder whose section the encoder keeps instead when it is no larger
    // (scattered points predict no better than raw bits), or nullptr.
    const GeometryCoderEntry* fallback;

    // Decoder, first pass, in the syntax of the file's format version;
    // throws Error (Corrupt) on a malformed section.
    VertexSet (*decode)(const uint8_t* data, size_t size, uint64_t vertexCount, int bits);
    // The low bits coded after the connectivity, read from the section
    // without decoding it (inspect); 0 for a coder with one pass.
    int (*refineBits)(const uint8_t* data, size_t size, int bits);

    // The second pass, nullptr for a coder with one. Encoder: the whole
    // section from the first pass's bytes, the full grid (decoded order)
    // and the triangles in the order the decoder rebuilds them (vertex
    // copies replaced by their originals).
    std::vector<uint8_t> (*encodeAfterConnectivity)(const std::vector<uint8_t>& firstPass,
                                                    const std::vector<int32_t>& fine, int lowBits,
                                                    const std::vector<uint32_t>& triangles);
    // Decoder: the full grid from the first pass's grid (coarse) and the
    // decoded triangles.
    std::vector<int32_t> (*decodeAfterConnectivity)(const VertexSet& vertices, const std::vector<int32_t>& coarse,
                                                    const std::vector<uint32_t>& triangles);
    // As a fallback, tried only where the section it would replace spends
    // at least this many bits a vertex (0: always).
    double triedFromBitsPerVertex = 0;
    // Its decoded order is the input's (raw bits): the connectivity then
    // keeps that numbering (kFlagSectionNumbering), so that decode() gives
    // the vertices back in input order, as documented for this coder.
    bool keepsInputOrder = false;
};

// nullptr for an id no coder has (file_format refuses the file as
// Unsupported, encode() the options as InvalidInput).
const GeometryCoderEntry* geometryCoderById(uint8_t id);
inline const GeometryCoderEntry* geometryCoderOf(GeometryCoder coder) { return geometryCoderById(uint8_t(coder)); }
// nullptr for a name no coder has.
const GeometryCoderEntry* geometryCoderByName(const std::string& name);

// Every coder, in the order the help and error messages list them (the
// default first).
const std::vector<const GeometryCoderEntry*>& geometryCoders();

}  // namespace drm

#endif  // DRM_GEOMETRY_CODERS_H
