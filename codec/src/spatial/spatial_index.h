// The neighbour searches of the codec, behind one interface with two
// implementations: the grid of cells (VertexIndex, grid_index.cpp) and
// FLANN's kd-tree (flann_index.cpp), the index the design names.
//
// An index only nominates candidates. What is nearest, and in which order,
// is always decided by the same exact arithmetic: squared fixed-point
// distances in 64-bit integers, ties broken by vertex index. The grid works
// in those integers directly; FLANN's float distances are turned into a
// certified bound (flann_index.cpp) and it is asked for more candidates
// until the exact answer is provably among them. Both therefore give the
// same files and decoded meshes, byte for byte; only speed differs, and
// drm::NeighbourIndex chooses between them per role.
//
// An index refers to the grid it was built on, which must outlive it. Its
// searches keep scratch buffers (and the grid's makes its cells when first
// asked): one index serves one thread.
#ifndef DRM_SPATIAL_INDEX_H
#define DRM_SPATIAL_INDEX_H

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "common.h"
#include "drmcodec/drmcodec.h"
#include "exact_math.h"

namespace drm {

// (squared fixed-point distance, vertex), ordered as ranks are.
using RankedVertex = std::pair<int64_t, uint32_t>;

// Squared distance from p to grid vertex v, in fixed-point units (1/16 of a
// grid step): the one distance every search is decided by.
inline int64_t fixedDistance2(const std::vector<int32_t>& grid, const FixedPoint& p, uint32_t v) {
    return fixedDistance2(grid.data() + 3 * size_t(v), p);
}

inline FixedPoint fixedPointOf(const std::vector<int32_t>& grid, uint32_t v) {
    return {int64_t(grid[3 * size_t(v)]) * kSubUnits, int64_t(grid[3 * size_t(v) + 1]) * kSubUnits,
            int64_t(grid[3 * size_t(v) + 2]) * kSubUnits};
}

// A reference to any callable with the signature R(Args...), which must
// outlive the call (a lambda passed as an argument does): the index's
// searches take their callbacks this way, being virtual.
template <class Signature>
class CallbackRef;
template <class R, class... Args>
class CallbackRef<R(Args...)> {
public:
    template <class F>
    CallbackRef(const F& f)  // NOLINT: implicit, so that lambdas pass as they are
        : object_(&f), call_([](const void* object, Args... args) -> R {
              return (*static_cast<const F*>(object))(args...);
          }) {}
    R operator()(Args... args) const { return call_(object_, args...); }

private:
    const void* object_;
    R (*call_)(const void*, Args...);
};

// Which vertices a nearest search may return; asked only of vertices that
// could enter the answer.
using VertexFilter = CallbackRef<bool(uint32_t)>;
// A run of `count` present vertices: their indices, their grid
// coordinates (x, y, z of ids[i] at points[3 i]), and a box that holds
// them all (grid units: lowest x, y, z at box[0..2], highest at box[3..5];
// it may be larger than their own), so that a caller can pass over a run
// that cannot hold what it looks for.
using PointRunVisitor =
    CallbackRef<void(const uint32_t* ids, const int32_t* points, size_t count, const int32_t* box)>;
// For a caller after the best vertex by some key: a lower bound of the key
// of any vertex in a box (grid units, as a run's) that it could take, or
// +infinity when it could take none; and the key beyond which it takes
// nothing (it may fall as the caller goes).
using BoxBound = CallbackRef<double(const int32_t* box)>;
using KeyLimit = CallbackRef<double()>;

class SpatialIndex {
public:
    virtual ~SpatialIndex() = default;
    virtual const char* name() const = 0;  // "grid" or "flann"

    // Takes v out of every later search (the paper's vertex culling).
    // Removing a vertex twice is a no-op.
    virtual void remove(uint32_t v) = 0;
    virtual size_t presentCount() const = 0;

    // Every present vertex whose distance from q is at most radius (grid
    // units), plus possibly some farther ones, in no particular order:
    // callers apply their own exact test. out is cleared first.
    virtual void collectNear(Vec3 q, double radius, std::vector<uint32_t>& out) const = 0;
    // The same vertices, with their grid coordinates, handed to visit in
    // runs (the grid keeps the coordinates with its cells, so the caller's
    // test reads them in order, and nothing is copied), each with a box
    // around it. The runs and boxes stay valid until the next remove() or
    // forEachNear().
    virtual void forEachNear(Vec3 q, double radius, PointRunVisitor visit) const = 0;
    // The same vertices for a caller after the best vertex by some key
    // that it can bound below over a box (the size correction's first
    // vertex ahead, the nearest candidates in its ball): a run, or a group
    // of runs, whose lowest(box) lies above limit() when it comes to be
    // handed over or opened is passed over whole; lower bounds go first
    // where the index can order them. A caller that takes the best of the
    // vertices it is handed gets the answer it would get from forEachNear.
    // A box handed to lowest may be a group's, valid during the call only.
    // By default forEachNear's runs, each tested in turn (FLANN's index:
    // its wideBallRadius is infinite, so the codec never asks it).
    virtual void forEachNearInOrder(Vec3 q, double radius, BoxBound lowest, KeyLimit limit,
                                    PointRunVisitor visit) const;
    // The radius beyond which forEachNearInOrder is the faster way to
    // search a ball (the grid's: balls many cells across, which it searches
    // through a hierarchy of boxes; by default none).
    virtual double wideBallRadius() const { return std::numeric_limits<double>::infinity(); }

    // The `count` present vertices nearest p that accept takes, exactly:
    // (fixedDistance2, vertex) in increasing order (ties by index); fewer
    // if fewer exist. out is cleared first.
    virtual void nearest(const FixedPoint& p, size_t count, VertexFilter accept,
                         std::vector<RankedVertex>& out) const = 0;
    // The last of nearest()'s answer for `count`, in out: what a decoder
    // asks for a far rank, which needs no list. Returns how many vertices
    // that answer holds (count, or fewer if fewer exist: out is then
    // untouched). The grid finds it without ordering the nearer ones; by
    // default it is taken from nearest().
    virtual size_t nthNearest(const FixedPoint& p, size_t count, VertexFilter accept, RankedVertex& out) const;

    // For every vertex v of the grid, the `count` present vertices other
    // than v nearest it, exactly as nearest() would give them:
    // neighbours[v * count + j] (kNoVertex past the last) and, unless
    // distance2 is null, their fixedDistance2 from v in
    // (*distance2)[v * count + j] (8 bytes a neighbour: the geometry
    // tree's graph asks for none). Uses up to `threads` threads (the
    // answers are the same).
    virtual void nearestOfEach(size_t count, std::vector<uint32_t>& neighbours,
                               std::vector<int64_t>* distance2, int threads = 1) const = 0;
};

// What an index serves: the traversal's searches (rank search, size
// correction, curvature), which remove culled vertices as they go, or the
// geometry tree's k-nearest-neighbour graph, built once over all vertices.
enum class IndexRole { Traversal, NeighbourGraph };

// The index `choice` names, or for NeighbourIndex::Auto the faster one for
// this role (measured: docs/tuning.md, kTraversalDefault).
NeighbourIndex resolveIndex(NeighbourIndex choice, IndexRole role);

// cellShift: cells 2^cellShift grid units wide; by default sized to the
// data (tests force others: no answer may depend on it).
std::unique_ptr<SpatialIndex> makeGridIndex(const std::vector<int32_t>& grid, int cellShift = -1);
std::unique_ptr<SpatialIndex> makeFlannIndex(const std::vector<int32_t>& grid);
std::unique_ptr<SpatialIndex> makeSpatialIndex(const std::vector<int32_t>& grid, NeighbourIndex choice,
                                               IndexRole role);

}  // namespace drm

#endif  // DRM_SPATIAL_INDEX_H
