// The optional repairs section: what the decoder needs to turn the manifold
// mesh it decodes back into the input mesh (see manifold_cut.h). Written
// only for meshes that needed a repair; a clean mesh pays nothing.
//
// One range-coded stream, in plain bits wherever a count bounds an
// allocation, so that each such value costs at least one bit and its count
// is checked against the section's length first:
//  1. the copies: the decoded index of the vertex each copy stands for, in
//     non-decreasing order (the encoder numbers copies so), as Elias-gamma
//     coded differences plus one; their count is in the header, since the
//     traversal (start triangles too) may use copies;
//  2. the faces repeating a vertex: a 32-bit count, then three decoded
//     vertex indices each, in the bits of the largest vertex index;
//  3. the count of repeated faces (32 bits);
//  -- the connectivity is decoded here: it needs 1 to 3 --
//  4. one bit saying whether any face was turned over and, if so, an
//     adaptive flip bit per traversal face, in decoded face order;
//  5. per repeated face, the decoded position of the traversal face it
//     repeats (in the bits of the largest position) and one bit, set when it
//     runs the other way round.
#ifndef DRM_REPAIR_SECTION_H
#define DRM_REPAIR_SECTION_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"

namespace drm {

struct Repairs {
    std::vector<uint32_t> copyOf;          // vertex vertexCount + k copies vertex copyOf[k]; non-decreasing
    std::vector<uint32_t> looseTriangles;  // 3 indices per face repeating a vertex
    std::vector<uint8_t> flipped;          // per traversal face, decoded order
    std::vector<uint32_t> duplicateOf;     // per repeated face: decoded position of the face it repeats
    std::vector<uint8_t> duplicateReversed;

    size_t looseCount() const { return looseTriangles.size() / 3; }
};

// The decoder's last step, which the encoder replays to know the decoded
// faces: copies back to their originals, turned faces back over, then the
// repeated faces and the faces repeating a vertex appended. traversal
// holds the traversal's faces in decoded order.
void undoCut(std::vector<uint32_t>& traversal, const Repairs& repairs, size_t vertexCount);

std::vector<uint8_t> encodeRepairs(const Repairs& repairs, uint64_t vertexCount);

// Reads the section in the order the decoder needs it: parts 1 to 3 on
// construction, 4 and 5 once the traversal's faces are known.
class RepairReader {
public:
    // Throws Error on counts the section cannot hold or indices out of range.
    RepairReader(const uint8_t* data, size_t size, uint64_t vertexCount, uint64_t copies, uint64_t faceCount);

    const Repairs& repairs() const { return repairs_; }
    size_t duplicateCount() const { return size_t(duplicates_); }
    // Reads parts 4 and 5 for a traversal of faceCount faces, then checks
    // that the section ended where it should.
    void readAfterTraversal(size_t faceCount);

private:
    RangeDecoder coder_;
    size_t size_;
    uint64_t bitsLeft_;
    uint64_t duplicates_ = 0;
    Repairs repairs_;
};

}  // namespace drm

#endif  // DRM_REPAIR_SECTION_H
