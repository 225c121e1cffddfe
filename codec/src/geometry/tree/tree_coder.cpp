#include "geometry/tree/tree_coder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <future>
#include <numeric>
#include <string>
#include <utility>

#include "common.h"
#include "concurrency.h"
#include "entropy/range_coder.h"
#include "geometry/tree/spanning_tree.h"
#include "geometry/tree/tree_coding.h"
#include "geometry/tree/tree_pricing.h"
#include "mesh/quantize.h"

namespace drm {

using namespace tree_coding;


// The side of the cells the coders search for near points: about three
// times the typical distance to the kNearest-th neighbour, as a power of two
// (the search covers at least half a cell around the parent).
int cellBitsFor(double spacing, int bits) { return std::min(bits, bitLength(uint32_t(std::min(3 * spacing, 1e9)))); }

namespace {

// How many nearest neighbours of each vertex the encoder's tree may take
// as its children (joined both ways): 4 by default, within a fraction of a
// per cent of the best single count over the corpus (docs/tuning.md). The
// count that codes smallest differs from mesh to mesh, so
// TreeNeighbours::Several and SeveralEveryWay try 4, 8, 2 and 16 (below),
// the first of equal sections kept.
constexpr int kTreeNeighbours = 4;
constexpr int kTreeNeighbourCountsTried = 4;
constexpr int kTreeNeighbourCounts[kTreeNeighbourCountsTried] = {kTreeNeighbours, 8, 2, 16};
// SeveralEveryWay chooses among the first three on the first way; the
// last, the widest graph, is grown under one way only.
constexpr int kTreeNeighbourCountsEveryWay = 3;
constexpr int kTreeNeighbourCountsMost = 16;
// At most this many of a vertex's neighbours are looked at per step. A
// surface vertex has about 6 to 10 in the symmetric graph of 4 nearest
// (16 to 24 in that of 16 nearest, where this bounds the pricing of
// ordinary vertices too); beyond, only coincident points make hubs (ties
// go to the lowest index, so m copies of a point all list the same four,
// which then have m neighbours each, and pricing them all at every step
// would cost m^2).
constexpr size_t kMaxNeighboursLooked = 32;
static_assert(kMaxNeighboursLooked <= size_t(kMaxPricedTogether), "cheapestPick prices them together");

// The encoder's tree, grown depth first over the neighbour graph: the next
// child of the vertex on top of the stack is its undecoded neighbour that
// costs least to code next under the models as they stand (its best
// prediction's residual plus naming that prediction); a vertex leaves the
// stack when no neighbour is left undecoded. The coding is done as it
// goes, so the models are the section's own at each step (child
// counts aside: they have models of their own and do not steer the
// choice). The decoder needs none of this: it reads the tree's shape from
// the child counts. A minimum spanning tree orders by edge length; this
// orders by how well a vertex can be predicted. Returns the vertices in
// coding order (the tree's preorder: each tree whole, roots in input order)
// and their child counts. The coding is kept in `log`, one unit a
// vertex in preorder (a root's coordinates, any other's choice and
// residuals): all of the section but the child counts, which are known
// only once the tree is grown (writeGrownTree puts them in).
// With a budget (TreeBudget), growing stops where the budget gives the
// tree up: `givenUp` is set and the rest is incomplete. `pickBits` (may be
// null) gets what each vertex cost when picked, by input index.
struct GrownTree {
    std::vector<uint32_t> order;       // coding order -> input vertex
    std::vector<uint32_t> childCount;  // per input vertex (counts, not lists: 8 bytes a vertex, not about 56)
    bool givenUp = false;
};
// The budget's test after each sixteenth of the vertices, from the fourth
// on: the first ones are mostly the models learning (as for the spanning
// tree against the cheapest-first one, below).
constexpr size_t kBudgetSteps = 16;
constexpr size_t kBudgetFromStep = 4;
GrownTree cheapestFirstTree(const std::vector<int32_t>& grid, int bits, const NeighbourGraph& graph, int cellBits,
                            bool flagChoices, bool frame, CodingLog& log, uint64_t& framedResiduals,
                            const TreeBudget* budget, std::vector<float>* pickBits) {
    const size_t n = grid.size() / 3;
    GrownTree grown;
    grown.order.reserve(n);
    grown.childCount.assign(n, 0);
    if (pickBits) pickBits->assign(n, 0.0f);
    if (budget && (!budget->rivalPickBits || budget->rivalPickBits->size() != n))
        throw Error(ErrorKind::Internal, "internal error: a geometry tree's budget is for another grid");
    // What the vertices coded so far cost here and in the budget's rival;
    // `picked` tells whether the budget gives the tree up (never once every
    // vertex is coded: the section's own size then decides).
    double spent = 0, rivalSpent = 0;
    const size_t step = std::max<size_t>(1, (n + kBudgetSteps - 1) / kBudgetSteps);
    auto picked = [&](uint32_t vertex, double cost, uint32_t coded) {
        if (pickBits) (*pickBits)[vertex] = float(cost);
        if (!budget) return false;
        spent += cost;
        rivalSpent += double((*budget->rivalPickBits)[vertex]);
        if (coded % step != 0 || coded / step < kBudgetFromStep || coded == n) return false;
        const double extrapolated = budget->rivalBits + (spent - rivalSpent) * double(n) / double(coded);
        return extrapolated > budget->bits + budget->margin;
    };
    std::vector<uint8_t> done(n, 0);
    // Per vertex, where its undecoded neighbours begin: a vertex decoded
    // stays decoded, so the cursor only moves on.
    std::vector<uint32_t> cursor(graph.offset.begin(), graph.offset.end() - 1);  // offset has n + 1 entries
    CodingState s(cellBits, flagChoices, frame);
    s.pos.reserve(n);
    s.parentOf.reserve(n);
    s.magnitude.reserve(3 * n);
    s.signs.reserve(3 * n);
    s.childCountOf.reserve(n);
    s.cells.reserve(n);  // grown by doubling, it held up to three times this while it moved
    LogWriter io{log};
    struct Frame {
        uint32_t vertex, decoded;
    };
    std::vector<Frame> stack;
    uint32_t self = 0;
    for (uint32_t root = 0; root < n; ++root) {
        if (done[root]) continue;
        done[root] = 1;
        s.begin(kNoVertex);
        const GridPoint rootAt = gridPointOf(grid, root);
        for (int32_t c : {rootAt.x, rootAt.y, rootAt.z}) log.encodeWideBits(uint32_t(c), bits);
        log.endUnit();
        s.place(self, rootAt);
        grown.order.push_back(root);
        stack.push_back({root, self++});
        if (picked(root, 3.0 * bits, self)) {
            grown.givenUp = true;
            return grown;
        }
        while (!stack.empty()) {
            const Frame top = stack.back();
            const uint32_t* first = graph.neighbour.data() + cursor[top.vertex];
            const uint32_t* end = graph.end(top.vertex);
            while (first != end && done[*first]) ++first;
            cursor[top.vertex] = uint32_t(first - graph.neighbour.data());
            if (first == end) {
                stack.pop_back();
                continue;
            }
            const uint32_t* last = first + std::min<size_t>(size_t(end - first), kMaxNeighboursLooked);
            const Predictions p = predict(s, self, top.decoded);
            int contexts[kResidualGroups][3];
            magnitudeContexts(s, p, self, top.decoded, contexts);
            const Pricing price(s, p, contexts);
            // *first is undecoded: the pick even if every price were NaN.
            uint32_t undecoded[kMaxNeighboursLooked];
            int count = 0;
            for (const uint32_t* w = first; w != last; ++w)
                if (!done[*w]) undecoded[count++] = *w;
            const Pick nextPick =
                cheapestPick(price, p, count, [&](int i) { return gridPointOf(grid, undecoded[i]); });
            const uint32_t next = undecoded[nextPick.vertex];
            done[next] = 1;
            ++grown.childCount[top.vertex];
            grown.order.push_back(next);
            s.begin(top.decoded);
            const GridPoint at = gridPointOf(grid, next);
            codeChild(io, s, self, top.decoded, p, at, nextPick.candidate);
            log.endUnit();
            s.place(self, at);
            stack.push_back({next, self++});
            if (picked(next, nextPick.bits, self)) {
                grown.givenUp = true;
                return grown;
            }
        }
    }
    framedResiduals = s.framedResiduals;
    return grown;
}

// The tree's section begins with the cell size and how the predictor
// choice is coded.
void writeTreeHeader(RangeEncoder& coder, int cellBits, bool flagChoices, bool frame) {
    coder.encodeBits(uint32_t(cellBits), kCellBitsWidth);
    coder.encodeBits(flagChoices ? 1 : 0, 1);
    coder.encodeBits(frame ? 1 : 0, 1);  // G
}

// The section of a tree cheapestFirstTree grew: each vertex's unit of its
// log, then the vertex's child count. `vertexBits` gets what each vertex
// (by input index) cost, both together.
std::vector<uint8_t> writeGrownTree(const CodingLog& log, int cellBits, const std::vector<uint32_t>& childCount,
                                    const std::vector<uint32_t>& order, bool flagChoices, bool frame,
                                    std::vector<float>& vertexBits) {
    RangeEncoder coder;
    Writer io{coder};
    writeTreeHeader(coder, cellBits, flagChoices, frame);
    CodingState s(cellBits, flagChoices, frame);  // for the child counts' models
    s.parentOf.reserve(order.size());
    s.childCountOf.reserve(order.size());
    TreeWalk walk;
    vertexBits.assign(order.size(), 0.0f);
    size_t at = 0;
    double before = coder.bitsSoFar();
    for (uint32_t self = 0; self < order.size(); ++self) {
        s.parentOf.push_back(walk.enter());
        at = log.replayInto(coder, at);
        const uint32_t count = childCount[order[self]];
        codeChildCount(io, s, self, count);
        walk.expect(self, count);
        const double after = coder.bitsSoFar();
        vertexBits[order[self]] = float(after - before);
        before = after;
    }
    return coder.finish();
}

// The spanning tree against the cheapest-first one, on meshes of at least
// kAbandonFromVertices: after each sixteenth of its vertices, from
// kAbandonFromStep sixteenths on, it is given up if it has spent more than
// kAbandonOverRival times what the cheapest-first section spent on the
// same vertices. Compared vertex for vertex the two settle early: on the
// corpus the large meshes where the spanning tree wins (crank, octopus)
// stay under 1.00 from 4/16 on, those where it loses run over 1.015 all
// the way (docs/tuning.md); a comparison of the sections' sizes at the
// same fraction of the way would compare different vertices and could not
// tell a scan such as igea from a CAD mesh such as crank. Small meshes are
// left out: they cost little either way, and there the spanning tree can
// win after trailing by 10 % (teapot). The first sixteenth is left out of
// both sums: it is mostly the models learning, and a spanning tree that
// wins in the end can trail far behind over it (on a regular lattice,
// nearly twice the cheapest-first tree's bits).
constexpr size_t kSteps = 16;
constexpr double kAbandonOverRival = 1.015;
constexpr size_t kAbandonFromStep = 4;
constexpr size_t kAbandonFromVertices = 16384;
// Before that, from 2/16 on, a tree more than 1.8 % behind is given up:
// the clear losers on the corpus are, the winners are not, and the files
// are those of a looser margin, for less encoding time (docs/tuning.md).
constexpr double kAbandonEarlyOverRival = 1.018;
constexpr size_t kAbandonEarlyFromStep = 2;

// The section of any tree: each vertex in preorder (a root raw, any other
// as a predicted residual) with its child count. With a rival (another
// section's size and cost per vertex, by input index), coding stops,
// returning nothing, once this section must end larger than the rival, or
// runs clearly over it on the same vertices (kAbandonOverRival).
std::vector<uint8_t> codeTree(const std::vector<int32_t>& grid, int bits, int cellBits,
                              const Forest& forest, const std::vector<uint32_t>& order,
                              bool flagChoices, bool frame, uint64_t& framedResiduals,
                              const std::vector<float>* rivalBits = nullptr, size_t rivalSize = 0) {
    const size_t n = order.size();
    RangeEncoder coder;
    Writer io{coder};
    writeTreeHeader(coder, cellBits, flagChoices, frame);
    CodingState s(cellBits, flagChoices, frame);
    s.pos.reserve(n);
    s.parentOf.reserve(n);
    s.magnitude.reserve(3 * n);
    s.signs.reserve(3 * n);
    s.childCountOf.reserve(n);
    s.cells.reserve(n);  // grown by doubling, it held up to three times this while it moved
    TreeWalk walk;
    const size_t step = (n + kSteps - 1) / kSteps;
    double start = coder.bitsSoFar();
    double rivalSpent = 0;
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t vertex = order[self];
        const GridPoint at = gridPointOf(grid, vertex);
        const uint32_t parent = walk.enter();
        s.begin(parent);
        if (parent == kNoVertex) {
            for (int32_t c : {at.x, at.y, at.z}) coder.encodeWideBits(uint32_t(c), bits);
        } else {
            codeChild(io, s, self, parent, predict(s, self, parent), at);
        }
        s.place(self, at);
        codeChildCount(io, s, self, forest.childCount(vertex));
        walk.expect(self, forest.childCount(vertex));
        if (!rivalBits) continue;
        rivalSpent += double((*rivalBits)[vertex]);
        if ((self + 1) % step != 0) continue;
        if (coder.bytesAtLeast() > rivalSize) return {};
        const size_t stepsDone = (self + 1) / step;
        if (stepsDone == 1) {
            start = coder.bitsSoFar();
            rivalSpent = 0;
        }
        const double over = stepsDone >= kAbandonFromStep        ? kAbandonOverRival
                            : stepsDone >= kAbandonEarlyFromStep ? kAbandonEarlyOverRival
                                                                 : 0.0;
        if (n >= kAbandonFromVertices && over > 0 && coder.bitsSoFar() - start > over * rivalSpent)
            return {};
    }
    framedResiduals = s.framedResiduals;
    return coder.finish();
}

}  // namespace

// Below this many vertices the spanning forest is built on the calling
// thread: a second one costs more than the forest.
constexpr size_t kForestBesideFromVertices = 16384;
// FourUnlessRegular (TreeNeighbours): the other counts' trees are given up
// where their extrapolated sections run this share of the tree over the 4
// nearest past the best section so far (as refine's estimates are,
// encode/refine_policy.cpp).
constexpr double kRegularCountsMargin = 0.03;
// Above this many vertices FourUnlessRegular is Four: the search for 16
// nearest, the wider graphs and the pick bits would add to the encoder's
// peak memory where it is highest, the vertex section being coded beside
// the early connectivity there (encode/encode_session.h).
constexpr size_t kRegularUpToVertices = size_t(1) << 18;

// Two trees, each with the choice coded both ways, the smallest section
// kept (the decoder reads any the same way): the cheapest-first tree wins
// on most meshes (fandisk: 10.30 bits a vertex against the spanning tree's
// 13.26), the minimum spanning tree with its children ordered straight on
// on some regular CAD meshes (blade: 3.67 against 4.20). Flags win on most
// meshes; one symbol on coarse grids, where candidates pile up (refine's
// coarse tree), and on some artist meshes (hero).
GeometryEncoding encodeGeometryTree(const std::vector<int32_t>& grid, int bits, NeighbourIndex index,
                                    GeometryTree which, ChoiceCoding choices, FrameUse frames,
                                    GeometryTreeTrials* trials, int threads, TreeNeighbours treeNeighbours) {
    GeometryTreeTrials own;
    if (!trials) trials = &own;
    if (trials->nearest && (trials->vertexCount != grid.size() / 3 || trials->bits != bits))
        throw Error(ErrorKind::Internal, "internal error: geometry tree trials reused for another grid");
    // Several neighbour counts need each vertex's kTreeNeighbourCountsMost
    // nearest; the spanning forest takes the first kNeighbours of them (the
    // same as a search for that many: ties go by index either way).
    const bool fourFirst = treeNeighbours == TreeNeighbours::Four || treeNeighbours == TreeNeighbours::FourUnlessRegular;
    const int nearestWanted = fourFirst ? kNeighbours : kTreeNeighbourCountsMost;
    if (!trials->nearest || trials->nearest->k < nearestWanted) {
        trials->vertexCount = grid.size() / 3;
        trials->bits = bits;
        trials->nearest = std::make_shared<const NearestNeighbours>(nearestNeighbours(grid, index, nearestWanted, threads));
    }
    // Held: FourUnlessRegular may search the neighbours again into the trials.
    const std::shared_ptr<const NearestNeighbours> nearestHeld = trials->nearest;
    const NearestNeighbours& nearest = *nearestHeld;
    const int cellBits = cellBitsFor(nearest.spacing, bits);
    GeometryEncoding* best = nullptr;
    // The cheapest-first tree's neighbour counts (kTreeNeighbourCounts, by
    // index). Every way grows the tree over the 4 nearest. With several
    // counts, one way also grows it over the others (SeveralEveryWay: the
    // first way; Several: the way that coded the 4 nearest smallest), and
    // `chosen` is the count that coded smallest there (< 0: not yet chosen;
    // an earlier call's choice is kept in the trials). SeveralEveryWay grows
    // a chosen count other than the 4 nearest under every later way too.
    int countsTried = fourFirst ? 1 : kTreeNeighbourCountsTried;
    // An earlier call's choice among the counts (-1: none).
    auto chosenBefore = [&] {
        for (int c = 0; c < kTreeNeighbourCountsTried; ++c)
            if (trials->treeNeighbours == kTreeNeighbourCounts[c]) return c;
        return -1;
    };
    int chosen = countsTried > 1 ? chosenBefore() : 0;
    NeighbourGraph graphs[kTreeNeighbourCountsTried];
    Forest spanning;  // kept for the next trial
    // The ways asked for, in the order tried (see the loop below).
    std::vector<std::pair<bool, bool>> ways;  // (flags, frame)
    for (ChoiceCoding coding : {ChoiceCoding::Flags, ChoiceCoding::Symbol})
        for (FrameUse use : {FrameUse::On, FrameUse::Off})
            if ((choices == ChoiceCoding::Smaller || choices == coding) && (frames == FrameUse::Smaller || frames == use))
                ways.emplace_back(coding == ChoiceCoding::Flags, use == FrameUse::On);
    auto buildSpanningForest = [&] {
        spanning = nearest.k > kNeighbours ? spanningForest(grid, nearestOnly(nearest, kNeighbours))
                                           : spanningForest(grid, nearest);
        orderChildrenForPrediction(grid, spanning);
    };
    // With a second thread, the spanning forest is built there while the
    // cheapest-first tree grows here (the forest is about 7 % of a scan's
    // encoding); it is the same forest.
    std::future<void> forestBuilding;
    if (threads >= 2 && which == GeometryTree::Smaller && grid.size() / 3 >= kForestBesideFromVertices) {
        bool uncoded = false;
        for (const auto& way : ways) uncoded |= trials->coded.count((way.first ? 2 : 0) + (way.second ? 1 : 0)) == 0;
        if (uncoded) forestBuilding = startBeside(buildSpanningForest);
    }
    // Codes one way, unless an earlier call did.
    // A section given up on (empty: a spanning tree against a cheapest-first
    // one, codeTree, or a tree held to a budget) is kept as such, and is
    // never the best; a call that asks for that tree alone codes it again.
    auto trial = [&](bool cheapestFirst, int count, bool flagChoices, bool frame, auto codeOneWay) -> size_t {
        const int key = sectionKey(cheapestFirst, count, flagChoices, frame);
        auto found = trials->coded.find(key);
        if (found != trials->coded.end() && found->second.bytes.empty() && which != GeometryTree::Smaller) {
            trials->coded.erase(found);
            found = trials->coded.end();
        }
        if (found == trials->coded.end()) found = trials->coded.emplace(key, codeOneWay(flagChoices, frame)).first;
        if (found->second.bytes.empty()) return SIZE_MAX;
        if (!best || found->second.bytes.size() < best->bytes.size()) best = &found->second;
        return found->second.bytes.size();
    };
    // FourUnlessRegular holds the other counts' trees to the best section
    // so far (TreeBudget), against the tree over the 4 nearest coded the
    // same way: what each vertex cost when picked there is kept for that
    // (4 bytes a vertex), in the trials where they keep them, else here.
    const bool pickBitsForRegular = treeNeighbours == TreeNeighbours::FourUnlessRegular &&
                                    which == GeometryTree::Smaller && grid.size() / 3 <= kRegularUpToVertices;
    std::map<int, std::vector<float>> ownPickBits;
    std::map<int, std::vector<float>>& pickBitsKept = trials->keepPickBits ? trials->pickBits : ownPickBits;
    auto cheapestFirst = [&](int count, bool flagChoices, bool frame) {
        NeighbourGraph& graph = graphs[count];
        if (graph.offset.empty()) graph = symmetricGraph(*trials->nearest, kTreeNeighbourCounts[count]);
        CodingLog log;
        // Scans log 11 to 15 words a vertex: reserved, the log is not grown
        // by doubling, which would hold up to three times its size while it
        // moves.
        log.reserve(16 * (grid.size() / 3));
        GeometryEncoding coded;
        const int bitsKey = treeBitsKey(count, flagChoices, frame);
        const bool keepPicks = count == 0 && (trials->keepPickBits || pickBitsForRegular);
        GrownTree grown = cheapestFirstTree(grid, bits, graph, cellBits, flagChoices, frame, log, coded.framedResiduals,
                                            trials->budget, keepPicks ? &pickBitsKept[bitsKey] : nullptr);
        if (grown.givenUp) {
            if (keepPicks) pickBitsKept.erase(bitsKey);
            return GeometryEncoding();
        }
        coded.order = std::move(grown.order);
        std::vector<float>& vertexBits = trials->vertexBits[bitsKey];
        coded.bytes = writeGrownTree(log, cellBits, grown.childCount, coded.order, flagChoices, frame, vertexBits);
        return coded;
    };
    auto spanningTree = [&](bool flagChoices, bool frame) {
        if (forestBuilding.valid()) forestBuilding.get();
        if (spanning.start.empty()) buildSpanningForest();
        // Against the cheapest-first tree coded the same way, where it was
        // (over the 4 nearest, or the chosen count where that coded smaller).
        auto rival = trials->coded.find(sectionKey(true, 0, flagChoices, frame));
        auto rivalBits = trials->vertexBits.find(treeBitsKey(0, flagChoices, frame));
        if (chosen > 0) {
            const auto other = trials->coded.find(sectionKey(true, chosen, flagChoices, frame));
            const auto otherBits = trials->vertexBits.find(treeBitsKey(chosen, flagChoices, frame));
            if (other != trials->coded.end() && otherBits != trials->vertexBits.end() &&
                (rival == trials->coded.end() || other->second.bytes.size() < rival->second.bytes.size())) {
                rival = other;
                rivalBits = otherBits;
            }
        }
        const bool against = which == GeometryTree::Smaller && rival != trials->coded.end() &&
                             rivalBits != trials->vertexBits.end();
        GeometryEncoding coded;
        coded.order = preorder(spanning);
        coded.bytes = codeTree(grid, bits, cellBits, spanning, coded.order, flagChoices, frame, coded.framedResiduals,
                               against ? &rivalBits->second : nullptr, against ? rival->second.bytes.size() : 0);
        return coded;
    };
    // The cheapest-first tree over `count` (an index), coded one way; the
    // first way that grows the other counts chooses among them.
    auto grow = [&](int count, const std::pair<bool, bool>& way) {
        return trial(true, count, way.first, way.second,
                     [&](bool flags, bool frame) { return cheapestFirst(count, flags, frame); });
    };
    // Grows the counts from 1 up to `upTo` (an index) under `way`, choosing
    // among them and the 4 nearest (`four`: that tree's size), unless an
    // earlier call chose (then the chosen count alone).
    auto growOthers = [&](const std::pair<bool, bool>& way, size_t four, int upTo) {
        if (chosen > 0) grow(chosen, way);
        if (chosen >= 0) return;
        size_t least = four;
        chosen = 0;
        for (int c = 1; c < upTo; ++c) {
            const size_t size = grow(c, way);
            if (size < least) {
                least = size;
                chosen = c;
            }
        }
        trials->treeNeighbours = kTreeNeighbourCounts[chosen];
    };
    const bool othersEveryWay = treeNeighbours == TreeNeighbours::SeveralEveryWay;
    for (const auto& way : ways) {
        // The cheapest-first tree is grown under the coding it is written with.
        if (which != GeometryTree::SpanningTree) {
            const size_t four = grow(0, way);
            if (othersEveryWay) growOthers(way, four, kTreeNeighbourCountsEveryWay);
        }
        if (which != GeometryTree::CheapestFirst) trial(false, 0, way.first, way.second, spanningTree);
    }
    // FourUnlessRegular: a spanning tree coded to the end (a regular mesh).
    bool regular = false;
    if (pickBitsForRegular) {
        for (const auto& way : ways) {
            const auto found = trials->coded.find(sectionKey(false, 0, way.first, way.second));
            regular |= found != trials->coded.end() && !found->second.bytes.empty();
        }
        if (regular) {
            if (trials->nearest->k < kTreeNeighbourCountsMost)
                trials->nearest = std::make_shared<const NearestNeighbours>(
                    nearestNeighbours(grid, index, kTreeNeighbourCountsMost, threads));
            countsTried = kTreeNeighbourCountsTried;
            chosen = chosenBefore();
        }
    }
    if (which != GeometryTree::SpanningTree && countsTried > 1) {
        // The way whose cheapest-first tree coded smallest so far (the
        // first of equals): Several grows the other counts under it and
        // chooses; SeveralEveryWay, the widest graph.
        std::pair<bool, bool> bestWay = ways.front();
        size_t least = SIZE_MAX;
        for (const auto& way : ways)
            for (int c = 0; c < countsTried; ++c) {
                const auto found = trials->coded.find(sectionKey(true, c, way.first, way.second));
                if (found != trials->coded.end() && !found->second.bytes.empty() && found->second.bytes.size() < least) {
                    least = found->second.bytes.size();
                    bestWay = way;
                }
            }
        // A regular mesh's other counts, against the tree over the 4 nearest
        // coded the best way (a refine attempt's coarse tree over the 4
        // nearest, grown by its estimate, kept no pick bits: there they
        // are grown to the end).
        TreeBudget budget;
        bool budgeted = false;
        if (regular && !trials->budget && best) {
            const auto kept = pickBitsKept.find(treeBitsKey(0, bestWay.first, bestWay.second));
            const auto rival = trials->coded.find(sectionKey(true, 0, bestWay.first, bestWay.second));
            if (kept != pickBitsKept.end() && rival != trials->coded.end() && !rival->second.bytes.empty()) {
                budget.rivalPickBits = &kept->second;
                budget.rivalBits = 8.0 * double(rival->second.bytes.size());
                budget.bits = 8.0 * double(best->bytes.size());
                budget.margin = kRegularCountsMargin * budget.rivalBits;
                budgeted = true;
            }
        }
        const BudgetScope scope(*trials, budgeted ? &budget : nullptr);
        if (othersEveryWay)
            grow(kTreeNeighbourCountsTried - 1, bestWay);
        else
            growOthers(bestWay, least, countsTried);
    }
    if (forestBuilding.valid()) forestBuilding.get();  // every spanning trial was coded before
    if (!best) {  // every tree given up: only a budget may do that
        if (!trials->budget)
            throw Error(ErrorKind::Internal, "internal error: no geometry tree was coded to the end");
        return GeometryEncoding();
    }
    return trials == &own ? std::move(*best) : *best;
}

}  // namespace drm
