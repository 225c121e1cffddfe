#include "geometry_tree.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>


#include "drm/drm.h"
#include "bit_model.h"
#include "quantize.h"
#include "range_coder.h"
#include "rank_coder.h"
#include "spatial_index.h"

namespace drm {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr int kNeighbours = 8;       // spanning tree over the 8-nearest-neighbour graph
constexpr int kChoiceContexts = 4;  // predictor choice tables: by the previous choice, clamped
constexpr uint32_t kDirectChildCounts = 8;  // 0..7, then an escape

struct Point {
    int32_t x = 0, y = 0, z = 0;
};
Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

int bitLength(uint32_t m) {
    int n = 0;
    for (; m != 0; m >>= 1) ++n;
    return n;
}

// The shape of the depth-first walk, rebuilt from the child counts alone:
// before each vertex it tells that vertex's parent (as a decoded index), so
// encoder and decoder predict from the same vertices.
class TreeWalk {
public:
    uint32_t enter() {
        while (!frames_.empty() && frames_.back().childrenLeft == 0) frames_.pop_back();
        if (frames_.empty()) return kNone;
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

uint32_t magnitudeOf(int32_t v) { return uint32_t(v < 0 ? -int64_t(v) : v); }

constexpr int kMagnitudeContexts = 8;
constexpr int kMaxLength = 23;      // bit lengths of residuals of 21-bit coordinates
constexpr int kAdaptiveLowBits = 2; // bits below the leading one with a model

// The models of one axis' residuals.
struct AxisModels {
    BitModel zero[kMagnitudeContexts];
    BitModel longer[kMagnitudeContexts][kMaxLength];  // unary bit length: "longer than k"
    BitModel sign;
    BitModel low[kMaxLength + 1][kAdaptiveLowBits];  // by bit length, 1..kMaxLength
};

// A residual: zero or not, the bit length n >= 1 in unary, the sign, then
// the bits below the leading one (the first two adaptive, per n).
template <class Io>
int32_t codeResidual(Io& io, AxisModels& m, int context, int32_t r) {
    const uint32_t magnitude = magnitudeOf(r);
    if (io.bit(m.zero[context], magnitude == 0)) return 0;
    const int n = bitLength(magnitude);
    int length = 1;
    while (length < kMaxLength && io.bit(m.longer[context][length], n > length)) ++length;
    const bool negative = io.bit(m.sign, r < 0) != 0;
    uint32_t value = 1;
    for (int k = 0; k < std::min(length - 1, kAdaptiveLowBits); ++k)
        value = (value << 1) | uint32_t(io.bit(m.low[length][k], (magnitude >> (length - 2 - k)) & 1));
    const int rest = length - 1 - std::min(length - 1, kAdaptiveLowBits);
    value = (value << rest) | io.plain(magnitude, rest);
    return negative ? -int32_t(value) : int32_t(value);
}

// The encoder's estimate of codeResidual's cost, in bits.
double residualBits(const AxisModels& m, int context, int32_t r) {
    const uint32_t magnitude = magnitudeOf(r);
    if (magnitude == 0) return m.zero[context].cost(1);
    const int n = bitLength(magnitude);
    double bits = m.zero[context].cost(0) + 1.0 + (n - 1);
    for (int length = 1; length < kMaxLength && length <= n; ++length) bits += m.longer[context][length].cost(n > length);
    return bits;
}

// The decoded points a prediction is built from are the kNearest decoded
// vertices nearest the parent; the candidates are the parent itself, the
// previous tree edge repeated from the parent, the reflections 2p - q of the
// near points q through the parent, and the parallelograms p + q - w over
// ordered pairs of them (on a surface sampled by near-regular triangles the
// next vertex around p often lies there).
constexpr int kNearest = 4;
constexpr int kMaxCandidates = 2 + kNearest + kNearest * (kNearest - 1);
struct Predictions {
    Point candidate[kMaxCandidates];
    int count = 0;
    void add(Point c) { candidate[count++] = c; }
};

// Cell key -> the cell's latest vertex: open addressing with linear
// probing, grown as cells appear (a decoder's table grows with what it has
// decoded, never with what a header claims). Much cheaper than a node-based
// map on the decoder's path.
class CellHeads {
public:
    // The head of cell `key`, inserted as kNone if absent.
    uint32_t& at(uint64_t key) {
        if (2 * (used_ + 1) > keys_.size()) grow();
        size_t slot = find(key);
        if (keys_[slot] == kEmpty) {
            keys_[slot] = key;
            heads_[slot] = kNone;
            ++used_;
        }
        return heads_[slot];
    }
    uint32_t get(uint64_t key) const {
        if (keys_.empty()) return kNone;
        const size_t slot = find(key);
        return keys_[slot] == key ? heads_[slot] : kNone;
    }

private:
    static constexpr uint64_t kEmpty = ~uint64_t(0);  // keys use 63 bits
    size_t find(uint64_t key) const {
        // The slot is the product's top bits, which every bit of the key
        // reaches (the bits from 20 up, as taken before, never depended on
        // the x field, bits 42 and up: cells sharing y and z collided and
        // a third of predict() went to probing). Which slot a key gets
        // changes nothing but speed.
        const size_t mask = keys_.size() - 1;
        size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - slotBits_));
        while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask;
        return slot;
    }
    void grow() {
        std::vector<uint64_t> keys(std::max<size_t>(64, 2 * keys_.size()), kEmpty);
        std::vector<uint32_t> heads(keys.size(), kNone);
        slotBits_ = 0;
        while ((size_t(1) << slotBits_) < keys.size()) ++slotBits_;
        keys.swap(keys_);
        heads.swap(heads_);
        for (size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != kEmpty) {
                const size_t slot = find(keys[i]);
                keys_[slot] = keys[i];
                heads_[slot] = heads[i];
            }
    }
    std::vector<uint64_t> keys_;
    std::vector<uint32_t> heads_;
    int slotBits_ = 0;  // keys_.size() == 2^slotBits_
    size_t used_ = 0;
};

// The decoded vertices bucketed by cubic cells of side 2^cellBits, to find
// those near a point. Each cell lists its vertices latest first.
class DecodedCells {
public:
    explicit DecodedCells(int cellBits) : cellBits_(cellBits) {}
    int cellBits() const { return cellBits_; }

    void insert(uint32_t v, Point at) {
        uint32_t& head = head_.at(key(at.x, at.y, at.z));
        if (next_.size() <= v) next_.resize(size_t(v) + 1, kNone);
        next_[v] = head;
        head = v;
    }

    // The up to kNearest decoded vertices nearest `at` (other than `self`)
    // in the 2x2x2 block of cells around it (its own cell and, on each axis,
    // the neighbour on its nearer side), nearest first; ties go to the later
    // vertex. Returns how many.
    int nearest(const std::vector<Point>& pos, uint32_t self, Point at, Point* near) const {
        const int64_t side = int64_t(1) << cellBits_;
        const int64_t half = side >> 1;
        const int64_t step[3] = {(at.x & (side - 1)) < half ? -side : side, (at.y & (side - 1)) < half ? -side : side,
                                 (at.z & (side - 1)) < half ? -side : side};
        int64_t distance2[kNearest];
        int count = 0;
        for (int corner = 0; corner < 8; ++corner) {
            const int64_t x = at.x + ((corner & 1) ? step[0] : 0), y = at.y + ((corner & 2) ? step[1] : 0),
                          z = at.z + ((corner & 4) ? step[2] : 0);
            if (x < 0 || y < 0 || z < 0 || x > kCoordinateMax || y > kCoordinateMax || z > kCoordinateMax) continue;
            for (uint32_t v = head_.get(key(int32_t(x), int32_t(y), int32_t(z))); v != kNone; v = next_[v]) {
                if (v == self) continue;
                const Point d = pos[v] - at;
                const int64_t d2 = int64_t(d.x) * d.x + int64_t(d.y) * d.y + int64_t(d.z) * d.z;
                if (count == kNearest && d2 >= distance2[count - 1]) continue;
                int i = count < kNearest ? count++ : count - 1;  // insertion into the sorted list
                for (; i > 0 && distance2[i - 1] > d2; --i) {
                    distance2[i] = distance2[i - 1];
                    near[i] = near[i - 1];
                }
                distance2[i] = d2;
                near[i] = pos[v];
            }
        }
        return count;
    }

private:
    static constexpr int64_t kCoordinateMax = (int64_t(1) << 21) - 1;
    uint64_t key(int32_t x, int32_t y, int32_t z) const {  // coordinates below 2^21: 21 bits each
        return (uint64_t(uint32_t(x) >> cellBits_) << 42) | (uint64_t(uint32_t(y) >> cellBits_) << 21) |
               uint64_t(uint32_t(z) >> cellBits_);
    }
    int cellBits_;
    CellHeads head_;                               // cell -> its latest vertex
    std::vector<uint32_t> next_;                   // vertex -> the one before it in its cell
};

// Everything both sides track while walking the tree.
struct CodingState {
    std::vector<Point> pos;            // decoded positions
    std::vector<uint32_t> parentOf;    // decoded parent, kNone for roots
    std::vector<uint32_t> magnitude;   // |residual| per axis, 3 per vertex
    DecodedCells cells;
    AxisModels axis[3];
    std::vector<AdaptiveFrequencies> predictorChoice;  // [previous choice, clamped]
    AdaptiveFrequencies childCount;
    uint32_t previousChoice = 0;

    explicit CodingState(int cellBits)
        : cells(cellBits),
          predictorChoice(kChoiceContexts, AdaptiveFrequencies(std::vector<uint16_t>(kMaxCandidates, 1))),
          childCount(std::vector<uint16_t>(kDirectChildCounts + 1, 1)) {}

    // Starts vertex `self` (the next decoded index): its parent is known,
    // its residuals not yet.
    void begin(uint32_t parent) {
        parentOf.push_back(parent);
        magnitude.insert(magnitude.end(), 3, 0);
    }
    void place(uint32_t self, Point at) {
        pos.push_back(at);
        cells.insert(self, at);
    }
};

// The expected size of this vertex's residual on an axis, from residuals
// already coded nearby: the parent's and the previous vertex's.
int magnitudeContext(const CodingState& s, uint32_t self, uint32_t parent, int axis) {
    const uint32_t previous = s.magnitude[3 * size_t(self - 1) + size_t(axis)];
    const uint32_t ofParent = s.magnitude[3 * size_t(parent) + size_t(axis)];
    return std::min(bitLength(uint32_t((uint64_t(previous) + ofParent + 1) / 2)), kMagnitudeContexts - 1);
}

Predictions predict(const CodingState& s, uint32_t self, uint32_t parent) {
    Predictions p;
    const Point at = s.pos[parent];
    p.add(at);
    const uint32_t previous = self - 1;  // repeat the previous tree edge (regular samplings)
    p.add(s.parentOf[previous] != kNone ? at + (s.pos[previous] - s.pos[s.parentOf[previous]]) : at);
    Point near[kNearest];
    const int m = s.cells.nearest(s.pos, parent, at, near);
    for (int i = 0; i < m; ++i) p.add(at + (at - near[i]));
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            if (i != j) p.add(at + (near[i] - near[j]));
    return p;
}

// Codes (or decodes) vertex `self`, a child of `parent`; `actual` is its
// position when encoding. Returns the position.
// The encoder's pick: the candidate whose residual and choice cost least
// under the current models. (Floating point is fine here: the choice is
// transmitted, the decoder never repeats this.)
uint32_t bestPrediction(const CodingState& s, const Predictions& p, const AdaptiveFrequencies& choiceModel,
                        const int* contexts, Point actual) {
    uint32_t best = 0;
    double bestCost = 1e300;
    const double total = choiceModel.totalCount();
    for (uint32_t c = 0; c < uint32_t(p.count); ++c) {
        const Point r = actual - p.candidate[c];
        const double cost = residualBits(s.axis[0], contexts[0], r.x) + residualBits(s.axis[1], contexts[1], r.y) +
                            residualBits(s.axis[2], contexts[2], r.z) + std::log2(total / choiceModel.countOf(c));
        if (cost < bestCost) {
            bestCost = cost;
            best = c;
        }
    }
    return best;
}

template <class Io>
Point codeChild(Io& io, CodingState& s, uint32_t self, uint32_t parent, Point actual) {
    const Predictions p = predict(s, self, parent);
    AdaptiveFrequencies& choiceModel = s.predictorChoice[std::min<uint32_t>(s.previousChoice, kChoiceContexts - 1)];
    int contexts[3];
    for (int a = 0; a < 3; ++a) contexts[a] = magnitudeContext(s, self, parent, a);
    const uint32_t best = Io::kEncoding ? bestPrediction(s, p, choiceModel, contexts, actual) : 0;
    const uint32_t choice = io.symbol(choiceModel, best);
    if (choice >= uint32_t(p.count)) throw Error("corrupt file: a geometry predictor choice is out of range");
    s.previousChoice = choice;
    const Point base = p.candidate[choice];
    const Point r = actual - base;
    int32_t out[3];
    const int32_t in[3] = {r.x, r.y, r.z};
    for (int a = 0; a < 3; ++a) {
        out[a] = codeResidual(io, s.axis[a], contexts[a], in[a]);
        s.magnitude[3 * size_t(self) + size_t(a)] = magnitudeOf(out[a]);
    }
    return {int32_t(int64_t(base.x) + out[0]), int32_t(int64_t(base.y) + out[1]), int32_t(int64_t(base.z) + out[2])};
}

template <class Io>
uint32_t codeChildCount(Io& io, CodingState& s, uint32_t count) {
    const uint32_t symbol = io.symbol(s.childCount, std::min(count, kDirectChildCounts));
    if (symbol < kDirectChildCounts) return symbol;
    // Elias gamma of w >= 1: n - 1 zero bits, a one bit, then the n - 1 bits
    // below the leading one.
    const uint32_t w = Io::kEncoding ? count - kDirectChildCounts + 1 : 0;
    const int n = bitLength(w);
    int zeros = 0;
    while (io.plain(zeros < n - 1 ? 0 : 1, 1) == 0)
        if (++zeros > 31) throw Error("corrupt file: a child count in the geometry section is too long");
    const uint64_t decoded = (uint64_t(1) << zeros) | io.plain(w, zeros);
    return uint32_t(std::min<uint64_t>(decoded - 1 + kDirectChildCounts, 0xFFFFFFFFu));
}

uint64_t residualCost(Point r) {  // Exp-Golomb length, to pick the predictor
    auto one = [](int32_t v) { return uint64_t(2 * bitLength(uint32_t(v < 0 ? -int64_t(v) : v)) + 1); };
    return one(r.x) + one(r.y) + one(r.z);
}

struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t root(uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
    bool join(uint32_t a, uint32_t b) {
        a = root(a);
        b = root(b);
        if (a == b) return false;
        parent[a] = b;
        return true;
    }
};

// Minimum spanning forest of the k-nearest-neighbour graph, as child lists,
// children nearest first.
std::vector<std::vector<uint32_t>> spanningForest(const std::vector<int32_t>& grid, NeighbourIndex index,
                                                  double* spacing) {
    const size_t n = grid.size() / 3;
    std::vector<std::vector<uint32_t>> children(n);
    *spacing = 1;
    if (n < 2) return children;
    // The kNeighbours nearest of every vertex, exactly, on the integer grid
    // (either index gives the same graph).
    std::vector<uint32_t> neighbours;
    std::vector<int64_t> distance2;
    makeSpatialIndex(grid, index, IndexRole::NeighbourGraph)->nearestOfEach(kNeighbours, neighbours, distance2);
    std::vector<int64_t> fourth(n, 0);  // squared distance to the kNearest-th nearest, fixed point
    for (size_t v = 0; v < n; ++v) {
        size_t found = 0;
        while (found < size_t(kNeighbours) && neighbours[v * kNeighbours + found] != kNone) ++found;
        if (found != 0) fourth[v] = distance2[v * kNeighbours + std::min<size_t>(kNearest, found) - 1];
    }
    {
        // The typical distance to the kNearest-th nearest neighbour: it sizes the cells of the near-point search.
        std::nth_element(fourth.begin(), fourth.begin() + n / 2, fourth.end());
        *spacing = std::sqrt(double(fourth[n / 2])) / double(kSubUnits);
    }
    struct Edge {
        int64_t length2;
        uint32_t a, b;
    };
    auto length2 = [&](uint32_t a, uint32_t b) {
        int64_t s = 0;
        for (int c = 0; c < 3; ++c) {
            const int64_t d = int64_t(grid[3 * size_t(a) + c]) - grid[3 * size_t(b) + c];
            s += d * d;
        }
        return s;
    };
    std::vector<Edge> edges;
    edges.reserve(n * size_t(kNeighbours));
    for (size_t v = 0; v < n; ++v)
        for (int j = 0; j < kNeighbours; ++j) {
            const uint32_t w = neighbours[v * kNeighbours + size_t(j)];
            if (w == kNone) continue;
            // Mutual neighbours give the same edge twice: keep it once (the
            // sort below is most of the tree's cost).
            const uint32_t* theirs = neighbours.data() + size_t(w) * kNeighbours;
            if (w < v && std::find(theirs, theirs + kNeighbours, uint32_t(v)) != theirs + kNeighbours) continue;
            edges.push_back({length2(uint32_t(v), w), uint32_t(std::min<size_t>(v, w)), uint32_t(std::max<size_t>(v, w))});
        }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
        return x.length2 != y.length2 ? x.length2 < y.length2 : (x.a != y.a ? x.a < y.a : x.b < y.b);
    });
    UnionFind sets(n);
    std::vector<std::vector<std::pair<int64_t, uint32_t>>> adjacent(n);
    for (const Edge& e : edges)
        if (sets.join(e.a, e.b)) {
            adjacent[e.a].push_back({e.length2, e.b});
            adjacent[e.b].push_back({e.length2, e.a});
        }
    // Orient away from each component's first vertex (input order).
    std::vector<uint8_t> seen(n, 0);
    std::vector<uint32_t> stack;
    for (size_t root = 0; root < n; ++root) {
        if (seen[root]) continue;
        seen[root] = 1;
        stack.push_back(uint32_t(root));
        while (!stack.empty()) {
            const uint32_t v = stack.back();
            stack.pop_back();
            std::sort(adjacent[v].begin(), adjacent[v].end());
            for (const auto& next : adjacent[v])
                if (!seen[next.second]) {
                    seen[next.second] = 1;
                    children[v].push_back(next.second);
                    stack.push_back(next.second);
                }
        }
    }
    return children;
}

Point pointOf(const std::vector<int32_t>& grid, uint32_t v) {
    return {grid[3 * size_t(v)], grid[3 * size_t(v) + 1], grid[3 * size_t(v) + 2]};
}


// The encoder may visit children in any order; the first child of a vertex
// is predicted by going straight on from its parent, so it should be the
// child that lies most nearly straight on (others use sibling predictions).
void orderChildrenForPrediction(const std::vector<int32_t>& grid, std::vector<std::vector<uint32_t>>& children) {
    std::vector<uint32_t> parentOf(children.size(), kNone);
    for (size_t v = 0; v < children.size(); ++v)
        for (uint32_t c : children[v]) parentOf[c] = uint32_t(v);
    for (size_t v = 0; v < children.size(); ++v) {
        if (parentOf[v] == kNone || children[v].size() < 2) continue;
        const Point at = pointOf(grid, uint32_t(v));
        const Point straight = at + (at - pointOf(grid, parentOf[v]));
        std::stable_sort(children[v].begin(), children[v].end(), [&](uint32_t a, uint32_t b) {
            return residualCost(pointOf(grid, a) - straight) < residualCost(pointOf(grid, b) - straight);
        });
    }
}

// The depth-first preorder of the forest (roots in input order, children
// nearest first), as input vertices.
std::vector<uint32_t> preorder(const std::vector<std::vector<uint32_t>>& children) {
    const size_t n = children.size();
    std::vector<uint8_t> isChild(n, 0);
    for (const auto& list : children)
        for (uint32_t c : list) isChild[c] = 1;
    std::vector<uint32_t> order, stack;
    order.reserve(n);
    for (size_t root = 0; root < n; ++root) {
        if (isChild[root]) continue;
        stack.push_back(uint32_t(root));
        while (!stack.empty()) {
            const uint32_t v = stack.back();
            stack.pop_back();
            order.push_back(v);
            for (size_t c = children[v].size(); c-- > 0;) stack.push_back(children[v][c]);
        }
    }
    return order;
}

}  // namespace

// The side of the cells the coders search for near points: about three
// times the typical distance to the kNearest-th neighbour, as a power of two
// (the search covers at least half a cell around the parent).
int cellBitsFor(double spacing, int bits) { return std::min(bits, bitLength(uint32_t(std::min(3 * spacing, 1e9)))); }
constexpr int kCellBitsWidth = 5;

GeometryEncoding encodeGeometryTree(const std::vector<int32_t>& grid, int bits, NeighbourIndex index) {
    double spacing = 1;
    std::vector<std::vector<uint32_t>> children = spanningForest(grid, index, &spacing);
    orderChildrenForPrediction(grid, children);
    GeometryEncoding result;
    result.order = preorder(children);
    const size_t n = result.order.size();

    RangeEncoder coder;
    Writer io{coder};
    const int cellBits = cellBitsFor(spacing, bits);
    coder.encodeBits(uint32_t(cellBits), kCellBitsWidth);
    CodingState s(cellBits);
    s.pos.reserve(n);
    s.parentOf.reserve(n);
    s.magnitude.reserve(3 * n);
    TreeWalk walk;
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t vertex = result.order[self];
        const Point at = pointOf(grid, vertex);
        const uint32_t parent = walk.enter();
        s.begin(parent);
        if (parent == kNone) {
            for (int32_t c : {at.x, at.y, at.z}) coder.encodeWideBits(uint32_t(c), bits);
        } else {
            codeChild(io, s, self, parent, at);
        }
        s.place(self, at);
        codeChildCount(io, s, uint32_t(children[vertex].size()));
        walk.expect(self, uint32_t(children[vertex].size()));
    }
    result.bytes = coder.finish();
    return result;
}

std::vector<int32_t> decodeGeometryTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    // Every vertex but a root codes at least five adaptive decisions (a
    // predictor choice, three residual zero flags, a child count). No
    // binary model gives a decision a probability above 4095/4096, and a
    // table of k symbols none above 1 - (k-1)/65568, so a vertex costs at
    // least ~0.0017 bits: at most ~4700 vertices per byte. A count far
    // beyond that is refused before anything is allocated.
    constexpr uint64_t kMaxVerticesPerByte = 8192;
    if (vertexCount > (uint64_t(size) + 8) * kMaxVerticesPerByte)
        throw Error("corrupt file: " + std::to_string(vertexCount) + " vertices cannot fit in a geometry section of " +
                    std::to_string(size) + " bytes");
    const size_t n = size_t(vertexCount);
    const int32_t top = gridMax(bits);
    RangeDecoder coder(data, size);
    Reader io{coder};
    const int cellBits = int(coder.decodeBits(kCellBitsWidth));
    if (cellBits > bits) throw Error("corrupt file: the geometry section's cell size is larger than the grid");
    // The count is only a claim until the stream delivers the vertices:
    // tables grow as they are decoded, so a short or garbage section fails
    // before memory is committed to it.
    CodingState s(cellBits);
    const size_t initial = std::min<size_t>(n, size_t(1) << 16);
    s.pos.reserve(initial);
    s.parentOf.reserve(initial);
    s.magnitude.reserve(3 * initial);
    TreeWalk walk;
    uint64_t promised = 0;  // children announced but not yet decoded
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t parent = walk.enter();
        s.begin(parent);
        Point at;
        if (parent == kNone) {
            if (promised != 0) throw Error("corrupt file: the geometry tree is inconsistent");
            const int32_t x = int32_t(coder.decodeWideBits(bits));  // in order: x, y, z
            const int32_t y = int32_t(coder.decodeWideBits(bits));
            const int32_t z = int32_t(coder.decodeWideBits(bits));
            at = {x, y, z};
        } else {
            --promised;
            at = codeChild(io, s, self, parent, Point{});
            if (at.x < 0 || at.y < 0 || at.z < 0 || at.x > top || at.y > top || at.z > top)
                throw Error("corrupt file: geometry vertex " + std::to_string(self) + " falls outside the grid");
        }
        s.place(self, at);
        const uint32_t childCount = codeChildCount(io, s, 0);
        promised += childCount;
        if (promised > n - 1 - self)
            throw Error("corrupt file: geometry vertex " + std::to_string(self) + " announces more children than remain");
        walk.expect(self, childCount);
        if (coder.bytesPastEnd() > 0) throw Error("corrupt file: the geometry section ends early");
    }
    if (promised != 0) throw Error("corrupt file: the geometry section ends inside the tree");
    std::vector<int32_t> grid(3 * n);
    for (size_t v = 0; v < n; ++v) {
        grid[3 * v] = s.pos[v].x;
        grid[3 * v + 1] = s.pos[v].y;
        grid[3 * v + 2] = s.pos[v].z;
    }
    return grid;
}

}  // namespace drm
