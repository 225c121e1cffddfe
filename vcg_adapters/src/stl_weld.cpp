// weldIdenticalPositions: see stl_weld.h.
#include "stl_weld.h"

#include <array>
#include <cstring>
#include <unordered_map>

namespace drm {
namespace vcgio {

namespace {

// A position as its three float bit patterns: -0.0 and 0.0 stay apart, as
// "bit-identical" promises.
using PositionBits = std::array<uint32_t, 3>;

struct PositionBitsHash {
    size_t operator()(const PositionBits& p) const {
        uint64_t h = 1469598103934665603ull;  // FNV-1a over the three words
        for (uint32_t word : p) {
            h ^= word;
            h *= 1099511628211ull;
        }
        return size_t(h);
    }
};

}  // namespace

drm::Mesh weldIdenticalPositions(const drm::Mesh& soup) {
    drm::Mesh welded;
    std::unordered_map<PositionBits, uint32_t, PositionBitsHash> indexOf;
    indexOf.reserve(soup.vertexCount());
    std::vector<uint32_t> newIndex(soup.vertexCount());
    for (size_t i = 0; i < soup.vertexCount(); ++i) {
        PositionBits bits;
        std::memcpy(bits.data(), &soup.positions[3 * i], sizeof bits);
        auto inserted = indexOf.emplace(bits, uint32_t(welded.vertexCount()));
        if (inserted.second)
            welded.positions.insert(welded.positions.end(), &soup.positions[3 * i], &soup.positions[3 * i] + 3);
        newIndex[i] = inserted.first->second;
    }
    welded.triangles.reserve(soup.triangles.size());
    for (uint32_t corner : soup.triangles) welded.triangles.push_back(newIndex[corner]);
    return welded;
}

}  // namespace vcgio
}  // namespace drm
