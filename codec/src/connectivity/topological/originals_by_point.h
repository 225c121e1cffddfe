// The originals a cut mesh's topological walk meets at each grid point
// (topological_coder.cpp): the walk codes a vertex at a point already met as
// a copy of one of them.
#ifndef DRM_CONNECTIVITY_TOPOLOGICAL_ORIGINALS_BY_POINT_H
#define DRM_CONNECTIVITY_TOPOLOGICAL_ORIGINALS_BY_POINT_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common.h"
#include "geometry/tree/cell_index.h"

namespace drm {

// The originals met at each grid point of a cut mesh, in the order they
// were met: a hash table of points (CellHeads), each naming a group, and the groups'
// members chained through a table by vertex. Nothing is allocated per point
// (a mesh with copies meets tens of thousands of points, nearly all holding
// one original).
class OriginalsByPoint {
public:
    // The group of the point with key `key` (63 bits), made empty if new.
    uint32_t group(uint64_t key) {
        uint32_t& g = groupOf_.at(key);
        if (g == kNoVertex) {
            g = uint32_t(groups_.size());
            groups_.push_back(Group());
        }
        return g;
    }
    uint32_t size(uint32_t g) const { return groups_[g].count; }
    // The group's index-th original (index < size(g)).
    uint32_t at(uint32_t g, uint32_t index) const {
        uint32_t v = groups_[g].first;
        for (; index > 0; --index) v = next_[v];
        return v;
    }
    // Where v is in the group, or size(g) if it is not there.
    uint32_t indexOf(uint32_t g, uint32_t v) const {
        uint32_t index = 0;
        for (uint32_t w = groups_[g].first; w != kNoVertex && w != v; w = next_[w]) ++index;
        return index;
    }
    void append(uint32_t g, uint32_t v) {
        if (next_.size() <= v) next_.resize(std::max<size_t>(size_t(v) + 1, 2 * next_.size()), kNoVertex);
        Group& group = groups_[g];
        if (group.count == 0) group.first = v;
        else next_[group.last] = v;
        group.last = v;
        ++group.count;
    }

private:
    struct Group {
        uint32_t first = kNoVertex, last = kNoVertex, count = 0;
    };
    CellHeads groupOf_;  // point key -> its group (the tree coder's table of cells, keyed the same way)
    std::vector<Group> groups_;
    std::vector<uint32_t> next_;  // by vertex: the group's next original
};

}  // namespace drm

#endif  // DRM_CONNECTIVITY_TOPOLOGICAL_ORIGINALS_BY_POINT_H
