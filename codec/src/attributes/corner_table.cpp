#include "attributes/corner_table.h"

namespace drm {
namespace {

bool degenerate(const std::vector<uint32_t>& t, uint32_t f) {
    const uint32_t a = t[3 * size_t(f)], b = t[3 * size_t(f) + 1], c = t[3 * size_t(f) + 2];
    return a == b || b == c || a == c;
}

}  // namespace

CornerTable buildCornerTable(const std::vector<uint32_t>& t, size_t vertexCount, bool withOpposites) {
    const size_t corners = t.size();
    CornerTable table;

    // Corners of each vertex (a counting sort: no comparison sort, which
    // would take a third of the attribute decoding time).
    table.cornerStart.assign(vertexCount + 1, 0);
    for (uint32_t v : t) ++table.cornerStart[size_t(v) + 1];
    for (size_t v = 0; v < vertexCount; ++v) table.cornerStart[v + 1] += table.cornerStart[v];
    table.vertexCorners.resize(corners);
    std::vector<uint32_t> fill(table.cornerStart.begin(), table.cornerStart.end() - 1);
    for (uint32_t c = 0; c < corners; ++c) table.vertexCorners[fill[t[c]]++] = c;
    if (withOpposites) addOpposites(table, t);
    return table;
}

void addOpposites(CornerTable& table, const std::vector<uint32_t>& t) {
    const size_t corners = t.size();
    table.opposite.assign(corners, kNoCorner);
    table.interiorEdges.clear();
    // The edge opposite corner c joins u and v; the faces around u that
    // also hold v share it. Exactly one other such face: an interior edge.
    for (uint32_t c = 0; c < corners; ++c) {
        const uint32_t f = c / 3;
        if (degenerate(t, f)) continue;
        const uint32_t u = t[nextCorner(c)], v = t[previousCorner(c)];
        uint32_t found = kNoCorner, count = 0;
        for (uint32_t i = table.cornerStart[u]; i < table.cornerStart[u + 1]; ++i) {
            const uint32_t y = table.vertexCorners[i], g = y / 3;
            if (g == f || degenerate(t, g)) continue;
            const uint32_t z = cornerAt(t, g, v);
            if (z == kNoCorner) continue;
            ++count;
            found = 3 * g + (3 - y % 3 - z % 3);  // the corner of g at neither u nor v
        }
        if (count == 1) table.opposite[c] = found;
    }
    for (uint32_t c = 0; c < corners; ++c)
        if (table.opposite[c] != kNoCorner && table.opposite[c] > c) table.interiorEdges.push_back(c);
}

}  // namespace drm
