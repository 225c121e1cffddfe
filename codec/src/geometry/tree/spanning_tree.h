// The spanning tree of the geometry coder: a minimum spanning forest over
// the vertices' nearest neighbours, its children ordered for prediction,
// its depth-first preorder (the decoded vertex order), and the walk that
// rebuilds the tree's shape from child counts on both sides.
#ifndef DRM_SPANNING_TREE_H
#define DRM_SPANNING_TREE_H

#include <cstdint>
#include <vector>

#include "common.h"
#include "drmcodec/drmcodec.h"

namespace drm {

constexpr int kNeighbours = 8;  // spanning tree over the 8-nearest-neighbour graph

// The k nearest neighbours of every grid point (kNoVertex-padded rows of k,
// nearest first, ties by index) and the typical distance to the
// kNearest-th of them (grid steps), which sizes the coders' cells.
struct NearestNeighbours {
    int k = 0;
    std::vector<uint32_t> neighbours;  // k per vertex
    double spacing = 1;
};
NearestNeighbours nearestNeighbours(const std::vector<int32_t>& grid, NeighbourIndex index, int k, int threads = 1);
// The first k (<= nearest.k) of each row: what a search for k nearest gives.
NearestNeighbours nearestOnly(const NearestNeighbours& nearest, int k);

// The symmetric count-nearest-neighbour graph (v and w joined when either
// is among the other's `count` nearest; count <= nearest.k), compressed rows: the neighbours of v are
// neighbour[offset[v] .. offset[v + 1]), v's own nearest first.
struct NeighbourGraph {
    std::vector<uint32_t> offset, neighbour;
    const uint32_t* begin(uint32_t v) const { return neighbour.data() + offset[v]; }
    const uint32_t* end(uint32_t v) const { return neighbour.data() + offset[size_t(v) + 1]; }
};
NeighbourGraph symmetricGraph(const NearestNeighbours& nearest, int count);

// A forest as child lists in one array: the children of v are
// child[start[v] .. start[v + 1]) (a vector per vertex would cost 24 bytes
// and an allocation each, about 50 bytes a vertex in all).
struct Forest {
    std::vector<uint32_t> start;  // vertexCount() + 1 entries
    std::vector<uint32_t> child;
    size_t vertexCount() const { return start.empty() ? 0 : start.size() - 1; }
    uint32_t childCount(uint32_t v) const { return start[size_t(v) + 1] - start[v]; }
    uint32_t* begin(uint32_t v) { return child.data() + start[v]; }
    uint32_t* end(uint32_t v) { return child.data() + start[size_t(v) + 1]; }
    const uint32_t* begin(uint32_t v) const { return child.data() + start[v]; }
    const uint32_t* end(uint32_t v) const { return child.data() + start[size_t(v) + 1]; }
};

// Minimum spanning forest of the nearest-neighbour graph (all nearest.k
// of each vertex), children nearest first. Each row must run nearest first,
// unfilled places (kNoVertex) last, as nearestNeighbours and nearestOnly
// give them: the forest takes the longest edge to be a row's last.
Forest spanningForest(const std::vector<int32_t>& grid, const NearestNeighbours& nearest);

// Puts first, among each vertex's children, the one lying most nearly
// straight on from its parent (the first child is predicted that way).
void orderChildrenForPrediction(const std::vector<int32_t>& grid, Forest& forest);

// The depth-first preorder of the forest (roots in input order), as input
// vertices.
std::vector<uint32_t> preorder(const Forest& forest);

// The shape of the depth-first walk, rebuilt from the child counts alone:
// before each vertex it tells that vertex's parent (as a decoded index), so
// encoder and decoder predict from the same vertices.
class TreeWalk {
public:
    uint32_t enter() {
        while (!frames_.empty() && frames_.back().childrenLeft == 0) frames_.pop_back();
        if (frames_.empty()) return kNoVertex;
        --frames_.back().childrenLeft;
        return frames_.back().vertex;
    }
    void expect(uint32_t self, uint32_t childCount) {
        if (childCount > 0) frames_.push_back({self, childCount});
    }

private:
    struct Frame {
        uint32_t vertex, childrenLeft;
    };
    std::vector<Frame> frames_;
};

}  // namespace drm

#endif  // DRM_SPANNING_TREE_H
