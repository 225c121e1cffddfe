// The spanning-tree vertex coder's decoder (docs/format.md, "Geometry
// payload, coder 2: spanning tree"): the tree walked in the order the
// encoder wrote it, each vertex read through the same coding functions
// (tree_coding.h).
#include "geometry/tree/tree_coder.h"

#include <string>

#include "entropy/range_coder.h"
#include "geometry/tree/spanning_tree.h"
#include "geometry/tree/tree_coding.h"
#include "mesh/quantize.h"

namespace drm {

using namespace tree_coding;

std::vector<int32_t> decodeGeometryTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    // Every vertex but a root codes at least four adaptive decisions (three
    // residual zero flags and a child count; a predictor choice too, unless
    // every candidate repeats the parent). No binary model gives a decision
    // a probability above 4095/4096, and a table of k symbols none above
    // 1 - (k-1)/65568, so a vertex costs at least ~0.0012 bits: at most
    // ~6500 vertices per byte. A count far beyond that is refused before
    // anything is allocated.
    constexpr uint64_t kMaxVerticesPerByte = 8192;
    if (vertexCount > (uint64_t(size) + 8) * kMaxVerticesPerByte)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(vertexCount) + " vertices cannot fit in a geometry section of " +
                    std::to_string(size) + " bytes");
    const size_t n = size_t(vertexCount);
    const int32_t top = gridMax(bits);
    RangeDecoder coder(data, size);
    Reader io{coder};
    const int cellBits = int(coder.decodeBits(kCellBitsWidth));
    const bool flagChoices = coder.decodeBits(1) == 1;
    const bool frame = coder.decodeBits(1) == 1;
    if (cellBits > bits) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section's cell size is larger than the grid");
    // The count is only a claim until the stream delivers the vertices:
    // tables grow as they are decoded, so a short or garbage section fails
    // before memory is committed to it.
    CodingState s(cellBits, flagChoices, frame);
    // Room for as many vertices as the section holds at four bits each (the
    // corpus takes 5.8 to 33 bits), up to 4M: tables sized once are not
    // copied as they grow, and touch half the pages. A corrupt count can so
    // reserve (not touch) about 200 MB at most; past that, tables grow as
    // vertices are decoded.
    constexpr size_t kMostReserved = size_t(1) << 22;
    const size_t initial = std::min({n, std::max<size_t>(size_t(1) << 16, 2 * size), kMostReserved});
    s.pos.reserve(initial);
    s.parentOf.reserve(initial);
    s.magnitude.reserve(3 * initial);
    s.signs.reserve(3 * initial);
    s.childCountOf.reserve(initial);
    s.cells.reserve(initial);
    TreeWalk walk;
    uint64_t promised = 0;  // children announced but not yet decoded
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t parent = walk.enter();
        s.begin(parent);
        GridPoint at;
        if (parent == kNoVertex) {
            if (promised != 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry tree is inconsistent");
            const int32_t x = int32_t(coder.decodeWideBits(bits));  // in order: x, y, z
            const int32_t y = int32_t(coder.decodeWideBits(bits));
            const int32_t z = int32_t(coder.decodeWideBits(bits));
            at = {x, y, z};
        } else {
            --promised;
            at = codeChild(io, s, self, parent, GridPoint{});
            if (at.x < 0 || at.y < 0 || at.z < 0 || at.x > top || at.y > top || at.z > top)
                throw Error(ErrorKind::Corrupt, "corrupt file: geometry vertex " + std::to_string(self) + " falls outside the grid");
        }
        s.place(self, at);
        const uint32_t childCount = codeChildCount(io, s, self, 0);
        promised += childCount;
        if (promised > n - 1 - self)
            throw Error(ErrorKind::Corrupt, "corrupt file: geometry vertex " + std::to_string(self) + " announces more children than remain");
        walk.expect(self, childCount);
        if (coder.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section ends early");
    }
    if (promised != 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section ends inside the tree");
    std::vector<int32_t> grid(3 * n);
    for (size_t v = 0; v < n; ++v) {
        grid[3 * v] = s.pos[v].x;
        grid[3 * v + 1] = s.pos[v].y;
        grid[3 * v + 2] = s.pos[v].z;
    }
    return grid;
}

}  // namespace drm
