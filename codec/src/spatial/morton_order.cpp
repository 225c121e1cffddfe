#include "spatial/morton_order.h"

#include <algorithm>

#include "spatial/morton.h"

namespace drm {
namespace {

uint64_t keyOf(const std::vector<int32_t>& grid, uint32_t v) { return mortonKeyOf(&grid[3 * size_t(v)]); }

// Digits of the least-significant-digit radix sort: 11 bits, so a 12-bit
// grid's 36-bit keys take 4 passes over 2,048 counters (a comparison sort
// takes several times as long).
constexpr int kDigitBits = 11;
constexpr size_t kBuckets = size_t(1) << kDigitBits;

}  // namespace

std::vector<uint32_t> mortonOrder(const std::vector<int32_t>& grid) {
    const size_t n = grid.size() / 3;
    std::vector<uint64_t> keys(n);
    uint64_t largest = 0;
    for (size_t v = 0; v < n; ++v) {
        keys[v] = keyOf(grid, uint32_t(v));
        largest = std::max(largest, keys[v]);
    }
    std::vector<uint32_t> order(n), other(n);
    for (size_t v = 0; v < n; ++v) order[v] = uint32_t(v);
    // Each pass is stable, so equal keys keep their order in grid.
    std::vector<size_t> start(kBuckets);
    for (int shift = 0; shift < 64 && (largest >> shift) != 0; shift += kDigitBits) {
        std::fill(start.begin(), start.end(), 0);
        for (uint32_t v : order) ++start[(keys[v] >> shift) & (kBuckets - 1)];
        size_t sum = 0;
        for (size_t& s : start) {
            const size_t count = s;
            s = sum;
            sum += count;
        }
        for (uint32_t v : order) other[start[(keys[v] >> shift) & (kBuckets - 1)]++] = v;
        order.swap(other);
    }
    return order;
}

bool hasCoincidentPoints(const std::vector<int32_t>& grid, const std::vector<uint32_t>& order) {
    for (size_t i = 1; i < order.size(); ++i)
        if (keyOf(grid, order[i]) == keyOf(grid, order[i - 1])) return true;
    return false;
}

}  // namespace drm
