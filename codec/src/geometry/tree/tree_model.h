// The spanning-tree vertex coder's model, shared by its encoder and its
// decoder: each vertex's prediction candidates (parent, the previous tree
// edge, reflections and parallelograms over the near decoded points), the
// local frame, and the coding state (bit models and contexts) that encoder
// and decoder update in the same order.
#ifndef DRM_TREE_MODEL_H
#define DRM_TREE_MODEL_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "common.h"
#include "drmcodec/drmcodec.h"
#include "entropy/bit_model.h"
#include "entropy/rank_coder.h"
#include "geometry/tree/cell_index.h"
#include "geometry/tree/local_frame.h"
#include "geometry/tree/residual_model.h"
#include "geometry/tree/tree_coder.h"

namespace drm {
namespace tree_coding {

constexpr int kChoiceContexts = 4;  // the one-symbol choice's tables (the section's bit F = 0): by the previous choice, clamped
constexpr uint32_t kDirectChildCounts = 8;  // 0..7, then an escape
constexpr int kCellBitsWidth = 5;  // bits of the section header's cell size field

// The decoded points a prediction is built from are the kNearest decoded
// vertices nearest the parent; the candidates are the parent itself, the
// previous tree edge repeated from the parent, the reflections 2p - q of the
// near points q through the parent, and the parallelograms p + q - w over
// ordered pairs of them (on a surface sampled by near-regular triangles the
// next vertex around p often lies there).
constexpr int kMaxCandidates = 2 + kNearest + kNearest * (kNearest - 1);
constexpr int kPaddedCandidates = (kMaxCandidates + 3) / 4 * 4;
struct Predictions {
    // The candidates, one array per axis, padded (pad()) with points far
    // from every candidate: crowding is a short branch-free scan over them.
    static constexpr int32_t kFar = -(1 << 28);
    // Candidates lie within [-2^21, 2^22] (21-bit coordinates, reflections
    // and parallelograms of them): far from kFar, and crowded()'s
    // differences fit in int32.
    static_assert(kMaxQuantizationBits <= 21, "candidates must stay far from kFar");
    int32_t xs[kPaddedCandidates], ys[kPaddedCandidates], zs[kPaddedCandidates];
    int count = 0;
    // The decoded points the candidates are built from, the parent first,
    // then the parent again in the place of near points it lacks (a point
    // twice changes no least distance, and every entry is then worth
    // looking at); as 64-bit coordinates, which distances are taken in.
    struct Known {
        int64_t x, y, z;
    };
    Known known[1 + kNearest];
    // The squared distance from the parent to the nearest of its near
    // points, and to the farthest: the local spacing (0 if it has none).
    int64_t nearest2 = 0;
    int64_t spacing2 = 0;
    // Two candidates crowd each other when no coordinate differs by more
    // than this: a fifth of the spacing.
    int32_t crowdRadius = 0;
    // With the section's bit G the residual from the parent (candidate 0)
    // may be coded in this frame: the surface's normal at the parent as its
    // third axis.
    LocalFrame frame;
    // Each candidate's flag context (flagContextOf), once known: the
    // encoder asks for it again when it codes the flag it priced.
    mutable int8_t flagContext[kMaxCandidates];

    Predictions() { std::fill(flagContext, flagContext + kMaxCandidates, int8_t(-1)); }
    GridPoint candidate(int c) const { return {xs[c], ys[c], zs[c]}; }
    void add(GridPoint c) {
        xs[count] = c.x;
        ys[count] = c.y;
        zs[count] = c.z;
        ++count;
    }
    // Once every candidate is in: the padding after them.
    void pad() {
        for (int k = count; k < kPaddedCandidates; ++k) xs[k] = ys[k] = zs[k] = kFar;
    }
};

// The section can name the predictor (when its bit F is 1) with a
// yes/no flag per candidate, in index order, each in a context of what the
// decoder can see about it:
// - how near it lies to a decoded point (under a quarter, half, or one
//   spacing, or farther: a vertex is rarely right next to one already
//   decoded, so a candidate on top of a decoded point is rarely the one);
// - whether it was the previous vertex's choice;
// - whether another candidate crowds it.
// A candidate equal to an earlier one has no flag, nor has the last one
// left (a "no" to every other names it). Against one symbol over all
// candidates this is smaller on the corpus (docs/tuning.md); one symbol
// still wins on coarse grids, where candidates pile up.
constexpr int kDistanceBuckets = 4;
inline int distanceBucket(const Predictions& p, int c) {
    if (p.spacing2 == 0) return kDistanceBuckets - 1;
    // The parent's nearest decoded point but itself is its nearest near
    // point, whose distance predict() kept.
    int64_t nearest = p.nearest2;
    if (c != 0) {
        const int64_t x = p.xs[c], y = p.ys[c], z = p.zs[c];
        nearest = INT64_MAX;
        for (const Predictions::Known& k : p.known)
            nearest = std::min(nearest, (x - k.x) * (x - k.x) + (y - k.y) * (y - k.y) + (z - k.z) * (z - k.z));
    }
    if (16 * nearest < p.spacing2) return 0;
    if (4 * nearest < p.spacing2) return 1;
    if (nearest < p.spacing2) return 2;
    return 3;
}
// Four lanes at once (GCC and Clang vector extensions: SSE2 on x86-64,
// NEON on ARM, plain code elsewhere); the compilers leave the scalar loop
// unvectorized, at about 140 instructions a call.
typedef uint32_t Lanes __attribute__((vector_size(16)));
typedef int32_t SignedLanes __attribute__((vector_size(16)));
inline int crowded(const Predictions& p, int c) {
    // A candidate k lies within the radius of c on an axis when
    // k - (c - radius), as unsigned, is at most twice the radius. SSE2
    // compares signed lanes only: with the top bit flipped on both sides
    // the unsigned comparison becomes a signed one, and flipping the top
    // bit of a difference is subtracting the flipped subtrahend.
    constexpr uint32_t kFlip = 0x80000000u;
    const uint32_t x = (uint32_t(p.xs[c] - p.crowdRadius)) ^ kFlip, y = (uint32_t(p.ys[c] - p.crowdRadius)) ^ kFlip,
                   z = (uint32_t(p.zs[c] - p.crowdRadius)) ^ kFlip;
    const int32_t width = int32_t(uint32_t(2 * p.crowdRadius) ^ kFlip);
    SignedLanes outside = {0, 0, 0, 0};  // minus the count of candidates outside c's box, per lane
    for (int k = 0; k < kPaddedCandidates; k += 4) {
        Lanes xs, ys, zs;
        std::memcpy(&xs, p.xs + k, sizeof xs);
        std::memcpy(&ys, p.ys + k, sizeof ys);
        std::memcpy(&zs, p.zs + k, sizeof zs);
        outside += (SignedLanes(xs - x) > width) | (SignedLanes(ys - y) > width) | (SignedLanes(zs - z) > width);
    }
    // c lies within its own box: crowded when another candidate does too.
    const int32_t within = kPaddedCandidates + (outside[0] + outside[1] + outside[2] + outside[3]);
    return within > 1 ? 1 : 0;
}
inline bool repeatsEarlier(const Predictions& p, int c) {
    const int32_t x = p.xs[c], y = p.ys[c], z = p.zs[c];
    for (int k = 0; k < c; ++k)
        if (p.xs[k] == x && p.ys[k] == y && p.zs[k] == z) return true;
    return false;
}
// The first candidate after c that is not a repeat, or p.count if none
// is: c is then the last candidate flags can name, and needs no flag of
// its own. (Candidate 0 is never a repeat.) Usually the next one: asking
// this as the flags go, instead of finding the last up front, looks at
// only as many candidates as the flags reach.
inline int nextFlagged(const Predictions& p, int c) {
    int next = c + 1;
    while (next < p.count && repeatsEarlier(p, next)) ++next;
    return next;
}

// The residual from the parent itself (the whole tree edge) has models of
// its own, apart from the residuals from the other candidates, which are
// small corrections.
constexpr int kResidualGroups = 2;
// The signs of coded residuals, as sign contexts see them.
enum Sign : uint8_t { kNoSign = 0, kPositive = 1, kNegative = 2 };
inline uint8_t signOf(int32_t r) { return r > 0 ? kPositive : r < 0 ? kNegative : kNoSign; }

inline int residualGroup(uint32_t choice) { return choice != 0 ? 1 : 0; }

// A child count is coded in a context of the parent's own child count (1,
// 2, 3 or more: a parent has at least one; roots apart).
constexpr int kChildCountContexts = 4;

// The sign of each tangent component of a residual coded in the frame has
// one of 27 models (tangentSignModel).
constexpr int kTangentSignContexts = 27;

// Everything both sides track while walking the tree.
struct CodingState {
    bool framedParent;                 // the section's bit G: the residual from the parent may be coded in its local frame
    bool tangentSigns;                 // with G: that frame turned along the walk, its tangent signs by where near points lie
    bool choiceFlags;                  // the choice as flags (the section's bit F = 1), else one symbol
    std::vector<GridPoint> pos;        // decoded positions
    std::vector<uint32_t> parentOf;    // decoded parent, kNoVertex for roots
    std::vector<uint32_t> magnitude;   // |residual| per axis, 3 per vertex
    std::vector<uint8_t> signs;        // the residual's Sign per axis, 3 per vertex
    std::vector<uint8_t> childCountOf; // decoded child-count symbols (8: escaped)
    DecodedCells cells;
    AxisModels axis[kResidualGroups][3];  // [residual group][axis]
    std::vector<AdaptiveFrequencies> predictorChoice;                // one symbol: [previous choice, clamped]
    BitModel isChoice[kMaxCandidates][kDistanceBuckets][2][2];       // flags: [candidate][distance][was previous][crowded]
    BitModel tangentSign[2][kTangentSignContexts];                   // [tangent axis][context]
    std::vector<AdaptiveFrequencies> childCount;                     // [context]
    uint32_t previousChoice = 0;
    // Whether the local frame has lately coded edges from the parent in
    // fewer bits than the grid's axes (> 0): after every vertex, both sides
    // add 256 times the difference in rough bits and decay the sum by
    // 1/kFrameMemory (the best of 2 to 128: docs/tuning.md). The frame gets
    // one rough bit more per vertex (kFrameCredit): its tangent signs cost
    // less than the bit each that rough bits count.
    static constexpr int64_t kFrameMemory = 8;
    static constexpr int64_t kFrameCredit = 256;
    int64_t frameScore = 0;
    uint64_t framedResiduals = 0;  // how many were coded in the frame (for tests and statistics)
    bool frameNow() const { return framedParent && frameScore > 0; }

    // The encoder prices residuals (Pricing) under the models of one group,
    // axis and context at a time, and a price holds until a residual is
    // coded in that context: each coded vertex changes three of the 48
    // tables, so the others are kept (encoders only: a decoder never prices).
    uint32_t residualsCoded[kResidualGroups][3][kMagnitudeContexts] = {};
    struct KeptCosts {
        ResidualCosts costs;
        uint32_t residualsCoded = ~0u;  // when they were built
    };
    std::vector<KeptCosts> keptCosts;
    const ResidualCosts& residualCosts(int group, int a, int context) {
        if (keptCosts.empty()) {
            keptCosts.resize(kResidualGroups * 3 * kMagnitudeContexts);
            for (int g = 0; g < kResidualGroups; ++g)
                for (int b = 0; b < 3; ++b)
                    for (int k = 0; k < kMagnitudeContexts; ++k)
                        keptCosts[size_t((g * 3 + b) * kMagnitudeContexts + k)].costs = ResidualCosts(axis[g][b], k);
        }
        KeptCosts& kept = keptCosts[size_t((group * 3 + a) * kMagnitudeContexts + context)];
        const uint32_t now = residualsCoded[group][a][context];
        if (kept.residualsCoded != now) {
            kept.costs.forget();  // cheaper than a new one: the prices need not be cleared
            kept.residualsCoded = now;
        }
        return kept.costs;
    }

    CodingState(int cellBits, bool flagChoices, bool frameAllowed)
        : framedParent(frameAllowed),
          tangentSigns(frameAllowed),
          choiceFlags(flagChoices),
          cells(cellBits),
          predictorChoice(kChoiceContexts, AdaptiveFrequencies(std::vector<uint16_t>(kMaxCandidates, 1))),
          childCount(kChildCountContexts, AdaptiveFrequencies(std::vector<uint16_t>(kDirectChildCounts + 1, 1))) {
        // The models learn their first bits fast (BitModel::agile:
        // small meshes, whose models see few bits, gain most), and a flag,
        // mostly "no", starts at 1/8.
        for (auto& byCandidate : isChoice)
            for (auto& byDistance : byCandidate)
                for (auto& byPrevious : byDistance)
                    for (BitModel& m : byPrevious) m = BitModel::agile(65536 / 8);
        for (auto& group : axis)
            for (AxisModels& a : group) a.makeAgile();
        for (auto& byAxis : tangentSign)
            for (BitModel& m : byAxis) m = BitModel::agile();
    }

    // Starts vertex `self` (the next decoded index): its parent is known,
    // its residuals not yet.
    void begin(uint32_t parent) {
        parentOf.push_back(parent);
        magnitude.insert(magnitude.end(), 3, 0);
        signs.insert(signs.end(), 3, kNoSign);
    }
    void place(uint32_t self, GridPoint at) {
        pos.push_back(at);
        cells.insert(self, at);
    }
    AdaptiveFrequencies& childCountModel(uint32_t self) {
        const uint32_t parent = parentOf[self];
        if (parent == kNoVertex) return childCount[kChildCountContexts - 1];
        const uint8_t ofParent = childCountOf[parent];  // at least 1: it announced this child
        return childCount[ofParent >= 3 ? 2 : ofParent == 2 ? 1 : 0];
    }
};

// A sign context per axis. Residuals along the tree are not
// independent: where a candidate overshoots the surface (curvature, a
// scanner's rows, a grid's regular steps) it tends to overshoot the same way
// for the parent and the child, and one error leaks into several axes. The
// parent's sign on the axis and this vertex's on the axis before name one of
// nine models (the corpus's files 0.7 % smaller in geometric mean).
inline int signContext(const CodingState& s, uint32_t self, uint32_t parent, int axis) {
    const int ofParent = s.signs[3 * size_t(parent) + size_t(axis)];
    const int before = axis > 0 ? int(s.signs[3 * size_t(self) + size_t(axis - 1)]) : int(kNoSign);
    return 3 * ofParent + before;
}

// The expected size of this vertex's residual on an axis, from residuals
// already coded nearby: the parent's and the previous vertex's.
inline int magnitudeContext(const CodingState& s, uint32_t self, uint32_t parent, int axis) {
    const uint32_t previous = s.magnitude[3 * size_t(self - 1) + size_t(axis)];
    const uint32_t ofParent = s.magnitude[3 * size_t(parent) + size_t(axis)];
    return std::min(bitLength(uint32_t((uint64_t(previous) + ofParent + 1) / 2)), kMagnitudeContexts - 1);
}

// Whether surfaceFrame's sums fit in 64 bits for near points from cells
// of side 2^cellBits: they lie in the 2x2x2 block of cells around `at`
// (DecodedCells::nearest), each coordinate less than 2^(cellBits + 1)
// away, so a cross product's components stay below 2^(2 cellBits + 3), the
// normal's (a sum of at most 6) below 2^(2 cellBits + 6), and a dot product
// of the two below 2^(4 cellBits + 11): within int64 up to cellBits 13.
// Wider cells (a coarse mesh on a fine grid) take 128 bits.
inline bool frameIn64Bits(int cellBits) { return cellBits <= 13; }

// The frame of the surface at `at`, from its near decoded points: the
// normal is the sum of the cross products of every pair of edges to them,
// each turned to agree with the sum so far (near points come in distance
// order, not around the parent). Fewer than two give the identity.
// kIn64Bits: the near points lie within 2^14 of `at` on every axis, so the
// dot products that turn each cross product take 64 bits exactly
// (frameIn64Bits); otherwise they take 128 (a WebAssembly build multiplies
// those through a call).
template <bool kIn64Bits>
inline LocalFrame summedSurfaceFrame(GridPoint at, const GridPoint* near, int m) {
    int64_t n[3] = {0, 0, 0};
    for (int i = 0; i < m; ++i) {
        const int64_t ux = int64_t(near[i].x) - at.x, uy = int64_t(near[i].y) - at.y, uz = int64_t(near[i].z) - at.z;
        for (int j = i + 1; j < m; ++j) {
            const int64_t vx = int64_t(near[j].x) - at.x, vy = int64_t(near[j].y) - at.y, vz = int64_t(near[j].z) - at.z;
            int64_t c[3] = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};  // below 2^43 each
            bool agrees;
            if constexpr (kIn64Bits) agrees = c[0] * n[0] + c[1] * n[1] + c[2] * n[2] >= 0;
            else agrees = __int128(c[0]) * n[0] + __int128(c[1]) * n[1] + __int128(c[2]) * n[2] >= 0;
            const int64_t sign = agrees ? 1 : -1;
            for (int a = 0; a < 3; ++a) n[a] += sign * c[a];  // at most 6 pairs: below 2^46
        }
    }
    return LocalFrame(n[0], n[1], n[2]);
}
// Any near points.
inline LocalFrame surfaceFrame(GridPoint at, const GridPoint* near, int m) { return summedSurfaceFrame<false>(at, near, m); }
// Near points from DecodedCells of side 2^cellBits: the same frame, in 64
// bits where they suffice.
inline LocalFrame surfaceFrame(GridPoint at, const GridPoint* near, int m, int cellBits) {
    return frameIn64Bits(cellBits) ? summedSurfaceFrame<true>(at, near, m) : summedSurfaceFrame<false>(at, near, m);
}

// The frame is turned about its normal so that its first axis points
// the way the tree last went, from the parent's parent to the parent (a
// depth-first walk tends to go on straight: the first tangent component of
// the next edge is then mostly positive).
inline void turnAlongTheWalk(const CodingState& s, uint32_t parent, LocalFrame& frame) {
    const uint32_t grandparent = s.parentOf[parent];
    if (grandparent == kNoVertex) return;
    const GridPoint at = s.pos[parent], from = s.pos[grandparent];
    frame.alignFirstAxis(int64_t(at.x) - from.x, int64_t(at.y) - from.y, int64_t(at.z) - from.z);
}

// Where the near points lie in the frame's tangent plane: how
// many have a positive and a negative first coordinate, and how many lie in
// each quadrant [first < 0][second < 0] (points on an axis in none). A new
// vertex seldom lies where decoded points already are, so these tell the
// signs of a residual coded in the frame (up to 2 % off a scan's whole
// file). Worked out only for such a residual.
struct NearPointSides {
    uint8_t side[2] = {0, 0};
    uint8_t quadrant[2][2] = {{0, 0}, {0, 0}};
};
inline NearPointSides nearPointSides(const Predictions& p) {
    NearPointSides sides;
    for (int i = 1; i <= kNearest; ++i) {  // known[0] is the parent; missing near points repeat it
        int64_t q[3] = {p.known[i].x - p.known[0].x, p.known[i].y - p.known[0].y, p.known[i].z - p.known[0].z};
        if (q[0] == 0 && q[1] == 0 && q[2] == 0) continue;
        p.frame.toFrame(q);
        if (q[0] == 0) continue;
        ++sides.side[q[0] < 0];
        if (q[1] != 0) ++sides.quadrant[q[0] < 0][q[1] < 0];
    }
    return sides;
}

// The sign model of tangent component `axis` (0 or 1) of a
// residual coded in the frame, of bit length `length`, from where the near
// points lie and from how long the component is:
// - the first component: by the near points on its positive and on its
//   negative side (0, 1, 2 or more each), and by its length against the
//   spacing (long: a new vertex away from the others; short: little to
//   tell);
// - the second: by the near points in the two quadrants on the first
//   component's side (none counted when the first is zero), and by its
//   length against the first's.
inline BitModel& tangentSignModel(CodingState& s, const Predictions& p, const NearPointSides& sides, int axis, int length,
                           int32_t first) {
    const auto clamped = [](uint8_t count) { return std::min<int>(count, 2); };
    int where = 0, howLong = 0;
    if (axis == 0) {
        where = 3 * clamped(sides.side[0]) + clamped(sides.side[1]);
        const int spacing = bitLength(uint64_t(p.spacing2));
        howLong = 2 * length >= spacing + 1 ? 2 : 2 * length >= spacing - 3 ? 1 : 0;
    } else {
        if (first != 0) {
            const int negative = first < 0 ? 1 : 0;
            where = 3 * clamped(sides.quadrant[negative][0]) + clamped(sides.quadrant[negative][1]);
        }
        const int ofFirst = bitLength(magnitudeOf(first));
        howLong = length > ofFirst ? 2 : length == ofFirst ? 1 : 0;
    }
    return s.tangentSign[axis][3 * where + howLong];
}

inline Predictions predict(const CodingState& s, uint32_t self, uint32_t parent) {
    Predictions p;
    const GridPoint at = s.pos[parent];
    p.add(at);
    const uint32_t previous = self - 1;  // repeat the previous tree edge (regular samplings)
    p.add(s.parentOf[previous] != kNoVertex ? at + (s.pos[previous] - s.pos[s.parentOf[previous]]) : at);
    GridPoint near[kNearest];
    int64_t nearD2[kNearest];
    const int m = s.cells.nearest(parent, at, near, nearD2);
    for (int i = 0; i < m; ++i) p.add(at + (at - near[i]));
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            if (i != j) p.add(at + (near[i] - near[j]));
    p.pad();
    p.spacing2 = m > 0 ? nearD2[m - 1] : 0;
    if (s.choiceFlags || s.tangentSigns)
        for (int i = 0; i <= kNearest; ++i) {
            const GridPoint k = i > 0 && i <= m ? near[i - 1] : at;
            p.known[i] = {k.x, k.y, k.z};
        }
    if (s.choiceFlags) {  // the flags' contexts
        p.nearest2 = m > 0 ? nearD2[0] : 0;
        p.crowdRadius = int32_t(integerSqrt(uint64_t(p.spacing2)) / 5);
    }
    if (s.framedParent) {
        p.frame = surfaceFrame(at, near, m, s.cells.cellBits());
        if (s.tangentSigns) turnAlongTheWalk(s, parent, p.frame);
    }
    return p;
}

// The residual from the parent (the whole tree edge) is coded in the
// parent's local frame when the frame has lately served better than the
// grid's axes: there the edge's component along the normal is small, which
// pays on unevenly sampled scans (4 to 6 % of their geometry); on CAD
// meshes whose edges follow the axes the axes serve better (a zero
// component costs one cheap flag). The same residual models serve both
// (models of their own for the frame make the corpus's files larger),
// and other candidates' residuals, small corrections, stay on the axes
// (rounding inflates them, per the method notes).
inline bool framed(bool frameNow, uint32_t choice) { return frameNow && choice == 0; }
inline GridPoint toFrame(const LocalFrame& frame, GridPoint r) {
    int64_t v[3] = {r.x, r.y, r.z};
    frame.toFrame(v);
    return {int32_t(v[0]), int32_t(v[1]), int32_t(v[2])};  // |r| below 2^22: rotated, still below 2^23
}

// How many bits fewer the edge from the parent (candidate 0) to `at` takes
// in the local frame than on the grid's axes, roughly: per component its
// bit length, plus one for the sign of any but zero.
inline int roughBits(GridPoint r) {
    int bits = 0;
    for (int32_t v : {r.x, r.y, r.z}) bits += v == 0 ? 0 : bitLength(magnitudeOf(v)) + 1;
    return bits;
}
inline int frameAdvantage(const LocalFrame& frame, GridPoint edge) { return roughBits(edge) - roughBits(toFrame(frame, edge)); }

// What a flag's context takes from the candidates alone: its distance
// bucket and whether it is crowded.
inline int flagContextOf(const Predictions& p, int c) {
    int8_t& known = p.flagContext[c];
    if (known < 0) known = int8_t(2 * distanceBucket(p, c) + crowded(p, c));
    return known;
}
inline BitModel& flagOf(CodingState& s, const Predictions& p, int c) {
    const int context = flagContextOf(p, c);
    return s.isChoice[c][context >> 1][s.previousChoice == uint32_t(c) ? 1 : 0][context & 1];
}

}  // namespace tree_coding
}  // namespace drm

#endif  // DRM_TREE_MODEL_H
