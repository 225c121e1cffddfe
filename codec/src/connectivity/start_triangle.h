// Start triangles (docs/format.md, "Start triangles"): each
// edge-connected component's first triangle, coded in the connectivity
// stream just before the component's first rank.
//
// The first vertex is coded as its distance from a cursor: the first vertex
// at or after the previous component's first vertex that no decoded
// triangle holds yet, cyclically. Components share no vertex (the traversal
// codes only manifold meshes), so an encoder that starts every component at
// its smallest vertex, in increasing order, codes a distance of 0 for each,
// or the count of vertices in no face that lie between; any other start
// costs the bits of its distance. The other two vertices are coded as their
// distance past the first, wrapping at the vertex count: the usual ones,
// numbered by the geometry soon after the first, cost a few bits instead of
// three varints.
#ifndef DRM_START_TRIANGLE_H
#define DRM_START_TRIANGLE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"
#include "connectivity/traversal.h"

namespace drm {

// The cursor above. Jump pointers over runs of touched vertices, shortened
// as they are followed, keep each look-up near constant time whatever
// order the starts come in (a plain scan from the previous start could be
// made quadratic by a corrupt file that starts far back each time).
class StartCursor {
public:
    explicit StartCursor(const Traversal& traversal) : traversal_(traversal), n_(uint32_t(traversal.vertexCount())) {}

    // The first untouched vertex at or after `from`, cyclically; the vertex
    // count if every vertex is touched.
    uint32_t at(uint32_t from) {
        const uint32_t found = firstUntouchedFrom(from);
        return found < n_ ? found : firstUntouchedFrom(0);
    }
    // Vertices stepped over so far (the tests' measure of the work done).
    uint64_t steps() const { return steps_; }

private:
    uint32_t firstUntouchedFrom(uint32_t from) {
        if (from >= n_ || !traversal_.isTouched(from)) return from;
        // Made at the first touched vertex met: a mesh of one component
        // never needs the table (4 bytes a vertex).
        if (jump_.empty()) {
            jump_.resize(n_);
            for (uint32_t v = 0; v < n_; ++v) jump_[v] = v;
        }
        uint32_t r = from;
        // jump_[v] never passes the first untouched vertex from v: it was
        // that vertex once, and vertices are only ever touched, not freed.
        while (r < n_ && traversal_.isTouched(r)) {
            r = jump_[r] > r ? jump_[r] : r + 1;
            ++steps_;
        }
        for (uint32_t v = from; v < n_ && v != r;) {
            const uint32_t next = jump_[v] > v ? jump_[v] : v + 1;
            jump_[v] = r;
            v = next;
        }
        return r;
    }

    const Traversal& traversal_;
    const uint32_t n_;
    std::vector<uint32_t> jump_;  // empty until needed
    uint64_t steps_ = 0;
};

// How far past `first` vertex v lies, counting up and wrapping at
// vertexCount: 0 .. vertexCount - 2 for v != first.
inline uint32_t startGap(uint32_t first, uint32_t v, size_t vertexCount) {
    return uint32_t((uint64_t(v) + vertexCount - first - 1) % vertexCount);
}

// The vertex `gap` past `first` (startGap's inverse); throws Error for a
// gap no vertex has (only a corrupt stream holds one).
inline uint32_t vertexAtGap(uint32_t first, uint32_t gap, size_t vertexCount) {
    if (uint64_t(gap) + 1 >= vertexCount)
        throw Error(ErrorKind::Corrupt, "a start triangle's vertex lies " + std::to_string(gap) + " past vertex " +
                    std::to_string(first) + ", but there are only " + std::to_string(vertexCount) + " vertices");
    return uint32_t((uint64_t(first) + 1 + gap) % vertexCount);
}

}  // namespace drm

#endif  // DRM_START_TRIANGLE_H
