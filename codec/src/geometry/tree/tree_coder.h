// The vertex set coder: a tree over near neighbours, walked depth first; each vertex is coded as the residual from a prediction the decoder
// can rebuild from vertices it already has (parent, grandparent, siblings,
// the previous tree edge), the encoder picking the best and coding which.
// This is the family the method notes measured best among connectivity-free
// point coders (bunny 11.3 bpv, horse 11.3 at 12 bits).
//
// The tree defines the decoded vertex order (depth-first preorder).
#ifndef DRM_TREE_CODER_H
#define DRM_TREE_CODER_H

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm {

struct GeometryEncoding {
    std::vector<uint8_t> bytes;
    std::vector<uint32_t> order;  // order[i] = input index of decoded vertex i
    uint64_t framedResiduals = 0; // residuals coded in the parent's local frame (bit G)
};

// Which tree the encoder builds: by default both, keeping the smaller
// section (the decoder reads either the same way).
enum class GeometryTree { Smaller, CheapestFirst, SpanningTree };
// How the section names each vertex's predictor (its bit F): one flag per
// candidate, or one symbol over all; by default both are tried.
enum class ChoiceCoding { Smaller, Flags, Symbol };
// Whether the section may code residuals from the parent in its local
// frame (its bit G); by default both are tried.
enum class FrameUse { Smaller, On, Off };
// Which nearest neighbours of each vertex the cheapest-first tree may take
// as its children. Four: its 4 nearest. Several: also its 8, 2 and 16
// nearest, under the way (choice coding, frame) whose tree over the 4
// nearest coded smallest. SeveralEveryWay: the first way tried also grows
// the tree over the 8 and the 2 nearest, the count of the three that
// codes smallest there is grown under every other way too, and the tree
// over the 16 nearest under the way whose tree coded smallest. The tree
// over the 4 nearest is grown under every way in each case, so no section
// is larger than with Four. FourUnlessRegular: as Four, and as Several where
// a spanning tree was coded to the end (given up nowhere: a regular mesh,
// as CAD meshes are), the neighbours then searched again for 16; on
// meshes of up to 262,144 vertices (larger ones stay with Four: the wider
// search and its graphs would add to the encoder's peak memory).
enum class TreeNeighbours { Four, Several, SeveralEveryWay, FourUnlessRegular };

struct NearestNeighbours;

// What a cheapest-first tree is held to while it grows (refine's estimate,
// encode/refine_policy.cpp; FourUnlessRegular's other counts): another
// tree over the same vertices, coded earlier, and the section size this
// one must stay under. After each sixteenth of its vertices from the
// fourth on, the tree extrapolates its size from what
// its vertices cost so far against what the same vertices cost in the
// rival (each as priced when it was picked: residual and choice, child
// counts left out), and is given up (the section comes back empty) where
// that passes `bits` by more than `margin`.
struct TreeBudget {
    const std::vector<float>* rivalPickBits = nullptr;  // per input vertex
    double rivalBits = 0;  // the rival's section
    double bits = 0;
    double margin = 0;
};

// The keys of GeometryTreeTrials' maps: a section by tree, neighbour count
// (an index into the counts tried: 0 is the 4 nearest), choice coding and
// frame; a cheapest-first tree's per-vertex figures by the same less the
// tree.
inline int treeBitsKey(int countIndex, bool flagChoices, bool frame) {
    return 4 * countIndex + (flagChoices ? 2 : 0) + (frame ? 1 : 0);
}
inline int sectionKey(bool cheapestFirst, int countIndex, bool flagChoices, bool frame) {
    return 8 * countIndex + (cheapestFirst ? 4 : 0) + (flagChoices ? 2 : 0) + (frame ? 1 : 0);
}

// What encodeGeometryTree has worked out for one grid: its near neighbours
// and every section it coded, by tree, neighbour count, choice coding and
// frame. An encoder that codes the same grid twice (refine's estimate, then
// refine's attempt on the same coarse grid) passes the same trials to both,
// and nothing is grown or coded twice (the neighbours aside: a call with
// several neighbour counts after one with TreeNeighbours::Four searches
// 16 nearest again); the section kept is the one a single call would keep,
// but where a budget gave a tree up (kept as an empty section: a later
// call with a budget does not grow it again).
struct GeometryTreeTrials {
    size_t vertexCount = 0;  // of the grid they are for (checked)
    int bits = 0;
    std::shared_ptr<const NearestNeighbours> nearest;
    std::map<int, GeometryEncoding> coded;  // by tree, count, choice coding and frame (a key encodeGeometryTree forms)
    // What each vertex (by input index) cost in the cheapest-first
    // sections, in bits, by choice coding and frame: a spanning tree that
    // codes the same vertices for clearly more is given up.
    std::map<int, std::vector<float>> vertexBits;
    // The cheapest-first tree's neighbour count, once chosen (0: not yet).
    int treeNeighbours = 0;
    // With keepPickBits, what each vertex (by input index) cost when the
    // cheapest-first trees over the 4 nearest picked it (TreeBudget), by
    // the keys of vertexBits: a rival for a later tree's budget.
    bool keepPickBits = false;
    std::map<int, std::vector<float>> pickBits;
    // Where set, every cheapest-first tree grown for these trials is held
    // to it; one given up is kept as an empty section.
    const TreeBudget* budget = nullptr;
};

// Holds trials to a budget for its lifetime (none: leaves them as they are).
class BudgetScope {
public:
    BudgetScope(GeometryTreeTrials& trials, const TreeBudget* budget) : trials_(trials), set_(budget != nullptr) {
        if (set_) trials_.budget = budget;
    }
    ~BudgetScope() {
        if (set_) trials_.budget = nullptr;
    }
    BudgetScope(const BudgetScope&) = delete;
    BudgetScope& operator=(const BudgetScope&) = delete;

private:
    GeometryTreeTrials& trials_;
    bool set_;
};

// Codes the grid with each tree, choice coding and frame asked for and
// returns the smallest section, the first of equal ones in the order they
// are coded: each way in turn (flags, then one symbol; within each, the
// frame on, then off) codes the cheapest-first tree over the 4 nearest,
// with SeveralEveryWay the other counts the first way tries or the count
// chosen there, then the spanning tree; after every way, the counts grown
// under the best way alone. `trials`, when
// given, holds what earlier calls on the same grid worked out, and gets
// what this one works out. With `threads` 2 or more, the neighbour graph and
// the spanning forest use a second thread (the section is the same). The
// section is empty only where the trials' budget gave up every tree asked
// for.
GeometryEncoding encodeGeometryTree(const std::vector<int32_t>& grid, int bits,
                                    NeighbourIndex index = NeighbourIndex::Auto,
                                    GeometryTree tree = GeometryTree::Smaller,
                                    ChoiceCoding choices = ChoiceCoding::Smaller,
                                    FrameUse frames = FrameUse::Smaller,
                                    GeometryTreeTrials* trials = nullptr, int threads = 1,
                                    TreeNeighbours treeNeighbours = TreeNeighbours::Four);

// Reads a section (docs/format.md, "Geometry payload, coder 2: spanning
// tree"). Throws Error on data that does not decode to exactly vertexCount
// vertices on the grid.
std::vector<int32_t> decodeGeometryTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits);

}  // namespace drm

#endif  // DRM_TREE_CODER_H
