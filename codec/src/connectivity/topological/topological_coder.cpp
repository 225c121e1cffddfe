#include "connectivity/topological/topological_coder.h"

#include <algorithm>
#include <string>

#include "connectivity/admissibility.h"
#include "entropy/bit_model.h"
#include "common.h"
#include "drmcodec/drmcodec.h"
#include "connectivity/topological/front_ranks.h"
#include "connectivity/topological/originals_by_point.h"
#include "connectivity/ranked/gap_closing.h"
#include "geometry/tree/local_frame.h"
#include "mesh/mesh_check.h"
#include "progress.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"
#include "geometry/tree/residual_model.h"
#include "connectivity/traversal.h"

namespace drm {
namespace {

// What lies across an open edge.
enum Symbol : uint32_t {
    kBoundaryEdge = 0,
    kNewVertex = 1,  // the next vertex: its position follows in the geometry stream
    kEndAtI = 2,     // the far end of the fan around the edge's first vertex
    kEndAtJ = 3,     // ... around its second vertex
    kOtherVertex = 4,  // a vertex already met, by distance rank
    kSymbolCount = 5,
};

// An edge's two sides each get a class from the fan end there: none, or the
// angle the edge makes with it, under 60 degrees, under 90, wider; or both
// ends are one vertex (a triangular hole). A narrow angle makes closing the
// fan likely.
constexpr int kSideClasses = 5;
constexpr int kSameEnd = 4;
constexpr int kFanClasses = 5;
constexpr int kSymbolContexts = kSymbolCount * kSideClasses * kSideClasses * kFanClasses;
// A young context starts from the proportions its previous-symbol parent
// has seen, scaled to this mass (as the rank coder's tables do).
constexpr uint32_t kSeedMass = 256;

struct Models {
    std::vector<AdaptiveFrequencies> parents, tables;
    std::vector<uint8_t> seeded;
    AxisModels newVertex[3], start[3], isolated[3];
    AxisModels otherRank;
    BitModel noSign;  // ranks are never negative: this model learns that at once
    BitModel isCopy;  // a vertex met at an earlier original's grid point copies one
    // Per triangle class, each predictor's recent errors (L1, decaying).
    int64_t predictorScore[3][3] = {};

    Models()
        : parents(kSymbolCount, AdaptiveFrequencies(std::vector<uint16_t>(kSymbolCount, 16))),
          tables(kSymbolContexts, AdaptiveFrequencies(std::vector<uint16_t>(kSymbolCount, 16))),
          seeded(kSymbolContexts, 0) {}

    AdaptiveFrequencies& table(uint32_t previous, int context) {
        const size_t at = size_t(previous) * kSideClasses * kSideClasses * kFanClasses + size_t(context);
        if (!seeded[at]) {
            tables[at].seedFrom(parents[previous], kSeedMass);
            seeded[at] = 1;
        }
        return tables[at];
    }
};

int64_t component(const std::vector<int32_t>& grid, uint32_t v, int axis) { return grid[3 * size_t(v) + size_t(axis)]; }

// How many rebuilt triangles lie around `center` from the triangle
// (center, toward, o), walking away from the edge (center, toward).
int fanSize(const Traversal& t, uint32_t center, uint32_t o, bool clockwise, int limit) {
    int count = 1;
    uint32_t far = o;
    while (count < limit) {
        const uint32_t next = clockwise ? t.thirdVertex(far, center) : t.thirdVertex(center, far);
        if (next == Traversal::kNoTriangle || next == Traversal::kBoundary) break;
        far = next;
        ++count;
    }
    return count;
}

// Whether d / sqrt(uu ww) > 1/2, for a dot product d > 0 of two vectors of
// squared lengths uu and ww, exactly: 4 d^2 > uu ww. With uu and ww below
// 2^30 (edges shorter than 2^15 grid steps) uu ww < 2^60
// and d^2 <= uu ww, so 64 bits hold both sides; otherwise 128 bits do
// (a WebAssembly build multiplies those through a call).
bool cosineAboveHalf(int64_t d, int64_t uu, int64_t ww) {
    constexpr int64_t k64BitsBelow = int64_t(1) << 30;
    if (uu < k64BitsBelow && ww < k64BitsBelow) return 4 * d * d > uu * ww;
    return 4 * __int128(d) * d > __int128(uu) * ww;
}

// The class of the side at `at` of edge (at, toward), whose fan ends at `end`.
int sideClass(const std::vector<int32_t>& grid, uint32_t at, uint32_t toward, uint32_t end) {
    if (end == kNoVertex) return 0;
    int64_t u[3], w[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = component(grid, toward, k) - component(grid, at, k);
        w[k] = component(grid, end, k) - component(grid, at, k);
    }
    const int64_t d = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];  // differences below 2^21: below 2^44
    const int64_t uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if (d > 0 && cosineAboveHalf(d, uu, ww)) return 1;
    return d > 0 ? 2 : 3;
}

// The decoder's side of what the walk shares: the positions met so far, the
// traversal, the vertices of the front (met and not culled), the models.
struct WalkState {
    // A decoder's counts are the header's claims: its tables start at
    // kFirstVertices at most and grow with the vertices met (room), and
    // room for about two faces a vertex at first (the traversal grows).
    static constexpr size_t kFirstVertices = size_t(1) << 22;
    WalkState(size_t vertexCount, size_t faceCount, int bits)
        : bits(bits), vertexCount(vertexCount), faceCount(faceCount),
          traversal(std::min(vertexCount, kFirstVertices), std::min<size_t>(faceCount, 2 * std::min(vertexCount, kFirstVertices) + 16),
                    nullptr),
          admissible(traversal, true) {
        traversal.setDepthFirst();
        traversal.trackFanPieces();  // fanEnds at every edge
        room(std::min(vertexCount, kFirstVertices));
    }
    // Tables for walk ids below n.
    void room(size_t n) {
        if (n <= slotOf.size()) return;
        const size_t size = std::min(vertexCount, std::max(n, 2 * slotOf.size()));
        grid.resize(3 * size, 0);
        slotOf.resize(size, kNoVertex);
        if (copies) originalOf.resize(size, kNoVertex);
        traversal.growVertices(size);
    }

    int bits;
    size_t vertexCount, faceCount;
    std::vector<int32_t> grid;
    Traversal traversal;
    Admissibility admissible;
    uint32_t met = 0;  // vertices met: walk ids 0 .. met - 1
    uint64_t components = 0, boundaryEdges = 0;
    // With copies (a cut mesh): the originals met at each grid point, and
    // per walk id the original it copies (kNoVertex: it is one).
    bool copies = false;
    OriginalsByPoint originalsAt;
    std::vector<uint32_t> originalOf;
    uint32_t copiesMet = 0;
    std::vector<uint32_t> front, slotOf;
    OtherSearchBound search;
    WalkProgress progress;
    Models models;

    // The front's positions beside it, an array per axis (frontAt[axis],
    // by slot), so that the pass over it reads them in order, several at
    // once (front_ranks.h).
    std::vector<double> frontAt[3];
    void enter(uint32_t v) {
        room(size_t(v) + 1);
        slotOf[v] = uint32_t(front.size());
        front.push_back(v);
        for (int k = 0; k < 3; ++k) frontAt[k].push_back(double(component(grid, v, k)));
    }
    void leaveIfCulled(uint32_t v) {
        if (slotOf[v] == kNoVertex || !traversal.isCulled(v)) return;
        const size_t slot = slotOf[v], lastSlot = front.size() - 1;
        const uint32_t last = front[lastSlot];
        front[slot] = last;
        for (std::vector<double>& axis : frontAt) {
            axis[slot] = axis[lastSlot];
            axis.pop_back();
        }
        slotOf[last] = uint32_t(slot);
        front.pop_back();
        slotOf[v] = kNoVertex;
    }
};

// Codes position v (given by `actual` when encoding) as a residual from
// `predicted`, one axis after the other; the first axis in `firstContext`,
// the others in the bit length of the residuals before them.
template <class Io>
void codePosition(Io& io, AxisModels* models, int firstContext, const int64_t predicted[3], const int32_t* actual,
                  WalkState& st, uint32_t v) {
    int context = firstContext;
    const int64_t top = (int64_t(1) << st.bits) - 1;
    for (int k = 0; k < 3; ++k) {
        const int64_t p = std::min(std::max<int64_t>(predicted[k], 0), top);
        const int32_t r = codeResidual(io, models[k], context, [&](int) -> BitModel& { return models[k].sign[0]; },
                                       Io::kEncoding ? int32_t(actual[k] - p) : 0);
        const int64_t value = p + r;
        if (!Io::kEncoding && (value < 0 || value > top))
            throw Error(ErrorKind::Corrupt, "corrupt file: vertex " + std::to_string(v) + " lies outside the grid");
        st.grid[3 * size_t(v) + size_t(k)] = int32_t(value);
        context = std::min(std::max(context, lengthOf(r)), kMagnitudeContexts - 1);
    }
}

// The same in a frame of the gate triangle (its normal the third axis, the
// edge the first): the residual is turned into the frame, coded, and turned
// back exactly (local_frame.h).
template <class Io>
void codePositionInFrame(Io& io, AxisModels* models, int firstContext, const int64_t predicted[3], const int32_t* actual,
                         const LocalFrame& frame, WalkState& st, uint32_t v) {
    const int64_t top = (int64_t(1) << st.bits) - 1;
    int64_t p[3], r[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        p[k] = std::min(std::max<int64_t>(predicted[k], 0), top);
        if constexpr (Io::kEncoding) r[k] = actual[k] - p[k];
    }
    if constexpr (Io::kEncoding) frame.toFrame(r);
    int context = firstContext;
    for (int k = 0; k < 3; ++k) {
        r[k] = codeResidual(io, models[k], context, [&](int) -> BitModel& { return models[k].sign[0]; }, int32_t(r[k]));
        context = std::min(std::max(context, lengthOf(int32_t(r[k]))), kMagnitudeContexts - 1);
    }
    frame.fromFrame(r);
    for (int k = 0; k < 3; ++k) {
        const int64_t value = p[k] + r[k];
        if (!Io::kEncoding && (value < 0 || value > top))
            throw Error(ErrorKind::Corrupt, "corrupt file: vertex " + std::to_string(v) + " lies outside the grid");
        st.grid[3 * size_t(v) + size_t(k)] = int32_t(value);
    }
}

// A new vertex across `edge` (given by `actual` when encoding), as
// vertex `v`. Three predictions: the parallelogram, and the rim of the fan
// around either end carried on (around a sliver's hub the parallelogram
// falls near the hub); the one of the smallest recent error in the gate
// triangle's class (which of its angles is the narrowest) is used, and the
// residual is coded in the gate triangle's frame, its first axis in a
// context of the edge's extent (residuals grow with the triangles).
template <class Io>
void codeNewVertex(Io& geometry, WalkState& st, const OpenEdge& edge, const int64_t parallelogram[3], const int32_t* actual,
                   uint32_t v) {
    int64_t candidates[3][3], e[3], f[3];
    int64_t edgeSpan = 0;
    for (int k = 0; k < 3; ++k) {
        const int64_t i = component(st.grid, edge.vi, k), j = component(st.grid, edge.vj, k), o = component(st.grid, edge.opposite, k);
        candidates[0][k] = parallelogram[k];
        candidates[1][k] = 2 * j - o;
        candidates[2][k] = 2 * i - o;
        e[k] = j - i;
        f[k] = o - i;
        edgeSpan = std::max(edgeSpan, std::abs(e[k]));
    }
    auto length2 = [&](uint32_t a, uint32_t b) {
        int64_t sum = 0;
        for (int k = 0; k < 3; ++k) {
            const int64_t d = component(st.grid, a, k) - component(st.grid, b, k);
            sum += d * d;
        }
        return sum;
    };
    const int64_t oppositeI = length2(edge.vj, edge.opposite), oppositeJ = length2(edge.vi, edge.opposite),
                  oppositeO = length2(edge.vi, edge.vj);
    const int triangleClass = oppositeI <= oppositeJ && oppositeI <= oppositeO ? 0 : oppositeJ <= oppositeO ? 1 : 2;
    int64_t* score = st.models.predictorScore[triangleClass];
    int chosen = 0;
    for (int c = 1; c < 3; ++c)
        if (score[c] < score[chosen]) chosen = c;
    LocalFrame frame(e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]);
    frame.alignFirstAxis(e[0], e[1], e[2]);
    const int firstContext = std::min(bitLength(uint64_t(edgeSpan)) / 2, kMagnitudeContexts - 1);
    codePositionInFrame(geometry, st.models.newVertex, firstContext, candidates[chosen], actual, frame, st, v);
    for (int c = 0; c < 3; ++c) {
        int64_t error = 0;
        for (int k = 0; k < 3; ++k) error += std::abs(component(st.grid, v, k) - candidates[c][k]);
        score[c] += error - (score[c] >> 4);
    }
}

// OtherSearchBound's test once `searched` front vertices have been read for
// apexes elsewhere on the front: "" within it, else what passed it. (No
// corpus mesh reads a fiftieth of the bound's 4096 a face: docs/tuning.md.)
std::string pastSearchBound(const WalkState& st, uint64_t searched) {
    const uint64_t faces = st.traversal.triangleCount();
    if (searched <= st.search.floor + st.search.perFace * faces) return std::string();
    return std::to_string(searched) + " front vertices read for apexes elsewhere on the front by face " + std::to_string(faces) +
           ", past the format's bound";
}

void reportProgress(WalkState& st) {
    if (!st.progress.reporter) return;
    st.progress.reporter->tickWith([&st] {
        return st.progress.from + st.progress.span * double(st.traversal.triangleCount()) / double(std::max<size_t>(st.faceCount, 1));
    });
}

// The front as front_ranks.h reads it.
FrontView frontOf(const WalkState& st) {
    return FrontView{st.frontAt[0].data(), st.frontAt[1].data(), st.frontAt[2].data(), st.front.data(), st.front.size()};
}

// The mesh being encoded: the true apex of each edge, and the input vertex
// behind each id. The decoder passes none.
struct Truth {
    Truth(const std::vector<int32_t>& grid, const std::vector<uint32_t>& triangles, size_t vertexCount)
        : grid(grid), triangles(triangles), idOf(vertexCount, kNoVertex), inputOf(vertexCount, kNoVertex) {}
    const std::vector<int32_t>& grid;
    const std::vector<uint32_t>& triangles;
    std::vector<uint32_t> idOf, inputOf;  // input vertex <-> walk id
    std::vector<uint32_t> faceOf;         // rebuilt face -> input face
    MeshTopology topology;
    uint64_t giveUpAbove = 0;  // TopologicalBudget's
    bool gaveUp = false;
    // The cut's copies: vertex firstCopy + k copies copyOf[k]. A vertex's
    // group is the vertex it stands for; the first of a group the walk
    // meets is coded as the original, whichever the cut made so.
    size_t firstCopy = 0;
    const std::vector<uint32_t>* copyOf = nullptr;
    std::vector<uint32_t> groupOriginal;  // group -> walk id of its original, once met
    uint32_t groupOf(uint32_t v) const { return v < firstCopy ? v : (*copyOf)[v - firstCopy]; }
};

// Encoder and decoder in one: with a Writer the symbols come from `truth`,
// with a Reader from the streams.
template <class Io>
void walk(Io& connectivity, Io& geometry, WalkState& st, Truth* truth, TopologicalStats* stats) {
    // Encoding with stats: the bits coded since the last call, in bits.
    double connectivityMark = 0, geometryMark = 0;
    auto spent = [&](Io& io, double& mark) {
        double now = 0;
        if constexpr (Io::kEncoding) now = io.coder.bitsSoFar();
        const double bits = now - mark;
        mark = now;
        return bits;
    };
    std::vector<RankKey> others;  // front_ranks.h's scratch
    uint64_t searched = 0;  // front vertices read for apexes elsewhere on it (OtherSearchBound)
    uint32_t previous = kNewVertex;
    size_t nextFace = 0;  // encoder: the first face that may start a component
    int64_t lastStart[3];
    for (int k = 0; k < 3; ++k) lastStart[k] = int64_t(1) << (st.bits - 1);
    auto meet = [&](uint32_t input, uint32_t id) {  // encoder: input vertex `input` gets `id`
        truth->idOf[input] = id;
        truth->inputOf[id] = input;
    };
    uint32_t nextInput = 0;  // encoder: no input vertex below it is left unmet
    const int32_t* none = nullptr;
    // A decoder reading invented zero bytes past its streams stops at the
    // next vertex, before it makes room for a header's claim.
    auto checkNotPastEnd = [&] {
        if constexpr (!Io::kEncoding)
            if (connectivity.coder.bytesPastEnd() > 0 || geometry.coder.bytesPastEnd() > 0)
                throw Error(ErrorKind::Corrupt, "corrupt file: a topological section ends at vertex " + std::to_string(st.met) + " of " +
                            std::to_string(st.vertexCount));
    };
    // After vertex v's position: in a mesh with copies, a vertex met at the
    // grid point of an original met before says whether it copies one (and
    // which, if several are there); the first of its group is an original.
    auto noteMet = [&](uint32_t v) {
        if (!st.copies) return;
        const uint64_t key = (uint64_t(component(st.grid, v, 0)) << 42) | (uint64_t(component(st.grid, v, 1)) << 21) |
                             uint64_t(component(st.grid, v, 2));
        const uint32_t there = st.originalsAt.group(key);
        const uint32_t thereCount = st.originalsAt.size(there);
        uint32_t original = kNoVertex;
        if (thereCount > 0) {
            int copy = 0;
            uint32_t index = 0;
            if constexpr (Io::kEncoding) {
                original = truth->groupOriginal[truth->groupOf(truth->inputOf[v])];
                copy = original != kNoVertex;
                if (copy) index = st.originalsAt.indexOf(there, original);
            }
            if (connectivity.bit(st.models.isCopy, copy)) {
                if (thereCount > 1) index = connectivity.plain(index, bitLength(uint64_t(thereCount - 1)));
                if (index >= thereCount)
                    throw Error(Io::kEncoding ? ErrorKind::Internal : ErrorKind::Corrupt,
                                "corrupt file: vertex " + std::to_string(v) + " copies an original that is not at its grid point");
                original = st.originalsAt.at(there, index);
            } else {
                original = kNoVertex;
            }
        }
        if (original == kNoVertex) {
            st.originalsAt.append(there, v);
            if constexpr (Io::kEncoding) truth->groupOriginal[truth->groupOf(truth->inputOf[v])] = v;
        } else {
            st.originalOf[v] = original;
            ++st.copiesMet;
        }
    };
    while (st.traversal.triangleCount() < st.faceCount) {
        // A new component: its first face's three vertices are the next
        // three ids (the manifold cut leaves no vertex in two components).
        if (size_t(st.met) + 3 > st.vertexCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: component " + std::to_string(st.components + 1) + " starts past the " +
                        std::to_string(st.vertexCount) + " vertices");
        checkNotPastEnd();
        st.room(size_t(st.met) + 3);
        const int32_t* at[3] = {none, none, none};
        if constexpr (Io::kEncoding) {
            while (nextFace < st.faceCount && truth->idOf[truth->triangles[3 * nextFace]] != kNoVertex) ++nextFace;
            if (nextFace == st.faceCount) throw Error(ErrorKind::Internal, "internal error: the topological walk missed faces");
            truth->faceOf.push_back(uint32_t(nextFace));
            for (int c = 0; c < 3; ++c) {
                const uint32_t input = truth->triangles[3 * nextFace + size_t(c)];
                if (truth->idOf[input] != kNoVertex)
                    throw Error(ErrorKind::Internal, "internal error: a component shares a vertex with another");
                meet(input, st.met + uint32_t(c));
                at[c] = truth->grid.data() + 3 * size_t(input);
            }
        }
        const uint32_t a = st.met, b = a + 1, c = a + 2;
        codePosition(geometry, st.models.start, 0, lastStart, at[0], st, a);
        for (int k = 0; k < 3; ++k) lastStart[k] = component(st.grid, a, k);
        codePosition(geometry, st.models.start, 1, lastStart, at[1], st, b);
        const int64_t fromB[3] = {component(st.grid, b, 0), component(st.grid, b, 1), component(st.grid, b, 2)};
        codePosition(geometry, st.models.start, 1, fromB, at[2], st, c);
        if (stats) stats->otherPositionBits += spent(geometry, geometryMark);
        st.met += 3;
        noteMet(a);
        noteMet(b);
        noteMet(c);
        ++st.components;
        st.traversal.startComponent(a, b, c);
        st.enter(a);
        st.enter(b);
        st.enter(c);

        OpenEdge edge;
        while (st.traversal.popOpenEdge(edge)) {
            const FanEnds ends = fanEnds(edge, st.traversal);
            int classI = sideClass(st.grid, edge.vi, edge.vj, ends.atI);
            int classJ = sideClass(st.grid, edge.vj, edge.vi, ends.atJ);
            if (ends.atI != kNoVertex && ends.atI == ends.atJ) classI = classJ = kSameEnd;
            int64_t predicted[3];
            for (int k = 0; k < 3; ++k)
                predicted[k] = component(st.grid, edge.vi, k) + component(st.grid, edge.vj, k) - component(st.grid, edge.opposite, k);

            uint32_t symbol = 0, apex = kNoVertex, input = kNoVertex, face = 0;
            if constexpr (Io::kEncoding) {
                input = truth->topology.apexAcross(truth->inputOf[edge.vi], truth->inputOf[edge.vj], &face);
                if (input == kNoVertex) symbol = kBoundaryEdge;
                else if (truth->idOf[input] == kNoVertex) symbol = kNewVertex;
                else {
                    apex = truth->idOf[input];
                    symbol = apex == ends.atI ? kEndAtI : apex == ends.atJ ? kEndAtJ : kOtherVertex;
                }
            }
            // The fuller of the two fans (triangles rebuilt around the end,
            // 2 or fewer .. 6 or more): the fuller, the likelier it closes.
            const int fan = std::max(fanSize(st.traversal, edge.vi, edge.opposite, false, kFanClasses + 1),
                                     fanSize(st.traversal, edge.vj, edge.opposite, true, kFanClasses + 1));
            const int fanClass = std::max(fan, 2) - 2;
            symbol = connectivity.symbol(st.models.table(previous, (classI * kSideClasses + classJ) * kFanClasses + fanClass), symbol);
            st.models.parents[previous].observe(symbol);
            previous = symbol;
            if (stats) {
                ++stats->symbols[symbol];
                stats->symbolBits += spent(connectivity, connectivityMark);
            }
            if (symbol == kBoundaryEdge) {
                st.traversal.closeAsBoundary(edge);
                ++st.boundaryEdges;
            } else {
                if (symbol == kNewVertex) {
                    if (st.met >= st.vertexCount)
                        throw Error(ErrorKind::Corrupt, "corrupt file: face " + std::to_string(st.traversal.triangleCount()) +
                                    " meets a vertex past the " + std::to_string(st.vertexCount));
                    const int32_t* actual = none;
                    if constexpr (Io::kEncoding) {
                        meet(input, st.met);
                        actual = truth->grid.data() + 3 * size_t(input);
                    }
                    checkNotPastEnd();
                    apex = st.met++;
                    st.room(size_t(apex) + 1);
                    codeNewVertex(geometry, st, edge, predicted, actual, apex);
                    if (stats) stats->newVertexBits += spent(geometry, geometryMark);
                    noteMet(apex);
                    st.enter(apex);
                } else if (symbol == kEndAtI || symbol == kEndAtJ) {
                    apex = symbol == kEndAtI ? ends.atI : ends.atJ;
                    if (apex == kNoVertex)
                        throw Error(ErrorKind::Corrupt, "corrupt file: face " + std::to_string(st.traversal.triangleCount()) +
                                    " closes a fan that has no open end");
                } else {
                    searched += st.front.size();
                    if (stats) stats->frontRead = searched;
                    const std::string past = pastSearchBound(st, searched);
                    if (!past.empty()) {
                        if constexpr (Io::kEncoding) {
                            // Auto's attempt gives up (the ranks' file is kept).
                            if (truth->giveUpAbove != 0) {
                                truth->gaveUp = true;
                                return;
                            }
                            throw Error(ErrorKind::InvalidInput, "the topological connectivity coder cannot code this mesh: " + past +
                                        "; code it with the distance ranks (--connectivity ranks or auto)");
                        }
                        throw Error(ErrorKind::Corrupt, "corrupt file: " + past);
                    }
                    auto admissible = [&](uint32_t v) { return st.admissible(v, edge); };
                    uint32_t rank = 0;
                    if constexpr (Io::kEncoding) {
                        int64_t d2 = 0;
                        for (int k = 0; k < 3; ++k) {
                            const int64_t d = component(st.grid, apex, k) - predicted[k];
                            d2 += d * d;
                        }
                        rank = rankAmongFront(frontOf(st), predicted, ends.atI, ends.atJ, RankKey(d2, apex), admissible, others);
                    }
                    rank = uint32_t(codeResidual(connectivity, st.models.otherRank, 0,
                                                 [&](int) -> BitModel& { return st.models.noSign; }, int32_t(rank)));
                    if (stats) stats->rankBits += spent(connectivity, connectivityMark);
                    // The encoder knows its apex; the decoder finds it. (A
                    // non-admissible apex is refused below either way.)
                    const uint32_t found =
                        Io::kEncoding ? apex : frontVertexOfRank(frontOf(st), predicted, ends.atI, ends.atJ, rank, admissible, others);
                    if (found == kNoVertex)
                        throw Error(ErrorKind::Corrupt, "corrupt file: face " + std::to_string(st.traversal.triangleCount()) +
                                    " names front vertex " + std::to_string(rank) + " of fewer admissible ones");
                    apex = found;
                }
                if (!st.admissible(apex, edge))
                    throw Error(Io::kEncoding ? ErrorKind::Internal : ErrorKind::Corrupt,
                                (Io::kEncoding ? "internal error: face " : "corrupt file: face ") +
                                    std::to_string(st.traversal.triangleCount()) + " would reuse an edge or a closed vertex " +
                                    std::to_string(apex));
                st.traversal.attachApex(edge, apex);
                if constexpr (Io::kEncoding) {
                    truth->faceOf.push_back(face);
                    const uint64_t done = st.traversal.triangleCount();
                    if (truth->giveUpAbove != 0 && done % 4096 == 0 && 4 * done >= st.faceCount &&
                        double(connectivity.coder.bytesAtLeast() + geometry.coder.bytesAtLeast()) * double(st.faceCount) >
                            double(truth->giveUpAbove) * double(done)) {
                        truth->gaveUp = true;
                        return;
                    }
                }
            }
            st.leaveIfCulled(edge.vi);
            st.leaveIfCulled(edge.vj);
            if (apex != kNoVertex) st.leaveIfCulled(apex);
            reportProgress(st);
            if (st.traversal.triangleCount() > st.faceCount)
                throw Error(ErrorKind::Corrupt, "corrupt file: more faces than the header's " + std::to_string(st.faceCount));
        }
    }
    // Vertices in no face, each from the one before.
    for (uint32_t v = st.met; v < st.vertexCount; ++v) {
        checkNotPastEnd();
        st.room(size_t(v) + 1);
        const int32_t* actual = none;
        if constexpr (Io::kEncoding) {
            while (truth->idOf[nextInput] != kNoVertex) ++nextInput;
            meet(nextInput, v);
            actual = truth->grid.data() + 3 * size_t(nextInput);
        }
        int64_t from[3];
        for (int k = 0; k < 3; ++k) from[k] = v > 0 ? component(st.grid, v - 1, k) : lastStart[k];
        codePosition(geometry, st.models.isolated, 0, from, actual, st, v);
        if (stats) stats->otherPositionBits += spent(geometry, geometryMark);
        st.met = v + 1;
        noteMet(v);
    }
}

// The decoded numbering of the walk's vertices: the originals in walk order,
// then the copies by the decoded index of their original, then walk id.
// Fills decodedOf (walk id -> decoded index) and copyOf (per copy, the
// decoded index of its original).
void numberDecoded(const WalkState& st, std::vector<uint32_t>& decodedOf, std::vector<uint32_t>& copyOf) {
    const size_t n = st.vertexCount;
    decodedOf.assign(n, kNoVertex);
    std::vector<uint32_t> copies;
    uint32_t next = 0;
    for (uint32_t w = 0; w < n; ++w) {
        if (!st.copies || st.originalOf[w] == kNoVertex) decodedOf[w] = next++;
        else copies.push_back(w);
    }
    std::sort(copies.begin(), copies.end(), [&](uint32_t a, uint32_t b) {
        return std::make_pair(decodedOf[st.originalOf[a]], a) < std::make_pair(decodedOf[st.originalOf[b]], b);
    });
    copyOf.clear();
    for (uint32_t w : copies) {
        copyOf.push_back(decodedOf[st.originalOf[w]]);
        decodedOf[w] = next++;
    }
}

}  // namespace

TopologicalStreams encodeTopological(const std::vector<int32_t>& grid, int bits, const std::vector<uint32_t>& triangles,
                                     const std::vector<uint32_t>& copyOf, TopologicalLayout* layout, TopologicalStats* stats,
                                     const TopologicalBudget& budget) {
    const size_t vertexCount = grid.size() / 3, faceCount = triangles.size() / 3;
    if (bits < 1 || bits > 21) throw Error("topological coder: bits must be 1 to 21");
    if (copyOf.size() > vertexCount) throw Error("topological coder: more copies than vertices");
    const size_t firstCopy = vertexCount - copyOf.size();
    for (uint32_t original : copyOf)
        if (original >= firstCopy) throw Error("topological coder: a copy of a copy or of no vertex");
    Truth truth(grid, triangles, vertexCount);
    if (budget.meshChecked) {
        buildTopology(triangles, vertexCount, &truth.topology);
    } else {
        const std::string problem = topologyProblem(triangles, vertexCount, &truth.topology);
        if (!problem.empty()) throw Error("topological coder: " + problem);
    }
    truth.giveUpAbove = budget.giveUpAbove;
    truth.firstCopy = firstCopy;
    truth.copyOf = &copyOf;
    truth.groupOriginal.assign(firstCopy, kNoVertex);
    WalkState st(vertexCount, faceCount, bits);
    st.search = budget.search;
    st.progress = budget.progress;
    st.copies = !copyOf.empty();
    if (st.copies) st.originalOf.assign(st.slotOf.size(), kNoVertex);
    RangeEncoder connectivityCoder, geometryCoder;
    Writer connectivity{connectivityCoder}, geometry{geometryCoder};
    if (stats) *stats = TopologicalStats();
    walk(connectivity, geometry, st, &truth, stats);
    if (truth.gaveUp) {
        TopologicalStreams none;
        none.complete = false;
        return none;
    }
    if (st.traversal.triangleCount() != faceCount)
        throw Error(ErrorKind::Internal, "internal error: the topological walk rebuilt another face count");

    if (st.copiesMet != copyOf.size()) throw Error(ErrorKind::Internal, "internal error: the topological walk met another copy count");
    std::vector<uint32_t> decodedOf, copiesOf;
    numberDecoded(st, decodedOf, copiesOf);
    if (layout) {
        layout->vertexOf.assign(vertexCount, 0);
        for (uint32_t w = 0; w < vertexCount; ++w) layout->vertexOf[decodedOf[w]] = truth.inputOf[w];
        layout->faceOf = std::move(truth.faceOf);
        layout->triangles = st.traversal.takeTriangles();
        for (uint32_t& v : layout->triangles) v = decodedOf[v];
        layout->copyOf = std::move(copiesOf);
        layout->components = st.components;
        layout->boundaryEdges = st.boundaryEdges;
    }
    TopologicalStreams out;
    out.connectivity = connectivityCoder.finish();
    out.geometry = geometryCoder.finish();
    return out;
}

TopologicalMesh decodeTopological(const uint8_t* connectivityBytes, size_t connectivitySize, const uint8_t* geometryBytes,
                                  size_t geometrySize, size_t vertexCount, size_t copyCount, size_t faceCount, int bits,
                                  const OtherSearchBound& search, const WalkProgress& progress) {
    if (bits < 1 || bits > 21) throw Error(ErrorKind::Corrupt, "corrupt file: bits must be 1 to 21");
    const size_t total = vertexCount + copyCount;
    // Each vertex codes at least three binary decisions, none cheaper than
    // log2(4096 / 4095) bits (bit_model.h): a byte holds fewer than 8,192.
    if (total == 0 || total / 8192 > geometrySize + 64)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(total) + " vertices claimed by a topological section of " +
                    std::to_string(geometrySize) + " bytes");
    WalkState st(total, faceCount, bits);
    st.search = search;
    st.progress = progress;
    st.copies = copyCount > 0;
    if (st.copies) st.originalOf.assign(st.slotOf.size(), kNoVertex);
    RangeDecoder connectivityCoder(connectivityBytes, connectivitySize);
    RangeDecoder geometryCoder(geometryBytes, geometrySize);
    Reader connectivity{connectivityCoder}, geometry{geometryCoder};
    walk(connectivity, geometry, st, nullptr, nullptr);
    if (connectivityCoder.bytesPastEnd() > 0 || geometryCoder.bytesPastEnd() > 0)
        throw Error(ErrorKind::Corrupt, "corrupt file: a topological section ends before its last symbol");
    if (st.copiesMet != copyCount)
        throw Error(ErrorKind::Corrupt, "corrupt file: the topological section meets " + std::to_string(st.copiesMet) +
                    " vertex copies, the header says " + std::to_string(copyCount));
    std::vector<uint32_t> decodedOf;
    TopologicalMesh out;
    numberDecoded(st, decodedOf, out.copyOf);
    out.grid.resize(3 * total);
    for (size_t w = 0; w < total; ++w)
        for (int k = 0; k < 3; ++k) out.grid[3 * size_t(decodedOf[w]) + size_t(k)] = st.grid[3 * w + size_t(k)];
    out.triangles = st.traversal.takeTriangles();
    for (uint32_t& v : out.triangles) v = decodedOf[v];
    out.components = st.components;
    out.boundaryEdges = st.boundaryEdges;
    return out;
}

}  // namespace drm
