#include "corner_table.h"

#include <algorithm>

namespace drm {

CornerTable buildCornerTable(const std::vector<uint32_t>& t, size_t vertexCount) {
    const size_t corners = t.size();
    CornerTable table;
    table.opposite.assign(corners, kNoCorner);

    // Every corner's opposite edge keyed by its vertex pair, sorted: equal
    // keys are the faces sharing an edge.
    struct Entry {
        uint64_t key;
        uint32_t corner;
    };
    std::vector<Entry> entries;
    entries.reserve(corners);
    for (uint32_t c = 0; c < corners; ++c) {
        const uint32_t f = c / 3;
        const uint32_t a = t[3 * f], b = t[3 * f + 1], d = t[3 * f + 2];
        if (a == b || b == d || a == d) continue;  // a face repeating a vertex joins nothing
        const uint32_t u = t[nextCorner(c)], v = t[previousCorner(c)];
        entries.push_back({(uint64_t(std::min(u, v)) << 32) | std::max(u, v), c});
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
        return x.key != y.key ? x.key < y.key : x.corner < y.corner;
    });
    for (size_t i = 0; i < entries.size();) {
        size_t j = i + 1;
        while (j < entries.size() && entries[j].key == entries[i].key) ++j;
        if (j - i == 2) {
            const uint32_t c0 = entries[i].corner, c1 = entries[i + 1].corner;
            table.opposite[c0] = c1;
            table.opposite[c1] = c0;
            table.interiorEdges.push_back(c0);
        }
        i = j;
    }

    table.cornerStart.assign(vertexCount + 1, 0);
    for (uint32_t v : t) ++table.cornerStart[size_t(v) + 1];
    for (size_t v = 0; v < vertexCount; ++v) table.cornerStart[v + 1] += table.cornerStart[v];
    table.vertexCorners.resize(corners);
    std::vector<uint32_t> fill(table.cornerStart.begin(), table.cornerStart.end() - 1);
    for (uint32_t c = 0; c < corners; ++c) table.vertexCorners[fill[t[c]]++] = c;
    return table;
}

}  // namespace drm
