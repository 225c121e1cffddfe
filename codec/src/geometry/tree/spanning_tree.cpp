#include "geometry/tree/spanning_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

#include "geometry/tree/cell_index.h"
#include "mesh/quantize.h"
#include "spatial/spatial_index.h"

namespace drm {

namespace {

uint64_t residualCost(GridPoint r) {  // Exp-Golomb length, to pick the predictor
    auto one = [](int32_t v) { return uint64_t(2 * bitLength(uint32_t(v < 0 ? -int64_t(v) : v)) + 1); };
    return one(r.x) + one(r.y) + one(r.z);
}

}  // namespace

NearestNeighbours nearestNeighbours(const std::vector<int32_t>& grid, NeighbourIndex index, int k, int threads) {
    const size_t n = grid.size() / 3;
    NearestNeighbours result;
    result.k = k;
    result.spacing = 1;
    if (n < 2) {
        result.neighbours.assign(n * size_t(k), kNoVertex);
        return result;
    }
    // Exactly, on the integer grid (either index gives the same graph).
    // Without the distances: 8 bytes a neighbour, which would raise the
    // encoder's peak while the early connectivity runs beside. The one
    // distance a vertex needs here is worked out again.
    makeSpatialIndex(grid, index, IndexRole::NeighbourGraph)->nearestOfEach(size_t(k), result.neighbours, nullptr,
                                                                                  threads);
    std::vector<int64_t> fourth(n, 0);  // squared distance to the kNearest-th nearest, fixed point
    for (size_t v = 0; v < n; ++v) {
        size_t found = 0;
        while (found < size_t(k) && result.neighbours[v * size_t(k) + found] != kNoVertex) ++found;
        if (found != 0)
            fourth[v] = fixedDistance2(grid, fixedPointOf(grid, uint32_t(v)),
                                       result.neighbours[v * size_t(k) + std::min<size_t>(kNearest, found) - 1]);
    }
    // The typical distance to the kNearest-th nearest neighbour: it sizes the cells of the near-point search.
    std::nth_element(fourth.begin(), fourth.begin() + ptrdiff_t(n / 2), fourth.end());
    result.spacing = std::sqrt(double(fourth[n / 2])) / double(kSubUnits);
    return result;
}

NearestNeighbours nearestOnly(const NearestNeighbours& nearest, int k) {
    const size_t row = size_t(nearest.k), kept = size_t(std::min(k, nearest.k));
    const size_t n = nearest.neighbours.size() / std::max<size_t>(row, 1);
    NearestNeighbours fewer;
    fewer.k = int(kept);
    fewer.spacing = nearest.spacing;
    fewer.neighbours.resize(n * kept);
    for (size_t v = 0; v < n; ++v)
        std::copy_n(nearest.neighbours.begin() + ptrdiff_t(v * row), kept, fewer.neighbours.begin() + ptrdiff_t(v * kept));
    return fewer;
}

namespace {

// A fixed number of flags, one bit each (std::vector<bool> takes more
// instructions than the searches these spare).
class Bits {
public:
    explicit Bits(size_t count) : words_((count + 63) / 64, 0) {}
    void set(size_t i) { words_[i / 64] |= uint64_t(1) << (i % 64); }
    bool test(size_t i) const { return (words_[i / 64] >> (i % 64) & 1) != 0; }

private:
    std::vector<uint64_t> words_;
};

}  // namespace

NeighbourGraph symmetricGraph(const NearestNeighbours& nearest, int count) {
    const size_t row = size_t(nearest.k), n = nearest.neighbours.size() / std::max<size_t>(row, 1);
    const size_t k = std::min<size_t>(size_t(count), row);
    NeighbourGraph graph;
    graph.offset.assign(n + 1, 0);
    auto mutual = [&](uint32_t v, uint32_t w) {  // v is among w's nearest as well
        const uint32_t* theirs = nearest.neighbours.data() + size_t(w) * row;
        return std::find(theirs, theirs + k, v) != theirs + k;
    };
    // Each edge once per end: v's own nearest, then those that have v among
    // theirs without being among v's. Which reverse edges are missing is
    // found in the first pass and kept for the second, a bit per neighbour.
    Bits missingBits(n * k);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<uint32_t> fill;
        if (pass == 1) {
            for (size_t v = 0; v < n; ++v) graph.offset[v + 1] += graph.offset[v];
            graph.neighbour.resize(graph.offset[n]);
            fill.assign(graph.offset.begin(), graph.offset.end() - 1);
        }
        for (size_t v = 0; v < n; ++v)
            for (size_t j = 0; j < k; ++j) {
                const uint32_t w = nearest.neighbours[v * row + j];
                if (w == kNoVertex) break;
                // v is not among w's own nearest
                const bool reverseMissing = pass == 0 ? !mutual(uint32_t(v), w) : missingBits.test(v * k + j);
                if (pass == 0) {
                    if (reverseMissing) missingBits.set(v * k + j);
                    ++graph.offset[v + 1];
                    if (reverseMissing) ++graph.offset[w + 1];
                } else {
                    graph.neighbour[fill[v]++] = w;
                    if (reverseMissing) graph.neighbour[fill[w]++] = uint32_t(v);
                }
            }
    }
    return graph;
}

namespace {

// A candidate edge of the forest, a < b. Length is the squared length's
// type: 32 bits where every squared length fits (grids up to 15 bits, the
// default 12 among them), 12 bytes an edge instead of 16.
template <typename Length>
struct Edge {
    Length length2;
    uint32_t a, b;
};

// Kruskal's forest, compacted in place: returns how many edges it kept at
// the front (at most n - 1), in the order taken. Edges are taken shortest
// first (`shorter`, a strict order), a chunk of n at a time: only the chunk
// is sorted, and once it is joined, the longer edges whose ends the forest
// already joins are dropped unsorted (most of them: sorting them all would
// be most of the forest's cost). So this forest is the one a full sort gives.
template <typename E, typename Shorter, typename EndsOf>
size_t joinShortestFirst(std::vector<E>& edges, size_t n, Shorter shorter, EndsOf endsOf) {
    const size_t chunk = std::max<size_t>(n, 1024);
    size_t treeEdges = 0;
    UnionFind sets(n);
    E* const all = edges.data();
    E* first = all;
    E* last = all + edges.size();
    while (first != last) {
        E* cut = last;
        if (size_t(last - first) > chunk) {
            cut = first + chunk;
            std::nth_element(first, cut, last, shorter);
        }
        std::sort(first, cut, shorter);
        for (const E* e = first; e != cut; ++e) {
            const std::pair<uint32_t, uint32_t> ends = endsOf(*e);
            if (sets.join(ends.first, ends.second)) all[treeEdges++] = *e;  // never ahead of e
        }
        last = std::remove_if(cut, last, [&](const E& e) {
            const std::pair<uint32_t, uint32_t> ends = endsOf(e);
            return sets.root(ends.first) == sets.root(ends.second);
        });
        first = cut;
    }
    return treeEdges;
}

template <typename Length>
Forest spanningForestOf(const std::vector<int32_t>& grid, const NearestNeighbours& nearest) {
    const size_t n = grid.size() / 3;
    const std::vector<uint32_t>& neighbours = nearest.neighbours;
    const size_t k = size_t(nearest.k);
    auto length2 = [&](uint32_t a, uint32_t b) { return Length(drm::distance2(gridPointOf(grid, a), gridPointOf(grid, b))); };
    // Mutual neighbours give the same edge twice: keep it once (the sort
    // below is most of the tree's cost).
    auto kept = [&](size_t v, uint32_t w) {
        if (w == kNoVertex) return false;
        const uint32_t* theirs = neighbours.data() + size_t(w) * k;
        return !(w < v && std::find(theirs, theirs + k, uint32_t(v)) != theirs + k);
    };
    // Counted before they are stored: room for k edges a vertex (128 bytes
    // a vertex) would be the largest block of the encoder's peak, and
    // mutual pairs are kept once. Which are kept is remembered from the
    // count, a bit per neighbour: the searches of the other end's list cost
    // as much as the rest of both passes.
    Bits keptBits(n * k);
    size_t edgeCount = 0;
    for (size_t v = 0; v < n; ++v)
        for (size_t j = 0; j < k; ++j)
            if (kept(v, neighbours[v * k + j])) {
                ++edgeCount;
                keptBits.set(v * k + j);
            }
    // Kruskal's forest over the kept edges (joinShortestFirst). Where the
    // longest squared length and both ends fit in 64 bits (at the default
    // 12 bits, always up to 2^19 vertices; igea x4's short edges fit too),
    // each edge is one number in the same order: sorting those takes half
    // the instructions of sorting triples.
    Length longest = 0;  // the last of each vertex's nearest is its farthest
    for (size_t v = 0; v < n; ++v) {
        size_t found = 0;
        while (found < k && neighbours[v * k + found] != kNoVertex) ++found;
        if (found != 0) longest = std::max(longest, length2(uint32_t(v), neighbours[v * k + found - 1]));
    }
    // Each kept edge once, as its ends a < b, in the order counted.
    auto forEachKept = [&](auto take) {
        for (size_t v = 0; v < n; ++v)
            for (size_t j = 0; j < k; ++j)
                if (keptBits.test(v * k + j)) {
                    const uint32_t w = neighbours[v * k + j];
                    take(std::min(uint32_t(v), w), std::max(uint32_t(v), w));
                }
    };
    const int endBits = bitLength(uint64_t(n - 1));
    const bool packed = 2 * endBits < 64 && bitLength(uint64_t(longest)) + 2 * endBits <= 64;
    std::vector<Edge<Length>> edges;
    if (packed) {
        std::vector<uint64_t> keys;
        keys.reserve(edgeCount);
        forEachKept([&](uint32_t a, uint32_t b) {
            keys.push_back(uint64_t(length2(a, b)) << (2 * endBits) | uint64_t(a) << endBits | uint64_t(b));
        });
        keptBits = Bits(0);
        const uint64_t endMask = (uint64_t(1) << endBits) - 1;
        auto endsOf = [&](uint64_t key) { return std::make_pair(uint32_t(key >> endBits & endMask), uint32_t(key & endMask)); };
        const size_t treeEdges = joinShortestFirst(keys, n, std::less<uint64_t>(), endsOf);
        edges.resize(treeEdges);
        for (size_t i = 0; i < treeEdges; ++i) {
            const std::pair<uint32_t, uint32_t> ends = endsOf(keys[i]);
            edges[i] = {Length(keys[i] >> (2 * endBits)), ends.first, ends.second};
        }
    } else {
        edges.reserve(edgeCount);
        forEachKept([&](uint32_t a, uint32_t b) { edges.push_back({length2(a, b), a, b}); });
        keptBits = Bits(0);
        const auto shorter = [](const Edge<Length>& x, const Edge<Length>& y) {
            return x.length2 != y.length2 ? x.length2 < y.length2 : (x.a != y.a ? x.a < y.a : x.b < y.b);
        };
        edges.resize(joinShortestFirst(edges, n, shorter,
                                       [](const Edge<Length>& e) { return std::make_pair(e.a, e.b); }));
    }
    edges.shrink_to_fit();
    // Each vertex's forest edges as (squared length, other end), all in one
    // array: a vector per vertex would cost 24 bytes and an allocation each.
    std::vector<uint32_t> offset(n + 1, 0);
    for (const Edge<Length>& e : edges) {
        ++offset[e.a + 1];
        ++offset[e.b + 1];
    }
    for (size_t v = 0; v < n; ++v) offset[v + 1] += offset[v];
    std::vector<std::pair<Length, uint32_t>> adjacent(offset[n]);
    {
        std::vector<uint32_t> fill(offset.begin(), offset.end() - 1);
        for (const Edge<Length>& e : edges) {
            adjacent[fill[e.a]++] = {e.length2, e.b};
            adjacent[fill[e.b]++] = {e.length2, e.a};
        }
    }
    std::vector<Edge<Length>>().swap(edges);
    // Orient away from each component's first vertex (input order). A
    // vertex's children are some of its forest edges: they are written
    // over the front of its own run of `adjacent`, then gathered; their
    // counts go in forest.start, one place on, and are summed after.
    Forest forest;
    forest.start.assign(n + 1, 0);
    std::vector<uint8_t> seen(n, 0);
    std::vector<uint32_t> stack;
    for (size_t root = 0; root < n; ++root) {
        if (seen[root]) continue;
        seen[root] = 1;
        stack.push_back(uint32_t(root));
        while (!stack.empty()) {
            const uint32_t v = stack.back();
            stack.pop_back();
            const auto first = adjacent.begin() + ptrdiff_t(offset[v]), last = adjacent.begin() + ptrdiff_t(offset[v + 1]);
            std::sort(first, last);
            auto kept = first;
            for (auto next = first; next != last; ++next)
                if (!seen[next->second]) {
                    seen[next->second] = 1;
                    *kept++ = *next;
                    stack.push_back(next->second);
                }
            forest.start[v + 1] = uint32_t(kept - first);
        }
    }
    for (size_t v = 0; v < n; ++v) forest.start[v + 1] += forest.start[v];
    forest.child.resize(forest.start[n]);
    for (uint32_t v = 0; v < n; ++v)
        for (uint32_t c = 0; c < forest.childCount(v); ++c)
            forest.child[forest.start[v] + c] = adjacent[offset[v] + c].second;
    return forest;
}

}  // namespace

// Minimum spanning forest of the k-nearest-neighbour graph, children
// nearest first.
Forest spanningForest(const std::vector<int32_t>& grid, const NearestNeighbours& nearest) {
    const size_t n = grid.size() / 3;
    if (n < 2) {
        Forest lone;
        lone.start.assign(n + 1, 0);
        return lone;
    }
    // No coordinate difference exceeds the coordinates' range (at most 21
    // bits: the test cannot overflow).
    const auto range = std::minmax_element(grid.begin(), grid.end());
    const int64_t span = int64_t(*range.second) - int64_t(*range.first);
    if (3 * span * span <= int64_t(std::numeric_limits<uint32_t>::max())) return spanningForestOf<uint32_t>(grid, nearest);
    return spanningForestOf<int64_t>(grid, nearest);
}

// The encoder may visit children in any order; the first child of a vertex
// is predicted by going straight on from its parent, so it should be the
// child that lies most nearly straight on (others use sibling predictions).
void orderChildrenForPrediction(const std::vector<int32_t>& grid, Forest& forest) {
    const size_t n = forest.vertexCount();
    std::vector<uint32_t> parentOf(n, kNoVertex);
    for (uint32_t v = 0; v < n; ++v)
        for (const uint32_t* c = forest.begin(v); c != forest.end(v); ++c) parentOf[*c] = v;
    for (uint32_t v = 0; v < n; ++v) {
        if (parentOf[v] == kNoVertex || forest.childCount(v) < 2) continue;
        const GridPoint at = gridPointOf(grid, v);
        const GridPoint straight = at + (at - gridPointOf(grid, parentOf[v]));
        std::stable_sort(forest.begin(v), forest.end(v), [&](uint32_t a, uint32_t b) {
            return residualCost(gridPointOf(grid, a) - straight) < residualCost(gridPointOf(grid, b) - straight);
        });
    }
}

// The depth-first preorder of the forest (roots in input order, children
// nearest first), as input vertices.
std::vector<uint32_t> preorder(const Forest& forest) {
    const size_t n = forest.vertexCount();
    std::vector<uint8_t> isChild(n, 0);
    for (uint32_t c : forest.child) isChild[c] = 1;
    std::vector<uint32_t> order, stack;
    order.reserve(n);
    for (size_t root = 0; root < n; ++root) {
        if (isChild[root]) continue;
        stack.push_back(uint32_t(root));
        while (!stack.empty()) {
            const uint32_t v = stack.back();
            stack.pop_back();
            order.push_back(v);
            for (const uint32_t* c = forest.end(v); c != forest.begin(v);) stack.push_back(*--c);
        }
    }
    return order;
}

}  // namespace drm
