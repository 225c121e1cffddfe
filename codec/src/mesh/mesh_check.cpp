#include "mesh/mesh_check.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "common.h"

namespace drm {
namespace {

std::string faceText(const std::vector<uint32_t>& t, size_t f) {
    return "face " + std::to_string(f) + " (" + std::to_string(t[3 * f]) + ", " + std::to_string(t[3 * f + 1]) +
           ", " + std::to_string(t[3 * f + 2]) + ")";
}

// Where a vertex's edge to b lies in its list of `degree` edges, sorted by
// far end; degree if it has none. A few edges leave most vertices; a hub's
// are searched by halving.
size_t placeOf(const MeshTopology::Outgoing* first, size_t degree, uint32_t b) {
    const MeshTopology::Outgoing* const last = first + degree;
    const MeshTopology::Outgoing* at = first;
    if (degree > 16) {
        at = std::lower_bound(first, last, b, [](const MeshTopology::Outgoing& e, uint32_t to) { return e.to < to; });
    } else {
        while (at != last && at->to < b) ++at;
    }
    return at != last && at->to == b ? size_t(at - first) : degree;
}

// For a vertex v whose faces (its edges first[0 .. degree), joined by
// next) form two fans or more: the first corner, in the order of the faces
// and their corners, that lies outside the fan of v's first corner.
size_t secondFanCorner(const std::vector<uint32_t>& t, size_t v, const MeshTopology::Outgoing* first, size_t degree,
                       const std::vector<uint32_t>& next) {
    UnionFind fans(degree);
    for (size_t i = 0; i < degree; ++i)
        if (next[i] != kNoIndex) fans.join(uint32_t(i), next[i]);
    auto corner = [&](size_t i) {
        const size_t f = first[i].face;
        int k = 0;
        while (t[3 * f + k] != v) ++k;
        return 3 * f + size_t(k);
    };
    size_t firstCorner = SIZE_MAX;
    uint32_t firstFan = 0;
    for (size_t i = 0; i < degree; ++i)
        if (corner(i) < firstCorner) {
            firstCorner = corner(i);
            firstFan = fans.root(uint32_t(i));
        }
    size_t seen = SIZE_MAX;
    for (size_t i = 0; i < degree; ++i)
        if (fans.root(uint32_t(i)) != firstFan) seen = std::min(seen, corner(i));
    return seen;
}

}  // namespace

uint32_t MeshTopology::faceOf(uint32_t a, uint32_t b) const {
    const size_t degree = start[a + 1] - start[a];
    if (degree == 0) return kNoIndex;  // (no faces at all: no array to point into)
    const Outgoing* first = out.data() + start[a];
    const size_t at = placeOf(first, degree, b);
    return at == degree ? kNoIndex : first[at].face;
}

uint32_t MeshTopology::apexAcross(uint32_t a, uint32_t b, uint32_t* face) const {
    const uint32_t g = faceOf(b, a);
    if (face) *face = g;
    if (g == kNoIndex) return kNoVertex;
    const uint32_t* t = triangles->data() + 3 * size_t(g);
    for (int k = 0; k < 3; ++k)
        if (t[k] == b) return t[(k + 2) % 3];
    return kNoVertex;  // unreachable for a table built by checkMesh
}

void checkIndices(const Mesh& mesh) { checkIndices(mesh.triangles, mesh.vertexCount()); }

void checkIndices(const std::vector<uint32_t>& t, size_t vertexCount) {
    const size_t faceCount = t.size() / 3;
    if (t.size() % 3 != 0) throw Error(ErrorKind::InvalidInput, "the triangle array does not hold whole index triples");
    if (vertexCount >= kNoVertex || faceCount >= 0x55555555u)
        throw Error(ErrorKind::InvalidInput, "the mesh is too large: at most 2^32-2 vertices and 1431655764 faces are supported");
    for (size_t f = 0; f < faceCount; ++f)
        for (int k = 0; k < 3; ++k)
            if (t[3 * f + k] >= vertexCount)
                throw Error(ErrorKind::InvalidInput, faceText(t, f) + " refers to vertex " + std::to_string(t[3 * f + k]) +
                            ", but the mesh has only " + std::to_string(vertexCount) + " vertices");
}

MeshTopology checkMesh(const Mesh& mesh) {
    checkIndices(mesh);
    MeshTopology topology;
    const std::string problem = topologyProblem(mesh, &topology);
    if (!problem.empty()) throw Error(ErrorKind::InvalidInput, problem);
    return topology;
}

std::string topologyProblem(const Mesh& mesh, MeshTopology* out) {
    return topologyProblem(mesh.triangles, mesh.vertexCount(), out);
}

void buildTopology(const std::vector<uint32_t>& t, size_t vertexCount, MeshTopology* out) {
    MeshTopology& topology = *out;
    topology.triangles = &t;
    std::vector<uint32_t>& start = topology.start;
    std::vector<MeshTopology::Outgoing>& edges = topology.out;
    start.assign(vertexCount + 1, 0);
    for (uint32_t v : t) ++start[size_t(v) + 1];
    for (size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
    edges.resize(t.size());
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        const size_t faceCount = t.size() / 3;
        for (size_t f = 0; f < faceCount; ++f)
            for (int k = 0; k < 3; ++k) edges[fill[t[3 * f + k]]++] = {t[3 * f + (k + 1) % 3], uint32_t(f)};
    }
    for (size_t v = 0; v < vertexCount; ++v) {
        if (start[v + 1] - start[v] < 2) continue;  // (no faces at all: no array to point into)
        std::sort(edges.data() + start[v], edges.data() + start[v + 1],
                  [](const MeshTopology::Outgoing& x, const MeshTopology::Outgoing& y) {
                      return x.to != y.to ? x.to < y.to : x.face < y.face;
                  });
    }
}

std::string topologyProblem(const std::vector<uint32_t>& t, size_t vertexCount, MeshTopology* out) {
    const size_t faceCount = t.size() / 3;
    for (size_t f = 0; f < faceCount; ++f) {
        if (t[3 * f] == t[3 * f + 1] || t[3 * f + 1] == t[3 * f + 2] || t[3 * f] == t[3 * f + 2])
            return (faceText(t, f) + " repeats a vertex index; such degenerate faces are not supported");
    }

    MeshTopology& topology = *out;
    buildTopology(t, vertexCount, &topology);
    const std::vector<uint32_t>& start = topology.start;
    const std::vector<MeshTopology::Outgoing>& edges = topology.out;
    // Each vertex's edges are sorted by far end, then face; a far end met
    // twice is a directed edge in two faces. The message names the pair a
    // table built face by face would meet first: the later face smallest,
    // and within it the first corner.
    size_t firstClash = SIZE_MAX, clashWith = 0;
    uint32_t clashFrom = 0, clashTo = 0;
    for (size_t v = 0; v < vertexCount; ++v) {
        if (start[v + 1] - start[v] < 2) continue;  // (no faces at all: no array to point into)
        const MeshTopology::Outgoing* first = edges.data() + start[v];
        const MeshTopology::Outgoing* last = edges.data() + start[v + 1];
        for (const MeshTopology::Outgoing* e = first; e + 1 < last; ++e) {
            if (e[1].to != e->to) continue;
            int corner = 0;
            while (t[3 * size_t(e[1].face) + corner] != v) ++corner;
            const size_t order = 3 * size_t(e[1].face) + corner;
            if (order < firstClash) {
                firstClash = order;
                clashWith = e->face;
                clashFrom = uint32_t(v);
                clashTo = e->to;
            }
        }
    }
    if (firstClash != SIZE_MAX)
        return (faceText(t, firstClash / 3) + " and " + faceText(t, clashWith) + " both contain the directed edge " +
                std::to_string(clashFrom) + "->" + std::to_string(clashTo) +
                ": the mesh is non-manifold or inconsistently oriented there");

    // A vertex's faces form one fan when its link is one path or one
    // cycle. Each face (v, a, b) around v is v's edge to a, and steps from
    // a to b; the step on from b is v's edge to b, looked up in v's own
    // list. So the test reads only that list and its faces. (A union of
    // corners joined across each edge would read other vertices' lists at
    // random: the whole check would take twice as long.)
    size_t firstSeen = SIZE_MAX;  // corner order, as a face-by-face test meets it
    uint32_t twoFanVertex = 0;
    std::vector<uint32_t> next;
    std::vector<uint8_t> reached;
    for (size_t v = 0; v < vertexCount; ++v) {
        const size_t degree = start[v + 1] - start[v];
        if (degree < 2) continue;
        const MeshTopology::Outgoing* first = edges.data() + start[v];
        next.assign(degree, kNoIndex);
        reached.assign(degree, 0);
        for (size_t i = 0; i < degree; ++i) {
            const uint32_t* f = t.data() + 3 * size_t(first[i].face);
            const uint32_t b = f[0] == first[i].to ? f[1] : (f[1] == first[i].to ? f[2] : f[0]);
            const size_t j = placeOf(first, degree, b);
            if (j == degree) continue;  // an open edge: the fan ends
            next[i] = uint32_t(j);
            reached[j] = 1;
        }
        // Walk from a path's start (an edge no face steps onto), else from
        // anywhere on the cycle; one fan if the walk meets every face.
        size_t from = 0, starts = 0;
        for (size_t i = 0; i < degree; ++i)
            if (!reached[i] && starts++ == 0) from = i;
        size_t walked = 0;
        if (starts <= 1) {
            size_t i = from;
            do {
                ++walked;
                i = next[i];
            } while (i != kNoIndex && i != from && walked <= degree);
        }
        if (starts <= 1 && walked == degree) continue;
        // Two fans or more (rare): the corner where a face-by-face test
        // first meets a face outside the fan of v's first corner.
        const size_t seen = secondFanCorner(t, v, first, degree, next);
        if (seen < firstSeen) {
            firstSeen = seen;
            twoFanVertex = uint32_t(v);
        }
    }
    if (firstSeen != SIZE_MAX)
        return ("vertex " + std::to_string(twoFanVertex) + " is non-manifold: its faces form more than one fan (first seen at " +
                faceText(t, firstSeen / 3) + ")");
    return std::string();
}

}  // namespace drm
