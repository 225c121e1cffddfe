// The cell index of the spanning-tree geometry coder: the vertices decoded
// so far, bucketed by cubic cells of the grid, to find those nearest a
// point (the predictions are built from them). Encoder and decoder fill it
// in the same order, so both find the same near points.
#ifndef DRM_CELL_INDEX_H
#define DRM_CELL_INDEX_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common.h"

namespace drm {

// How many near decoded vertices a prediction is built from.
constexpr int kNearest = 4;

// Cell key -> the cell's latest vertex: open addressing with linear
// probing, grown as cells appear (a decoder's table grows with what it has
// decoded, never with what a header claims). Much cheaper than a node-based
// map on the decoder's path.
class CellHeads {
public:
    // The head of cell `key`, inserted as kNoVertex if absent.
    uint32_t& at(uint64_t key) {
        if (2 * (used_ + 1) > keys_.size()) grow();
        size_t slot = find(key);
        if (keys_[slot] == kEmpty) {
            keys_[slot] = key;
            heads_[slot] = kNoVertex;
            ++used_;
        }
        return heads_[slot];
    }
    uint32_t get(uint64_t key) const {
        if (keys_.empty()) return kNoVertex;
        const size_t slot = find(key);
        return keys_[slot] == key ? heads_[slot] : kNoVertex;
    }

private:
    static constexpr uint64_t kEmpty = ~uint64_t(0);  // keys use 63 bits
    size_t find(uint64_t key) const {
        // The slot is the product's top bits, which every bit of the key
        // reaches (the product's bits from 20 up alone never depend on the
        // x field, bits 42 and up: cells sharing y and z would collide and
        // probing would take much of predict()). Which slot a key gets
        // changes nothing but speed.
        const size_t mask = keys_.size() - 1;
        size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - slotBits_));
        while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask;
        return slot;
    }
    void grow() {
        std::vector<uint64_t> keys(std::max<size_t>(64, 2 * keys_.size()), kEmpty);
        std::vector<uint32_t> heads(keys.size(), kNoVertex);
        slotBits_ = 0;
        while ((size_t(1) << slotBits_) < keys.size()) ++slotBits_;
        keys.swap(keys_);
        heads.swap(heads_);
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != kEmpty) {
                const size_t slot = find(keys[i]);
                keys_[slot] = keys[i];
                heads_[slot] = heads[i];
            }
    }
    std::vector<uint64_t> keys_;
    std::vector<uint32_t> heads_;
    int slotBits_ = 0;  // keys_.size() == 2^slotBits_
    size_t used_ = 0;
};

// The decoded vertices bucketed by cubic cells of side 2^cellBits, to find
// those near a point. Each cell lists its vertices latest first.
class DecodedCells {
public:
    explicit DecodedCells(int cellBits) : cellBits_(cellBits) {}
    int cellBits() const { return cellBits_; }
    void reserve(size_t vertices) { nodes_.reserve(vertices); }

    void insert(uint32_t v, GridPoint at) {
        uint32_t& head = head_.at(key(at.x, at.y, at.z));
        if (v == nodes_.size()) nodes_.push_back({at, head});  // the coders insert in order
        else {
            if (nodes_.size() < v) nodes_.resize(size_t(v) + 1);
            nodes_[v] = {at, head};
        }
        head = v;
    }

    // The up to kNearest decoded vertices nearest `at` (other than `self`)
    // in the 2x2x2 block of cells around it (its own cell and, on each axis,
    // the neighbour on its nearer side), nearest first; ties go to the one
    // seen first: cells in corner order 0..7 (corner 0 is at's own cell; bit
    // 0 of the corner steps on x, bit 1 on y, bit 2 on z), each cell's
    // vertices from the latest decoded down. Returns how many; `nearD2`
    // gets their squared distances to `at`.
    int nearest(uint32_t self, GridPoint at, GridPoint* near, int64_t* nearD2) const {
        // Per axis (x, y, z: corner bits 0, 1, 2): the own cell's and the
        // neighbour's part of a key, whether the neighbour lies off the grid,
        // and the least squared distance from `at` to the neighbour.
        const int32_t side = int32_t(1) << cellBits_;
        const int32_t at3[3] = {at.x, at.y, at.z};
        uint64_t part[3][2];
        int offGrid = 0;  // corner bits of the neighbours off the grid
        int64_t gap2[3];
        for (int a = 0; a < 3; ++a) {
            const int32_t offset = at3[a] & (side - 1);  // from the own cell's low side
            const bool down = offset < side / 2;
            const int64_t gap = down ? int64_t(offset) + 1 : int64_t(side - offset);  // integer coordinates
            gap2[a] = gap * gap;
            const uint32_t cell = uint32_t(at3[a]) >> cellBits_;
            const uint32_t neighbour = down ? cell - 1 : cell + 1;  // below 0: wraps, off the grid
            if (neighbour >= (uint32_t(1) << (kCoordinateBits - cellBits_))) offGrid |= 1 << a;
            part[a][0] = uint64_t(cell) << keyShift(a);
            part[a][1] = uint64_t(neighbour) << keyShift(a);
        }
        int64_t least[8];  // per corner: the least squared distance from `at` to its cell
        least[0] = 0;
        for (int corner = 1; corner < 8; ++corner) least[corner] = least[corner & (corner - 1)] + gap2[__builtin_ctz(unsigned(corner))];
        // The list so far, nearest first, padded with "farther than any"
        // (squared distances of 21-bit coordinates are below 2^45): a vertex
        // at the last entry's distance or farther can never enter it.
        int64_t d2s[kNearest];
        uint32_t vs[kNearest];
        std::fill(d2s, d2s + kNearest, INT64_MAX);
        std::fill(vs, vs + kNearest, kNoVertex);
        int64_t last = INT64_MAX;  // d2s[kNearest - 1], kept at hand
        int count = 0;
        const int64_t ax = at.x, ay = at.y, az = at.z;
        for (int corner = 0; corner < 8; ++corner) {
            // A cell no nearer than the list's last entry cannot enter it
            // (a tie goes to the one seen first): skipping it, and its
            // look-up, changes nothing. On a surface most of the block's
            // vertices are skipped so.
            if (least[corner] >= last || (corner & offGrid) != 0) continue;
            const uint64_t key = part[0][corner & 1] | part[1][(corner >> 1) & 1] | part[2][corner >> 2];
            for (uint32_t v = head_.get(key); v != kNoVertex;) {
                const Node& node = nodes_[v];
                const int64_t dx = node.at.x - ax, dy = node.at.y - ay, dz = node.at.z - az;
                const int64_t d2 = dx * dx + dy * dy + dz * dz;
                // `self` lies at `at` (0 away): tested only once a vertex
                // would enter, which few do.
                if (d2 < last && v != self) {
                    // Insertion into the sorted list, after the entries as
                    // near (seen first), without branches: where it lands is
                    // a coin toss to a branch predictor.
                    for (int i = kNearest - 1; i > 0; --i) {
                        const bool shifted = d2s[i - 1] > d2, here = d2s[i] > d2;
                        vs[i] = shifted ? vs[i - 1] : (here ? v : vs[i]);
                        d2s[i] = shifted ? d2s[i - 1] : (here ? d2 : d2s[i]);
                    }
                    const bool front = d2s[0] > d2;
                    vs[0] = front ? v : vs[0];
                    d2s[0] = front ? d2 : d2s[0];
                    count += count < kNearest ? 1 : 0;
                    last = d2s[kNearest - 1];
                }
                v = node.next;
            }
        }
        for (int i = 0; i < count; ++i) {
            near[i] = nodes_[vs[i]].at;
            nearD2[i] = d2s[i];
        }
        return count;
    }

private:
    // A cell's key: its x, y and z (coordinates below 2^21, over the cell
    // size) in 21 bits each.
    static constexpr int kCoordinateBits = 21;
    static constexpr int keyShift(int axis) { return (2 - axis) * kCoordinateBits; }
    uint64_t key(int32_t x, int32_t y, int32_t z) const {
        return (uint64_t(uint32_t(x) >> cellBits_) << keyShift(0)) | (uint64_t(uint32_t(y) >> cellBits_) << keyShift(1)) |
               uint64_t(uint32_t(z) >> cellBits_);
    }
    struct Node {
        GridPoint at;
        uint32_t next;  // the vertex before this one in its cell
    };
    int cellBits_;
    CellHeads head_;          // cell -> its latest vertex
    std::vector<Node> nodes_;  // by vertex: where it is and the rest of its cell's list
};

}  // namespace drm

#endif  // DRM_CELL_INDEX_H
