// Union-find over face corners (3f + k): corners joined across shared edges
// fall into one set per fan around their vertex. Used by the manifold check
// and by the manifold cut.
#ifndef DRM_CORNER_SETS_H
#define DRM_CORNER_SETS_H

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace drm {

struct CornerSets {
    std::vector<uint32_t> parent;
    explicit CornerSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t root(uint32_t c) {
        while (parent[c] != c) c = parent[c] = parent[parent[c]];
        return c;
    }
    void join(uint32_t a, uint32_t b) { parent[root(a)] = root(b); }
};

}  // namespace drm

#endif  // DRM_CORNER_SETS_H
