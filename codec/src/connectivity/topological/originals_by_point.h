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

namespace drm {

// The originals met at each grid point of a cut mesh, in the order they
// were met: a hash table of points, each naming a group, and the groups'
// members chained through a table by vertex. Nothing is allocated per point
// (a mesh with copies meets tens of thousands of points, nearly all holding
// one original).
class OriginalsByPoint {
public:
    // The group of the point with key `key` (63 bits), made empty if new.
    uint32_t group(uint64_t key) {
        if (2 * (groups_.size() + 1) > keys_.size()) grow();
        const size_t slot = find(key);
        if (keys_[slot] == kEmpty) {
            keys_[slot] = key;
            groupAt_[slot] = uint32_t(groups_.size());
            groups_.push_back(Group());
        }
        return groupAt_[slot];
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
    static constexpr uint64_t kEmpty = ~uint64_t(0);
    struct Group {
        uint32_t first = kNoVertex, last = kNoVertex, count = 0;
    };
    size_t find(uint64_t key) const {  // the slot of key, or the empty one where it goes
        const size_t mask = keys_.size() - 1;
        size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - slotBits_));
        while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask;
        return slot;
    }
    void grow() {
        std::vector<uint64_t> keys(std::max<size_t>(64, 2 * keys_.size()), kEmpty);
        std::vector<uint32_t> groupAt(keys.size(), 0);
        slotBits_ = 0;
        while ((size_t(1) << slotBits_) < keys.size()) ++slotBits_;
        keys.swap(keys_);
        groupAt.swap(groupAt_);
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != kEmpty) {
                const size_t slot = find(keys[i]);
                keys_[slot] = keys[i];
                groupAt_[slot] = groupAt[i];
            }
    }
    std::vector<uint64_t> keys_;     // a power of two of slots, at most half used
    std::vector<uint32_t> groupAt_;  // by slot
    int slotBits_ = 0;
    std::vector<Group> groups_;
    std::vector<uint32_t> next_;  // by vertex: the group's next original
};

}  // namespace drm

#endif  // DRM_CONNECTIVITY_TOPOLOGICAL_ORIGINALS_BY_POINT_H
