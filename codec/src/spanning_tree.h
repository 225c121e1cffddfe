// The spanning tree of the geometry coder: a minimum spanning forest over
// the vertices' nearest neighbours, its children ordered for prediction,
// its depth-first preorder (the decoded vertex order), and the walk that
// rebuilds the tree's shape from child counts on both sides.
#ifndef DRM_SPANNING_TREE_H
#define DRM_SPANNING_TREE_H

#include <cstdint>
#include <vector>

#include "common.h"
#include "drm/drm.h"

namespace drm {

constexpr int kNeighbours = 8;  // spanning tree over the 8-nearest-neighbour graph

// Minimum spanning forest of the kNeighbours-nearest-neighbour graph of the
// grid points, as child lists, children nearest first; *spacing is set to
// the typical distance to the kNearest-th neighbour (grid steps).
std::vector<std::vector<uint32_t>> spanningForest(const std::vector<int32_t>& grid, NeighbourIndex index,
                                                  double* spacing);

// Puts first, among each vertex's children, the one lying most nearly
// straight on from its parent (the first child is predicted that way).
void orderChildrenForPrediction(const std::vector<int32_t>& grid, std::vector<std::vector<uint32_t>>& children);

// The depth-first preorder of the forest (roots in input order), as input
// vertices.
std::vector<uint32_t> preorder(const std::vector<std::vector<uint32_t>>& children);

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
