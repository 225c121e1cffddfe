#include "geometry/geometry_coders.h"

#include "geometry/raw_coder.h"
#include "geometry/sorted_coder.h"

namespace drm {
namespace {

// Raw: every coordinate in `bits` bits; the decoded order is the input's.
GeometryEncoding encodeRaw(const std::vector<int32_t>& grid, int bits, NeighbourIndex, GeometryTreeTrials*, int) {
    GeometryEncoding out;
    out.bytes = packGrid(grid, bits);
    out.order.resize(grid.size() / 3);
    for (size_t v = 0; v < out.order.size(); ++v) out.order[v] = uint32_t(v);
    return out;
}
VertexSet decodeRaw(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    VertexSet out;
    out.grid = unpackGrid(data, size, vertexCount, bits);
    return out;
}

// Sorted: the points in Morton order, as gaps (sorted_coder.h).
GeometryEncoding encodeSorted(const std::vector<int32_t>& grid, int bits, NeighbourIndex, GeometryTreeTrials*, int) {
    GeometryEncoding out;
    out.bytes = encodeSortedPoints(grid, bits, out.order);
    return out;
}
VertexSet decodeSorted(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    VertexSet out;
    out.grid = decodeSortedPoints(data, size, vertexCount, bits);
    return out;
}

// SpanningTree: one pass (tree_coder.h), the smaller of its two trees,
// flags naming the predictors, the local frame allowed. On meshes of up to
// kEveryTreeCodingUpTo vertices, which encode in a fraction of a second,
// the trees are also grown and coded with one symbol per choice, and each
// way without the frame, the smallest section kept: one symbol per choice
// wins on some scans, no frame on some CAD meshes and terrains; a large
// mesh would take four times as long (docs/tuning.md).
constexpr size_t kEveryTreeCodingUpTo = 32768;
// On those meshes the cheapest-first tree is also grown over each vertex's
// 8, 2 and 16 nearest neighbours (TreeNeighbours), not only its 4 nearest:
// which count codes smallest differs from mesh to mesh. Below
// kOtherCountsEveryWayBelow vertices, the 8 and 2 nearest under the first
// way, and the count of the three that codes smallest there under every
// other way; from there, under the best way only, which on the corpus's
// meshes of 16,384 to 32,768 vertices gives the same files for fewer trees
// grown (docs/tuning.md). (From 16,384 vertices a spanning tree far behind is
// also given up, against the cheapest-first tree coded the same way:
// under every way, that could be a tree over another count, and a
// spanning tree given up against it might have ended smaller than the
// tree over the 4 nearest.) The 16 nearest, whose tree
// prices several times as many neighbours a step, under the best way only
// (chosen among the others under the first way, 16 can win there and lose
// under the other ways).
constexpr size_t kOtherCountsEveryWayBelow = 16384;
TreeNeighbours treeNeighboursFor(size_t vertices) {
    if (vertices < kOtherCountsEveryWayBelow) return TreeNeighbours::SeveralEveryWay;
    return vertices <= kEveryTreeCodingUpTo ? TreeNeighbours::Several : TreeNeighbours::FourUnlessRegular;
}
GeometryEncoding encodeTree(const std::vector<int32_t>& grid, int bits, NeighbourIndex index,
                            GeometryTreeTrials* trials, int threads) {
    const bool small = grid.size() / 3 <= kEveryTreeCodingUpTo;
    return encodeGeometryTree(grid, bits, index, GeometryTree::Smaller, small ? ChoiceCoding::Smaller : ChoiceCoding::Flags,
                              small ? FrameUse::Smaller : FrameUse::On, trials, threads, treeNeighboursFor(grid.size() / 3));
}
// Refine's coarse grid: candidates pile up on it, and a tree grown and
// coded with one symbol per choice often wins: both are tried.
GeometryEncoding encodeRefineCoarse(const std::vector<int32_t>& grid, int bits, NeighbourIndex index,
                                    GeometryTreeTrials* trials, int threads) {
    return encodeGeometryTree(grid, bits, index, GeometryTree::Smaller, ChoiceCoding::Smaller, FrameUse::On, trials,
                              threads, treeNeighboursFor(grid.size() / 3));
}
VertexSet decodeTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    VertexSet out;
    out.grid = decodeGeometryTree(data, size, vertexCount, bits);
    return out;
}

// Refine: the coarse grid by the spanning tree inside the refine payload,
// the low bits after the connectivity (refine_coder.h).
VertexSet decodeRefineCoarse(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    VertexSet out;
    out.refinement = readRefinePayload(data, size, bits);
    out.lowBits = out.refinement.lowBits;
    out.grid = decodeGeometryTree(out.refinement.tree, out.refinement.treeSize, vertexCount, bits - out.lowBits);
    return out;
}
int refineBitsOfRefine(const uint8_t* data, size_t size, int bits) {
    return readRefinePayload(data, size, bits).lowBits;
}
std::vector<uint8_t> encodeRefineLowBits(const std::vector<uint8_t>& tree, const std::vector<int32_t>& fine,
                                         int lowBits, const std::vector<uint32_t>& triangles) {
    return writeRefinePayload(lowBits, encodeRefinement(fine, lowBits, triangles), tree);
}
std::vector<int32_t> decodeRefineLowBits(const VertexSet& vertices, const std::vector<int32_t>& coarse,
                                         const std::vector<uint32_t>& triangles) {
    return decodeRefinement(vertices.refinement, coarse, triangles);
}

int noRefineBits(const uint8_t*, size_t, int) { return 0; }

// Indexed by id - 1 (the ids are 1 to 4). The tree falls back to the sorted
// points, and they to raw bits (tiny sets, whose lengths cost more than
// the gaps save).
const GeometryCoderEntry kCoders[] = {
    {GeometryCoder::Raw, "raw", encodeRaw, nullptr, decodeRaw, noRefineBits, nullptr, nullptr, 0.0, true},
    {GeometryCoder::SpanningTree, "tree", encodeTree, &kCoders[3], decodeTree, noRefineBits, nullptr, nullptr},
    // Refine's own fallback, the spanning tree alone, is one of the low-bit
    // counts the encoder tries (encodeConnectivity), not a section swap.
    {GeometryCoder::Refine, "refine", encodeRefineCoarse, nullptr, decodeRefineCoarse, refineBitsOfRefine,
     encodeRefineLowBits, decodeRefineLowBits},
    // Tried only where the tree spends 16 bits a vertex or more: it wins
    // only well above that, and its sort and coding take encoding time
    // (docs/tuning.md).
    {GeometryCoder::Sorted, "sorted", encodeSorted, &kCoders[0], decodeSorted, noRefineBits, nullptr, nullptr, 16.0},
};
constexpr size_t kCoderCount = sizeof kCoders / sizeof kCoders[0];

}  // namespace

const GeometryCoderEntry* geometryCoderById(uint8_t id) {
    if (id < 1 || id > kCoderCount) return nullptr;
    const GeometryCoderEntry* entry = &kCoders[id - 1];
    return uint8_t(entry->id) == id ? entry : nullptr;
}

const GeometryCoderEntry* geometryCoderByName(const std::string& name) {
    for (const GeometryCoderEntry& entry : kCoders)
        if (name == entry.name) return &entry;
    return nullptr;
}

const std::vector<const GeometryCoderEntry*>& geometryCoders() {
    static const std::vector<const GeometryCoderEntry*> listed = {
        geometryCoderOf(GeometryCoder::SpanningTree), geometryCoderOf(GeometryCoder::Refine),
        geometryCoderOf(GeometryCoder::Sorted), geometryCoderOf(GeometryCoder::Raw)};
    return listed;
}

}  // namespace drm
