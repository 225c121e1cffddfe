// A hash map from directed edges (a, b) to a 32-bit value.
//
// Both the input check and the shared traversal look up directed edges once
// or twice per triangle; an open-addressing table keyed by the packed pair is
// several times faster than std::unordered_map and allocates once.
#ifndef DRM_HALFEDGE_MAP_H
#define DRM_HALFEDGE_MAP_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

class HalfEdgeMap {
public:
    static constexpr uint32_t kAbsent = 0xFFFFFFFFu;

    // expectedEdges: how many edges will be inserted (the table never grows
    // past twice that without rehashing, so a good guess keeps it fast).
    explicit HalfEdgeMap(size_t expectedEdges = 16) { reset(expectedEdges); }

    void reset(size_t expectedEdges) {
        size_t capacity = 16;
        while (capacity < expectedEdges * 2) capacity *= 2;
        keys_.assign(capacity, kEmptyKey);
        values_.assign(capacity, kAbsent);
        size_ = 0;
    }

    // The value stored for (a, b), or kAbsent.
    uint32_t find(uint32_t a, uint32_t b) const {
        const uint64_t key = pack(a, b);
        for (size_t slot = home(key);; slot = (slot + 1) & mask()) {
            if (keys_[slot] == key) return values_[slot];
            if (keys_[slot] == kEmptyKey) return kAbsent;
        }
    }

    bool contains(uint32_t a, uint32_t b) const { return find(a, b) != kAbsent; }

    // Inserts (a, b) -> value; returns false (and changes nothing) if the
    // edge is already present.
    bool insert(uint32_t a, uint32_t b, uint32_t value) {
        if ((size_ + 1) * 2 > keys_.size()) grow();
        const uint64_t key = pack(a, b);
        size_t slot = home(key);
        for (; keys_[slot] != kEmptyKey; slot = (slot + 1) & mask())
            if (keys_[slot] == key) return false;
        keys_[slot] = key;
        values_[slot] = value;
        ++size_;
        return true;
    }

    size_t size() const { return size_; }

private:
    // (a, b) with a == b never occurs (faces with a repeated index are
    // refused), so the packed self-loop of vertex 2^32-1 is a safe marker.
    static constexpr uint64_t kEmptyKey = ~uint64_t(0);

    static uint64_t pack(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }
    size_t mask() const { return keys_.size() - 1; }
    size_t home(uint64_t key) const {
        // Fibonacci hashing: the high bits of the product are well mixed.
        return size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & mask();
    }

    void grow() {
        std::vector<uint64_t> oldKeys;
        std::vector<uint32_t> oldValues;
        oldKeys.swap(keys_);
        oldValues.swap(values_);
        keys_.assign(oldKeys.size() * 2, kEmptyKey);
        values_.assign(oldKeys.size() * 2, kAbsent);
        size_ = 0;
        for (size_t i = 0; i < oldKeys.size(); ++i)
            if (oldKeys[i] != kEmptyKey)
                insert(uint32_t(oldKeys[i] >> 32), uint32_t(oldKeys[i]), oldValues[i]);
    }

    std::vector<uint64_t> keys_;
    std::vector<uint32_t> values_;
    size_t size_ = 0;
};

}  // namespace drm

#endif  // DRM_HALFEDGE_MAP_H
