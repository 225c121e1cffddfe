// The connectivity section in two parts that decode apart (docs/format.md,
// "Two connectivity parts"), so that a decoder with two cores rebuilds
// both halves of a mesh at once.
//
// The traversal's vertices (connectivity numbering: Morton order, then any
// vertex copies) are split at an index m. Part 1 holds every face with a
// vertex below m, part 2 every other face, whose vertices all lie from m
// on. Each part is a rank stream of its own, exactly as a whole mesh's
// (start triangles, ranks, boundary codes), with its own traversal,
// candidates and models:
// - part 1 over all N vertices, with one more rule of admissibility: an
//   edge whose two ends both lie from m on closes on a vertex below m or
//   not at all (a face over three such vertices is part 2's);
// - part 2 over vertices m .. N - 1, numbered from 0 (ties still break by
//   index: the order is kept).
// The faces a part holds around a vertex on the seam may form several
// fans, and the traversal culls a vertex once its open edges run out (at
// the end of its first fan): so part 1 never culls its vertices from m
// on, and part 2 never culls the vertices the payload lists (those with
// two fans or more in part 2). Such a kept vertex may be part of an
// earlier component when a component starts. Edges along the seam are
// coded as boundary edges in both parts. The decoded faces are part 1's,
// then part 2's.
#ifndef DRM_CONNECTIVITY_PARTS_H
#define DRM_CONNECTIVITY_PARTS_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

// Meshes whose traversal codes at least this many faces are split
// (EncodeOptions::connectivityParts 0). Below it decoding is quick anyway,
// and the seam's boundary codes and the second part's learning weigh more.
constexpr size_t kTwoPartsFromFaces = 32768;

struct ConnectivityParts {
    uint32_t split = 0;            // m: part 2's vertices are m .. N - 1
    uint64_t firstComponents = 0;  // part 2 has the rest of the header's
    uint64_t firstFaces = 0;       // part 2 has the rest of the traversal's
    std::vector<uint32_t> keptInSecond;  // part 2's vertices never culled, increasing, numbered from 0
    const uint8_t* first = nullptr;
    size_t firstSize = 0;
    const uint8_t* second = nullptr;
    size_t secondSize = 0;
};

// The payload: varints m, part 1's components, part 1's faces, the count
// of part 2's kept vertices and each as its gap from the one before (the
// first from -1, less one), part 1's byte count; then part 1's bytes and
// part 2's (the rest).
std::vector<uint8_t> writeConnectivityParts(const ConnectivityParts& layout, const std::vector<uint8_t>& first,
                                            const std::vector<uint8_t>& second);
// Throws Error (Corrupt) naming the field out of range: 1 <= m < vertices,
// counts within the header's components and faces, kept vertices below
// vertices - m, part 1 within the payload.
ConnectivityParts readConnectivityParts(const uint8_t* data, size_t size, uint64_t vertices, uint64_t components,
                                        uint64_t faces);

}  // namespace drm

#endif  // DRM_CONNECTIVITY_PARTS_H
