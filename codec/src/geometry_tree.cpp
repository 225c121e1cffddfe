#include "geometry_tree.h"

#include <algorithm>
#include <numeric>
#include <string>

#include <flann/flann.hpp>

#include "drm/drm.h"
#include "quantize.h"
#include "range_coder.h"
#include "rank_coder.h"

namespace drm {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
constexpr int kNeighbours = 8;       // spanning tree over the 8-nearest-neighbour graph
constexpr int kPredictors = 4;
constexpr int kResidualClasses = 24; // bit lengths 0..23 (differences of 21-bit coordinates)
constexpr int kClassContexts = 12;
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
// before each vertex it tells that vertex's parent and previous sibling (as
// decoded indices), so encoder and decoder predict from the same vertices.
class TreeWalk {
public:
    void enter(uint32_t self, uint32_t* parent, uint32_t* sibling) {
        while (!frames_.empty() && frames_.back().childrenLeft == 0) frames_.pop_back();
        if (frames_.empty()) {
            *parent = *sibling = kNone;
            return;
        }
        Frame& f = frames_.back();
        *parent = f.vertex;
        *sibling = f.lastChild;
        --f.childrenLeft;
        f.lastChild = self;
    }
    void expect(uint32_t self, uint32_t childCount) {
        if (childCount > 0) frames_.push_back({self, childCount, kNone});
    }

private:
    struct Frame {
        uint32_t vertex, childrenLeft, lastChild;
    };
    std::vector<Frame> frames_;
};

// The decoder-rebuildable predictions for vertex `next` (decoded index),
// child of `parent`, after `sibling` (kNone if first).
struct Predictions {
    Point candidate[kPredictors];
};

Predictions predict(const std::vector<Point>& pos, const std::vector<uint32_t>& parentOf, uint32_t next,
                    uint32_t parent, uint32_t sibling) {
    Predictions p;
    const Point at = pos[parent];
    for (Point& c : p.candidate) c = at;
    const uint32_t grandparent = parentOf[parent];
    if (grandparent != kNone) p.candidate[1] = at + (at - pos[grandparent]);  // keep going straight
    if (sibling != kNone) p.candidate[2] = at + (at - pos[sibling]);          // opposite the previous sibling
    const uint32_t previous = next - 1;  // repeat the previous tree edge (regular samplings)
    if (parentOf[previous] != kNone) p.candidate[3] = at + (pos[previous] - pos[parentOf[previous]]);
    return p;
}

// The models shared by both sides.
struct GeometryModels {
    std::vector<AdaptiveFrequencies> residualClass;  // [axis][class context]
    std::vector<AdaptiveFrequencies> topBit;         // [axis][bit length]: the bit below the leading one
    std::vector<AdaptiveFrequencies> predictorChoice;  // [previous choice]
    AdaptiveFrequencies childCount;
    int previousClass[3] = {0, 0, 0};
    uint32_t previousChoice = 0;

    GeometryModels()
        : residualClass(3 * kClassContexts, AdaptiveFrequencies(std::vector<uint16_t>(kResidualClasses, 1))),
          topBit(3 * kResidualClasses, AdaptiveFrequencies(std::vector<uint16_t>(2, 1))),
          predictorChoice(kPredictors, AdaptiveFrequencies(std::vector<uint16_t>(kPredictors, 1))),
          childCount(std::vector<uint16_t>(kDirectChildCounts + 1, 1)) {}

    AdaptiveFrequencies& choiceModel() { return predictorChoice[previousChoice]; }

    AdaptiveFrequencies& classModel(int axis) {
        return residualClass[size_t(axis * kClassContexts + std::min(previousClass[axis], kClassContexts - 1))];
    }
};

// Exp-Golomb-like: the bit length of |r| as an adaptive symbol, then the sign
// and the bits below the leading one as plain bits.
void encodeResidual(RangeEncoder& coder, GeometryModels& models, int axis, int32_t r) {
    const uint32_t magnitude = uint32_t(r < 0 ? -int64_t(r) : r);
    const int n = bitLength(magnitude);
    models.classModel(axis).encode(coder, uint32_t(n));
    models.previousClass[axis] = n;
    if (n == 0) return;
    coder.encodeBits(r < 0 ? 1 : 0, 1);
    if (n == 1) return;
    // Residuals are peaked: within a bit length the smaller half is likelier.
    models.topBit[size_t(axis * kResidualClasses + n)].encode(coder, (magnitude >> (n - 2)) & 1);
    coder.encodeWideBits(magnitude, n - 2);
}

int32_t decodeResidual(RangeDecoder& coder, GeometryModels& models, int axis) {
    const int n = int(models.classModel(axis).decode(coder));
    models.previousClass[axis] = n;
    if (n == 0) return 0;
    const bool negative = coder.decodeBits(1) != 0;
    uint32_t magnitude = 1;
    if (n > 1) {
        const uint32_t top = models.topBit[size_t(axis * kResidualClasses + n)].decode(coder);
        magnitude = (((uint32_t(1) << 1) | top) << (n - 2)) | uint32_t(coder.decodeWideBits(n - 2));
    }
    return negative ? -int32_t(magnitude) : int32_t(magnitude);
}

void encodeChildCount(RangeEncoder& coder, GeometryModels& models, uint32_t count) {
    if (count < kDirectChildCounts) {
        models.childCount.encode(coder, count);
        return;
    }
    models.childCount.encode(coder, kDirectChildCounts);
    // Elias gamma of w >= 1: n - 1 zero bits, a one bit, then the n - 1 bits
    // below the leading one. Each piece is coded exactly as the decoder reads
    // it (one bit at a time, then one chunk): in a range coder a 4-bit value
    // and four single bits are different codes.
    const uint32_t w = count - kDirectChildCounts + 1;
    const int n = bitLength(w);
    for (int zero = 0; zero < n - 1; ++zero) coder.encodeBits(0, 1);
    coder.encodeBits(1, 1);
    coder.encodeWideBits(w, n - 1);
}

uint32_t decodeChildCount(RangeDecoder& coder, GeometryModels& models) {
    const uint32_t symbol = models.childCount.decode(coder);
    if (symbol < kDirectChildCounts) return symbol;
    int zeros = 0;
    while (coder.decodeBits(1) == 0)
        if (++zeros > 31) throw Error("corrupt file: a child count in the geometry section is too long");
    const uint64_t w = (uint64_t(1) << zeros) | coder.decodeWideBits(zeros);
    return uint32_t(std::min<uint64_t>(w - 1 + kDirectChildCounts, 0xFFFFFFFFu));
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
std::vector<std::vector<uint32_t>> spanningForest(const std::vector<int32_t>& grid) {
    const size_t n = grid.size() / 3;
    std::vector<std::vector<uint32_t>> children(n);
    if (n < 2) return children;
    const int k = int(std::min<size_t>(kNeighbours + 1, n));  // the query point finds itself too
    std::vector<float> points(grid.begin(), grid.end());
    flann::Matrix<float> data(points.data(), n, 3);
    flann::KDTreeSingleIndex<flann::L2_Simple<float>> tree(data, flann::KDTreeSingleIndexParams(8));
    tree.buildIndex();
    std::vector<size_t> indices(n * size_t(k));
    std::vector<float> distances(n * size_t(k));
    flann::Matrix<size_t> indexMatrix(indices.data(), n, size_t(k));
    flann::Matrix<float> distanceMatrix(distances.data(), n, size_t(k));
    tree.knnSearch(data, indexMatrix, distanceMatrix, size_t(k), flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED));

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
    edges.reserve(n * size_t(k));
    for (size_t v = 0; v < n; ++v)
        for (int j = 0; j < k; ++j) {
            const uint32_t w = uint32_t(indices[v * size_t(k) + size_t(j)]);
            if (w < n && w != v) edges.push_back({length2(uint32_t(v), w), uint32_t(std::min<size_t>(v, w)), uint32_t(std::max<size_t>(v, w))});
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

GeometryEncoding encodeGeometryTree(const std::vector<int32_t>& grid, int bits) {
    std::vector<std::vector<uint32_t>> children = spanningForest(grid);
    orderChildrenForPrediction(grid, children);
    GeometryEncoding result;
    result.order = preorder(children);
    const size_t n = result.order.size();

    std::vector<Point> pos(n);
    std::vector<uint32_t> parentOf(n, kNone);
    RangeEncoder coder;
    GeometryModels models;
    TreeWalk walk;
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t vertex = result.order[self];
        const Point at = pointOf(grid, vertex);
        uint32_t parent = kNone, sibling = kNone;
        walk.enter(self, &parent, &sibling);
        parentOf[self] = parent;
        if (parent == kNone) {
            for (int32_t c : {at.x, at.y, at.z}) coder.encodeWideBits(uint32_t(c), bits);
        } else {
            const Predictions p = predict(pos, parentOf, self, parent, sibling);
            int best = 0;
            uint64_t bestCost = residualCost(at - p.candidate[0]);
            for (int c = 1; c < kPredictors; ++c) {
                const uint64_t cost = residualCost(at - p.candidate[c]);
                if (cost < bestCost) {
                    bestCost = cost;
                    best = c;
                }
            }
            models.choiceModel().encode(coder, uint32_t(best));
            models.previousChoice = uint32_t(best);
            const Point r = at - p.candidate[best];
            encodeResidual(coder, models, 0, r.x);
            encodeResidual(coder, models, 1, r.y);
            encodeResidual(coder, models, 2, r.z);
        }
        pos[self] = at;
        encodeChildCount(coder, models, uint32_t(children[vertex].size()));
        walk.expect(self, uint32_t(children[vertex].size()));
    }
    result.bytes = coder.finish();
    return result;
}

std::vector<int32_t> decodeGeometryTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits) {
    // Every vertex but a root codes five adaptive symbols (a predictor choice,
    // three residual lengths, a child count). A table of k symbols never gives
    // one a probability above 1 - (k-1)/65568, so these cost at least 0.00176
    // bits per vertex together: at most ~4550 vertices per byte. A count far
    // beyond that is refused before anything is allocated. (Coincident
    // vertices really do code this densely: fandisk at 1 bit is 118 per byte.)
    constexpr uint64_t kMaxVerticesPerByte = 8192;
    if (vertexCount > (uint64_t(size) + 8) * kMaxVerticesPerByte)
        throw Error("corrupt file: " + std::to_string(vertexCount) + " vertices cannot fit in a geometry section of " +
                    std::to_string(size) + " bytes");
    const size_t n = size_t(vertexCount);
    const int32_t top = gridMax(bits);
    // The count is only a claim until the stream delivers the vertices:
    // tables grow as they are decoded, so a short or garbage section fails
    // before memory is committed to it.
    std::vector<Point> pos;
    std::vector<uint32_t> parentOf;
    pos.reserve(std::min<size_t>(n, size_t(1) << 16));
    parentOf.reserve(pos.capacity());
    RangeDecoder coder(data, size);
    GeometryModels models;
    TreeWalk walk;
    uint64_t promised = 0;  // children announced but not yet decoded
    for (uint32_t self = 0; self < n; ++self) {
        uint32_t parent = kNone, sibling = kNone;
        walk.enter(self, &parent, &sibling);
        parentOf.push_back(parent);
        Point at;
        if (parent == kNone) {
            if (promised != 0) throw Error("corrupt file: the geometry tree is inconsistent");
            const int32_t x = int32_t(coder.decodeWideBits(bits));  // in order: x, y, z
            const int32_t y = int32_t(coder.decodeWideBits(bits));
            const int32_t z = int32_t(coder.decodeWideBits(bits));
            at = {x, y, z};
        } else {
            --promised;
            const uint32_t choice = models.choiceModel().decode(coder);
            models.previousChoice = choice;
            const Predictions p = predict(pos, parentOf, self, parent, sibling);
            const Point base = p.candidate[choice];
            const int32_t rx = decodeResidual(coder, models, 0);
            const int32_t ry = decodeResidual(coder, models, 1);
            const int32_t rz = decodeResidual(coder, models, 2);
            const int64_t x = int64_t(base.x) + rx, y = int64_t(base.y) + ry, z = int64_t(base.z) + rz;
            if (x < 0 || y < 0 || z < 0 || x > top || y > top || z > top)
                throw Error("corrupt file: geometry vertex " + std::to_string(self) + " falls outside the grid");
            at = {int32_t(x), int32_t(y), int32_t(z)};
        }
        pos.push_back(at);
        const uint32_t childCount = decodeChildCount(coder, models);
        promised += childCount;
        if (promised > n - 1 - self)
            throw Error("corrupt file: geometry vertex " + std::to_string(self) + " announces more children than remain");
        walk.expect(self, childCount);
        if (coder.bytesPastEnd() > 0) throw Error("corrupt file: the geometry section ends early");
    }
    if (promised != 0) throw Error("corrupt file: the geometry section ends inside the tree");
    std::vector<int32_t> grid(3 * n);
    for (size_t v = 0; v < n; ++v) {
        grid[3 * v] = pos[v].x;
        grid[3 * v + 1] = pos[v].y;
        grid[3 * v + 2] = pos[v].z;
    }
    return grid;
}

}  // namespace drm
