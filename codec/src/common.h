// Small helpers every part of the codec uses, written once: the "none"
// index (and its name for vertices), bit lengths, integer square roots, integer grid points and their
// squared distances, and
// a union-find.
#ifndef DRM_COMMON_H
#define DRM_COMMON_H

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace drm {

// The value that stands for "none" in any table of uint32 indices: never a
// valid index, since a file holds at most 2^32 - 2 vertices and 3 * faces
// corners fit below it. Each kind of index names it once, from this one:
// kNoVertex and kNotPresent here, kNoCorner (corner_table.h),
// HalfEdgeMap::kAbsent (no entry), VertexIndex::kNoColumn.
constexpr uint32_t kNoIndex = 0xFFFFFFFFu;

// "No vertex" (no parent, no candidate, no preferred apex, an empty slot)
// wherever a vertex index is stored.
constexpr uint32_t kNoVertex = kNoIndex;

// A removed vertex's slot in a spatial index's list of present vertices
// (VertexIndex, FlannIndex: presentSlot_).
constexpr uint32_t kNotPresent = kNoIndex;

// The number of bits needed to write m: 0 for 0, 1 for 1, 3 for 5.
inline int bitLength(uint64_t m) { return m == 0 ? 0 : 64 - __builtin_clzll(m); }

// floor(sqrt(v)), exactly on every machine (the double is only a first
// guess), for v below 2^62 (squared distances of 21-bit coordinates are
// below 2^45).
inline uint64_t integerSqrt(uint64_t v) {
    uint64_t r = uint64_t(std::sqrt(double(v)));
    while (r > 0 && r * r > v) --r;
    while ((r + 1) * (r + 1) <= v) ++r;
    return r;
}

// A point of the quantization grid (or a difference of two).
struct GridPoint {
    int32_t x = 0, y = 0, z = 0;
};
inline GridPoint operator+(GridPoint a, GridPoint b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline GridPoint operator-(GridPoint a, GridPoint b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// Vertex v of a grid stored as 3 coordinates per vertex.
inline GridPoint gridPointOf(const std::vector<int32_t>& grid, uint32_t v) {
    return {grid[3 * size_t(v)], grid[3 * size_t(v) + 1], grid[3 * size_t(v) + 2]};
}

// Exact squared distance between two grid points (coordinates below 2^21,
// so 64 bits never overflow).
inline int64_t distance2(GridPoint a, GridPoint b) {
    const int64_t dx = int64_t(a.x) - b.x, dy = int64_t(a.y) - b.y, dz = int64_t(a.z) - b.z;
    return dx * dx + dy * dy + dz * dz;
}

// Union-find with path halving. join(a, b) puts a's set under b's root;
// joinToLower keeps the smaller root, so a set's root is its least member.
struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t root(uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
    // False if a and b were already in one set.
    bool join(uint32_t a, uint32_t b) {
        a = root(a);
        b = root(b);
        if (a == b) return false;
        parent[a] = b;
        return true;
    }
    void joinToLower(uint32_t a, uint32_t b) {
        a = root(a);
        b = root(b);
        if (a < b) parent[b] = a;
        else if (b < a) parent[a] = b;
    }
};

}  // namespace drm

#endif  // DRM_COMMON_H
