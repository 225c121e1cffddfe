// A hash map from directed edges (a, b) to a 32-bit value.
//
// Both the input check and the shared traversal look up directed edges once
// or twice per triangle; an open-addressing table keyed by the packed pair is
// several times faster than std::unordered_map and allocates once.
#ifndef DRM_HALFEDGE_MAP_H
#define DRM_HALFEDGE_MAP_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common.h"

namespace drm {

class HalfEdgeMap {
public:
    // The answer for a key not in the map. It is kNoVertex, so a map of
    // vertices (MeshTopology's apexes) answers "no vertex" as it is.
    static constexpr uint32_t kAbsent = kNoIndex;

    // expectedEdges: how many edges will be inserted (the table never grows
    // past slotsPerEdge times that without rehashing, so a good guess keeps
    // it fast). slotsPerEdge: the table grows when its entries would fill
    // more than 1 / slotsPerEdge of its slots. 2 suits a table of the whole
    // mesh (memory); 4 a small one that is searched far more often than it
    // is filled (shorter probe runs: a look-up's loop ends where a branch
    // predictor expects more often).
    explicit HalfEdgeMap(size_t expectedEdges = 16, size_t slotsPerEdge = 2) : slotsPerEdge_(slotsPerEdge) {
        reset(expectedEdges);
    }

    void reset(size_t expectedEdges) {
        // Exactly slotsPerEdge times the edges (not the next power of two,
        // which would cost up to twice as much again: 43 bytes per vertex on
        // a 1M-face mesh's input check).
        setCapacity(std::max<size_t>(16, expectedEdges * slotsPerEdge_));
    }

    // The value stored for (a, b), or kAbsent.
    uint32_t find(uint32_t a, uint32_t b) const {
        const uint64_t key = pack(a, b);
        for (size_t slot = home(key);; slot = next(slot)) {
            if (keys_[slot] == key) return values_[slot];
            if (keys_[slot] == kEmptyKey) return kAbsent;
        }
    }

    bool contains(uint32_t a, uint32_t b) const { return find(a, b) != kAbsent; }

    // Inserts (a, b) -> value; returns false (and changes nothing) if the
    // edge is already present (an erased one is not: it takes the value).
    bool insert(uint32_t a, uint32_t b, uint32_t value) { return put(a, b, value, false); }

    // Sets (a, b) -> value, inserting the edge or overwriting its value.
    void assign(uint32_t a, uint32_t b, uint32_t value) { put(a, b, value, true); }
    // Makes (a, b) answer kAbsent. Its slot stays taken (linear probing has
    // no other tombstone) until a rebuildKeeping that drops it.
    void erase(uint32_t a, uint32_t b) {
        const uint64_t key = pack(a, b);
        for (size_t slot = home(key); keys_[slot] != kEmptyKey; slot = next(slot))
            if (keys_[slot] == key) {
                values_[slot] = kAbsent;
                return;
            }
    }

    // Entries held, erased ones included until a rebuild or growth drops them.
    size_t size() const { return size_; }
    size_t capacity() const { return keys_.size(); }

    // True when the next insert would grow the table: a caller that knows
    // some entries will never be asked for again can drop them first
    // (rebuildKeeping) instead.
    bool full() const { return (size_ + 1) * slotsPerEdge_ > keys_.size(); }

    // Rebuilds the table with only the entries (a, b) -> value for which
    // keep(a, b, value) holds (an erased entry's value is kAbsent), at a
    // capacity that leaves them at most a quarter of the most the table
    // holds (so it is full again only after at least 3/4 of that
    // has been inserted: sweeping costs O(1) per insert, amortized, and
    // little, as it reads each slot once). Linear probing needs no
    // tombstones this way; the dropped keys then answer kAbsent.
    template <class Keep>
    void rebuildKeeping(Keep keep) {
        std::vector<uint64_t> keptKeys;
        std::vector<uint32_t> keptValues;
        // A full() table uses at most 1 / slotsPerEdge of its slots (the
        // traversal's a quarter), so empty slots, passed over at the cost
        // of a compare, are most of the scan. Every used entry is written and kept if it
        // should be, without a branch on keep() (a coin toss).
        keptKeys.resize(size_ + 1);  // kept <= size_: room for the one written last
        keptValues.resize(size_ + 1);
        size_t kept = 0;
        for (size_t i = 0; i < keys_.size(); ++i) {
            const uint64_t key = keys_[i];
            if (key == kEmptyKey) continue;
            keptKeys[kept] = key;
            keptValues[kept] = values_[i];
            kept += bool(keep(uint32_t(key >> 32), uint32_t(key), values_[i]));
        }
        keptKeys.resize(kept);
        keptValues.resize(kept);
        const size_t capacity = std::max<size_t>(kLeastRebuiltSlots, keptKeys.size() * 4 * slotsPerEdge_);
        std::vector<uint64_t>().swap(keys_);  // freed before the new table is made
        std::vector<uint32_t>().swap(values_);
        setCapacity(capacity);
        for (size_t i = 0; i < keptKeys.size(); ++i) {
            size_t slot = home(keptKeys[i]);
            while (keys_[slot] != kEmptyKey) slot = next(slot);
            keys_[slot] = keptKeys[i];
            values_[slot] = keptValues[i];
        }
        size_ = keptKeys.size();
    }

private:
    // A rebuilt table has at least this many slots: a table that keeps a
    // handful of entries (the traversal's fan pieces beyond each vertex's
    // first: a few at a time) would otherwise fill again, and be rebuilt,
    // every few inserts.
    static constexpr size_t kLeastRebuiltSlots = 256;
    // (a, b) with a == b never occurs (faces with a repeated index are
    // refused), so the packed self-loop of vertex 2^32-1 is a safe marker.
    static constexpr uint64_t kEmptyKey = ~uint64_t(0);

    static uint64_t pack(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }
    // insert (overwrite false: a present value stays) and assign.
    bool put(uint32_t a, uint32_t b, uint32_t value, bool overwrite) {
        if (full()) grow();
        const uint64_t key = pack(a, b);
        size_t slot = home(key);
        for (; keys_[slot] != kEmptyKey; slot = next(slot))
            if (keys_[slot] == key) {
                if (!overwrite && values_[slot] != kAbsent) return false;
                values_[slot] = value;
                return true;
            }
        keys_[slot] = key;
        values_[slot] = value;
        ++size_;
        return true;
    }
    size_t next(size_t slot) const { return slot + 1 == capacity_ ? 0 : slot + 1; }
    size_t home(uint64_t key) const {
        // Fibonacci hashing: the top bits of the product depend on every bit
        // of the key (the product's bits from 20 up alone ignore a in small
        // tables, so that all edges into one vertex would share a probe run).
        // (The product's top 32 bits scaled to the capacity, which need
        // not be a power of two.)
        return size_t((((key * 0x9E3779B97F4A7C15ull) >> 32) * capacity_) >> 32);
    }
    void setCapacity(size_t capacity) {  // >= 16, below 2^32
        keys_.assign(capacity, kEmptyKey);
        values_.assign(capacity, kAbsent);
        capacity_ = capacity;
        size_ = 0;
    }

    void grow() {
        std::vector<uint64_t> oldKeys;
        std::vector<uint32_t> oldValues;
        oldKeys.swap(keys_);
        oldValues.swap(values_);
        setCapacity(oldKeys.size() * 2);
        for (size_t i = 0; i < oldKeys.size(); ++i)
            if (oldKeys[i] != kEmptyKey && oldValues[i] != kAbsent)  // erased entries are dropped
                insert(uint32_t(oldKeys[i] >> 32), uint32_t(oldKeys[i]), oldValues[i]);
    }

    std::vector<uint64_t> keys_;
    std::vector<uint32_t> values_;
    size_t slotsPerEdge_;
    size_t size_ = 0;
    size_t capacity_ = 0;  // keys_.size(), kept for the look-ups' arithmetic
};

}  // namespace drm

#endif  // DRM_HALFEDGE_MAP_H
