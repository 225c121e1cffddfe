#include "geometry/tree/tree_coder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <future>
#include <numeric>
#include <string>
#include <utility>

#include "entropy/bit_model.h"
#include "geometry/tree/cell_index.h"
#include "common.h"
#include "concurrency.h"
#include "drm/drm.h"
#include "geometry/tree/local_frame.h"
#include "mesh/quantize.h"
#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"
#include "geometry/tree/residual_model.h"
#include "geometry/tree/spanning_tree.h"

namespace drm {
namespace {

constexpr int kChoiceContexts = 4;  // the one-symbol choice's tables (format 1, and 2 with F = 0): by the previous choice, clamped
constexpr uint32_t kDirectChildCounts = 8;  // 0..7, then an escape

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
    // Format 3 codes the residual from the parent (candidate 0) in this
    // frame: the surface's normal at the parent as its third axis.
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

// Format 2 can name the predictor (when the section's bit F is 1) with a
// yes/no flag per candidate, in index order, each in a context of what the
// decoder can see about it:
// - how near it lies to a decoded point (under a quarter, half, or one
//   spacing, or farther: a vertex is rarely right next to one already
//   decoded, so a candidate on top of a decoded point is rarely the one);
// - whether it was the previous vertex's choice;
// - whether another candidate crowds it.
// A candidate equal to an earlier one has no flag, nor has the last one
// left (a "no" to every other names it). Against one symbol over all
// candidates this is 2 % smaller on the corpus (docs/geometry-ablation.md,
// "Format 2"); one symbol still wins on coarse grids, where candidates
// pile up.
constexpr int kDistanceBuckets = 4;
int distanceBucket(const Predictions& p, int c) {
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
// NEON on ARM, plain code elsewhere); the compilers left the scalar loop
// unvectorized, at about 140 instructions a call.
typedef uint32_t Lanes __attribute__((vector_size(16)));
typedef int32_t SignedLanes __attribute__((vector_size(16)));
int crowded(const Predictions& p, int c) {
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
bool repeatsEarlier(const Predictions& p, int c) {
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
int nextFlagged(const Predictions& p, int c) {
    int next = c + 1;
    while (next < p.count && repeatsEarlier(p, next)) ++next;
    return next;
}

// Format 2 also codes the residual from the parent itself (the whole tree
// edge) with models of its own, apart from the residuals from the other
// candidates, which are small corrections; format 1 has one set.
constexpr int kResidualGroups = 2;
// Format 6's signs of coded residuals, as sign contexts see them.
enum Sign : uint8_t { kNoSign = 0, kPositive = 1, kNegative = 2 };
inline uint8_t signOf(int32_t r) { return r > 0 ? kPositive : r < 0 ? kNegative : kNoSign; }

inline int residualGroup(bool version2, uint32_t choice) { return version2 && choice != 0 ? 1 : 0; }

// Format 2 codes a child count in a context of the parent's own child
// count (1, 2, 3 or more: a parent has at least one; roots apart); format 1
// has one table.
constexpr int kChildCountContexts = 4;

// Format 7: the sign of each tangent component of a residual coded in the
// frame has one of 27 models (tangentSignModel).
constexpr int kTangentSignContexts = 27;

// Everything both sides track while walking the tree.
struct CodingState {
    bool version2;                     // format 2's residual models and child-count contexts (else format 1's)
    bool spacingContexts;              // format 3: the residual from the parent in contexts of the spacing
    bool signContexts;                 // format 6: signs in contexts of the parent's and the previous axis'
    bool framedParent;                 // format 3 with the section's bit G: ... and in its local frame
    bool tangentSigns;                 // format 7: that frame turned along the walk, its tangent signs by where near points lie
    bool choiceFlags;                  // the choice as flags (format 2, F = 1), else one symbol
    std::vector<GridPoint> pos;        // decoded positions
    std::vector<uint32_t> parentOf;    // decoded parent, kNoVertex for roots
    std::vector<uint32_t> magnitude;   // |residual| per axis, 3 per vertex
    std::vector<uint8_t> signs;        // format 6: the residual's Sign per axis, 3 per vertex
    std::vector<uint8_t> childCountOf; // decoded child-count symbols (8: escaped)
    DecodedCells cells;
    AxisModels axis[kResidualGroups][3];  // [residual group][axis]
    std::vector<AdaptiveFrequencies> predictorChoice;                // one symbol: [previous choice, clamped]
    BitModel isChoice[kMaxCandidates][kDistanceBuckets][2][2];       // flags: [candidate][distance][was previous][crowded]
    BitModel tangentSign[2][kTangentSignContexts];                   // format 7: [tangent axis][context]
    std::vector<AdaptiveFrequencies> childCount;                     // [context]
    uint32_t previousChoice = 0;
    // Format 3: whether the local frame has lately coded edges from the
    // parent in fewer bits than the grid's axes (> 0): after every vertex,
    // both sides add 256 times the difference in rough bits and decay the
    // sum by 1/kFrameMemory (8: 2 and 4, 32 and 128 all measured worse, by
    // 0.1 to 0.17 % of geometry). Format 7 credits the frame one rough bit
    // more per vertex: its tangent signs cost less than the bit each that
    // rough bits count (corpus whole file -0.2 % in geometric mean over
    // format 7 without it; elephant -2.2 %, horse-lres -1.7 %).
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

    CodingState(int cellBits, int formatVersion, bool flagChoices, bool frameAllowed)
        : version2(formatVersion >= 2),
          spacingContexts(formatVersion >= 3),
          signContexts(formatVersion >= 6),
          framedParent(formatVersion >= 3 && frameAllowed),
          tangentSigns(formatVersion >= 7 && frameAllowed),
          choiceFlags(formatVersion >= 2 && flagChoices),
          cells(cellBits),
          predictorChoice(kChoiceContexts, AdaptiveFrequencies(std::vector<uint16_t>(kMaxCandidates, 1))),
          childCount(kChildCountContexts, AdaptiveFrequencies(std::vector<uint16_t>(kDirectChildCounts + 1, 1))) {
        // Format 2's models learn their first bits fast (BitModel::agile:
        // 1.8 % smaller geometry on the corpus, up to 14 % on small meshes),
        // and a flag, mostly "no", starts at 1/8.
        for (auto& byCandidate : isChoice)
            for (auto& byDistance : byCandidate)
                for (auto& byPrevious : byDistance)
                    for (BitModel& m : byPrevious) m = BitModel::agile(65536 / 8);
        if (version2)
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
        if (signContexts) signs.insert(signs.end(), 3, kNoSign);
    }
    void place(uint32_t self, GridPoint at) {
        pos.push_back(at);
        cells.insert(self, at);
    }
    AdaptiveFrequencies& childCountModel(uint32_t self) {
        if (!version2) return childCount[0];
        const uint32_t parent = parentOf[self];
        if (parent == kNoVertex) return childCount[kChildCountContexts - 1];
        const uint8_t ofParent = childCountOf[parent];  // at least 1: it announced this child
        return childCount[ofParent >= 3 ? 2 : ofParent == 2 ? 1 : 0];
    }
};

// Format 6: a sign context per axis. Residuals along the tree are not
// independent: where a candidate overshoots the surface (curvature, a
// scanner's rows, a grid's regular steps) it tends to overshoot the same way
// for the parent and the child, and one error leaks into several axes. The
// parent's sign on the axis and this vertex's on the axis before name one of
// nine models (corpus whole file -0.7 % in geometric mean; teapot -4 %,
// igea -2 %, bunny -1 %).
int signContext(const CodingState& s, uint32_t self, uint32_t parent, int axis) {
    if (!s.signContexts) return 0;
    const int ofParent = s.signs[3 * size_t(parent) + size_t(axis)];
    const int before = axis > 0 ? int(s.signs[3 * size_t(self) + size_t(axis - 1)]) : int(kNoSign);
    return 3 * ofParent + before;
}

// The expected size of this vertex's residual on an axis, from residuals
// already coded nearby: the parent's and the previous vertex's.
int magnitudeContext(const CodingState& s, uint32_t self, uint32_t parent, int axis) {
    const uint32_t previous = s.magnitude[3 * size_t(self - 1) + size_t(axis)];
    const uint32_t ofParent = s.magnitude[3 * size_t(parent) + size_t(axis)];
    return std::min(bitLength(uint32_t((uint64_t(previous) + ofParent + 1) / 2)), kMagnitudeContexts - 1);
}

// The frame of the surface at `at`, from its near decoded points: the
// normal is the sum of the cross products of every pair of edges to them,
// each turned to agree with the sum so far (near points come in distance
// order, not around the parent). Fewer than two give the identity.
LocalFrame surfaceFrame(GridPoint at, const GridPoint* near, int m) {
    int64_t n[3] = {0, 0, 0};
    for (int i = 0; i < m; ++i) {
        const int64_t ux = int64_t(near[i].x) - at.x, uy = int64_t(near[i].y) - at.y, uz = int64_t(near[i].z) - at.z;
        for (int j = i + 1; j < m; ++j) {
            const int64_t vx = int64_t(near[j].x) - at.x, vy = int64_t(near[j].y) - at.y, vz = int64_t(near[j].z) - at.z;
            int64_t c[3] = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};  // below 2^43 each
            const __int128 agreement = __int128(c[0]) * n[0] + __int128(c[1]) * n[1] + __int128(c[2]) * n[2];
            const int64_t sign = agreement < 0 ? -1 : 1;
            for (int a = 0; a < 3; ++a) n[a] += sign * c[a];  // at most 6 pairs: below 2^46
        }
    }
    return LocalFrame(n[0], n[1], n[2]);
}

// Format 7 turns the frame about its normal so that its first axis points
// the way the tree last went, from the parent's parent to the parent (a
// depth-first walk tends to go on straight: the first tangent component of
// the next edge is then mostly positive).
void turnAlongTheWalk(const CodingState& s, uint32_t parent, LocalFrame& frame) {
    const uint32_t grandparent = s.parentOf[parent];
    if (grandparent == kNoVertex) return;
    const GridPoint at = s.pos[parent], from = s.pos[grandparent];
    frame.alignFirstAxis(int64_t(at.x) - from.x, int64_t(at.y) - from.y, int64_t(at.z) - from.z);
}

// Format 7: where the near points lie in the frame's tangent plane: how
// many have a positive and a negative first coordinate, and how many lie in
// each quadrant [first < 0][second < 0] (points on an axis in none). A new
// vertex seldom lies where decoded points already are, so these tell the
// signs of a residual coded in the frame (venus-lres and max-planck-5k
// -2 % whole file, feline -1 %). Worked out only for such a residual.
struct NearPointSides {
    uint8_t side[2] = {0, 0};
    uint8_t quadrant[2][2] = {{0, 0}, {0, 0}};
};
NearPointSides nearPointSides(const Predictions& p) {
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

// Format 7: the sign model of tangent component `axis` (0 or 1) of a
// residual coded in the frame, of bit length `length`, from where the near
// points lie and from how long the component is:
// - the first component: by the near points on its positive and on its
//   negative side (0, 1, 2 or more each), and by its length against the
//   spacing (long: a new vertex away from the others; short: little to
//   tell);
// - the second: by the near points in the two quadrants on the first
//   component's side (none counted when the first is zero), and by its
//   length against the first's.
BitModel& tangentSignModel(CodingState& s, const Predictions& p, const NearPointSides& sides, int axis, int length,
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

Predictions predict(const CodingState& s, uint32_t self, uint32_t parent) {
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
    if (s.choiceFlags || s.spacingContexts) p.spacing2 = m > 0 ? nearD2[m - 1] : 0;
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
        p.frame = surfaceFrame(at, near, m);
        if (s.tangentSigns) turnAlongTheWalk(s, parent, p.frame);
    }
    return p;
}

// Format 3 codes the residual from the parent (the whole tree edge) in the
// parent's local frame when the frame has lately served better than the
// grid's axes: there the edge's component along the normal is small, which
// pays on unevenly sampled scans (venus -4.2 % geometry, nefertiti-50k
// -5.9 %); on CAD meshes whose edges follow the axes the axes serve better
// (a zero component costs one cheap flag). The same residual models serve
// both (models of their own for the frame: 0.15 % larger on the corpus),
// and other candidates' residuals, small corrections, stay on the axes
// (rounding inflates them, per the method notes).
bool framed(bool frameNow, uint32_t choice) { return frameNow && choice == 0; }
GridPoint toFrame(const LocalFrame& frame, GridPoint r) {
    int64_t v[3] = {r.x, r.y, r.z};
    frame.toFrame(v);
    return {int32_t(v[0]), int32_t(v[1]), int32_t(v[2])};  // |r| below 2^22: rotated, still below 2^23
}

// How many bits fewer the edge from the parent (candidate 0) to `at` takes
// in the local frame than on the grid's axes, roughly: per component its
// bit length, plus one for the sign of any but zero.
int roughBits(GridPoint r) {
    int bits = 0;
    for (int32_t v : {r.x, r.y, r.z}) bits += v == 0 ? 0 : bitLength(magnitudeOf(v)) + 1;
    return bits;
}
int frameAdvantage(const LocalFrame& frame, GridPoint edge) { return roughBits(edge) - roughBits(toFrame(frame, edge)); }

// What a flag's context takes from the candidates alone: its distance
// bucket and whether it is crowded.
int flagContextOf(const Predictions& p, int c) {
    int8_t& known = p.flagContext[c];
    if (known < 0) known = int8_t(2 * distanceBucket(p, c) + crowded(p, c));
    return known;
}
BitModel& flagOf(CodingState& s, const Predictions& p, int c) {
    const int context = flagContextOf(p, c);
    return s.isChoice[c][context >> 1][s.previousChoice == uint32_t(c) ? 1 : 0][context & 1];
}

// What coding the next vertex from each candidate costs under the current
// models, in bits: the residual per axis by its bit length, and naming the
// candidate. Built once per step of the encoder, which then prices the
// candidates of every vertex it might code next. (Floating point is fine
// here: the choice is transmitted, the decoder never repeats this.) The
// encoder writes format 2 only.
//
// Naming candidate c with flags costs the "no" flags of the candidates
// before it, each in a context that takes work to find (flagContextOf), so
// those costs are worked out only as far as a pick needs them
// (cheapestPick): most picks are settled by the first few candidates.
typedef int32_t Ints __attribute__((vector_size(16)));
typedef float Floats __attribute__((vector_size(16)));
class Pricing {
public:
    Pricing(CodingState& s, const Predictions& p, const int (*contexts)[3])
        : s_(s), p_(p), version2_(s.version2), frameNow_(s.frameNow()), flags_(s.choiceFlags) {
        for (int g = 0; g < kResidualGroups; ++g)
            for (int a = 0; a < 3; ++a) axis_[g][a] = &s.residualCosts(g, a, contexts[g][a]);
        others_ = axis_[residualGroup(version2_, 1)];
        if (!flags_) {
            symbols_ = &s.predictorChoice[std::min<uint32_t>(s.previousChoice, kChoiceContexts - 1)];
            symbolTotal_ = symbols_->totalCount();
        }
    }
    double residual(GridPoint r, uint32_t c) const {
        const bool inFrame = framed(frameNow_, c);
        const ResidualCosts* const* a = axis_[residualGroup(version2_, c)];
        if (inFrame) r = toFrame(p_.frame, r);
        return (*a[0])(r.x) + (*a[1])(r.y) + (*a[2])(r.z);
    }
    // Every candidate's residual(actual - candidate, c) into residual[c],
    // and leastFrom[c], the least of those from c on (leastFrom[count] is
    // 1e300). Candidates 1 and on share their models and are never turned
    // into the frame: their bit lengths come four at a time (the exponent of
    // the float 2m + 1 is 127 plus m's bit length; m is below 2^23, so the
    // float is exact), their tables are priced as far as the longest, and
    // then each residual is three loads and the same sum as residual()'s.
    void residuals(GridPoint actual, double* residual, double* leastFrom) const {
        alignas(16) int32_t length[3][kPaddedCandidates];
        const int32_t at[3] = {actual.x, actual.y, actual.z};
        const int32_t* coordinates[3] = {p_.xs, p_.ys, p_.zs};
        const double* table[3];
        for (int a = 0; a < 3; ++a) {
            Ints longest = {0, 0, 0, 0};  // the OR of the magnitudes: its bit length is the longest's
            for (int k = 0; k < kPaddedCandidates; k += 4) {
                Ints d;
                std::memcpy(&d, coordinates[a] + k, sizeof d);
                d = at[a] - d;
                const Ints sign = d >> 31;
                const Ints m = (d ^ sign) - sign;
                const Ints n = (Ints(__builtin_convertvector(2 * m + 1, Floats)) >> 23) - 127;
                std::memcpy(length[a] + k, &n, sizeof n);
                const Ints index = {k, k + 1, k + 2, k + 3};
                longest |= m & Ints((index >= 1) & (index < p_.count));  // candidates 1 .. count - 1
            }
            table[a] = others_[a]->upTo(lengthOf(longest[0] | longest[1] | longest[2] | longest[3]));
        }
        leastFrom[p_.count] = 1e300;
        for (int c = p_.count - 1; c >= 1; --c) {
            residual[c] = table[0][length[0][c]] + table[1][length[1][c]] + table[2][length[2][c]];
            leastFrom[c] = std::min(residual[c], leastFrom[c + 1]);
        }
        residual[0] = this->residual(actual - p_.candidate(0), 0);
        leastFrom[0] = std::min(residual[0], leastFrom[1]);
    }
    // The cost of naming candidate c.
    double choice(int c) const {
        if (known_ <= c) knowUpTo(c);
        return choice_[c];
    }
    // A floor under the cost of naming any candidate from c on: the "no"
    // flags of those before c (every later name pays them too).
    double choiceFloor(int c) const {
        if (!flags_ || c <= 0) return 0;
        if (known_ < c) knowUpTo(c - 1);
        return noBefore_[c - 1];
    }

private:
    void knowUpTo(int c) const {
        for (; known_ <= c; ++known_) {
            const int k = known_;
            if (!flags_) {  // one symbol: no cost grows with c, 0 bounds them all
                choice_[k] = std::log2(symbolTotal_ / symbols_->countOf(uint32_t(k)));
                noBefore_[k] = 0;
                continue;
            }
            const double noSoFar = k == 0 ? 0 : noBefore_[k - 1];
            if (k != flagged_) {
                choice_[k] = 1e300;  // never picked: an equal candidate comes first
                noBefore_[k] = noSoFar;
                continue;
            }
            flagged_ = nextFlagged(p_, k);
            if (flagged_ == p_.count) {  // the last: named by the "no" flags before it
                choice_[k] = noSoFar;
                noBefore_[k] = noSoFar;
            } else {
                const BitModel& flag = flagOf(s_, p_, k);
                choice_[k] = noSoFar + flag.cost(1);
                noBefore_[k] = noSoFar + flag.cost(0);
            }
        }
    }

    CodingState& s_;
    const Predictions& p_;
    const ResidualCosts* axis_[kResidualGroups][3];
    const ResidualCosts* const* others_;  // the models of candidates 1 and on
    bool version2_;
    bool frameNow_;
    bool flags_;
    const AdaptiveFrequencies* symbols_ = nullptr;  // one symbol: its table
    double symbolTotal_ = 0;
    mutable int flagged_ = 0;  // the next candidate, from known_ on, that is not a repeat (p.count: none)
    // Worked out so far: candidates 0 .. known_ - 1; noBefore_[k], the "no"
    // flags of candidates 0 .. k.
    mutable int known_ = 0;
    mutable double choice_[kMaxCandidates];
    mutable double noBefore_[kMaxCandidates];
};

// The encoder's pick among vertices it might code next: the vertex and
// candidate whose residual and choice cost least, and that cost in bits;
// of equal ones the first vertex, then its first candidate (the pick of
// pricing each vertex's candidates in turn, then keeping the first
// cheapest vertex).
constexpr int kMaxPricedTogether = 32;
struct Pick {
    uint32_t candidate = 0;
    double bits = 1e300;
    int vertex = 0;  // which of those priced
};
template <class PointOf>
Pick cheapestPick(const Pricing& price, const Predictions& p, int n, PointOf pointOf) {
    double residual[kMaxPricedTogether][kMaxCandidates];
    double leastFrom[kMaxPricedTogether][kMaxCandidates + 1];  // the least residual of candidates c and on
    for (int i = 0; i < n; ++i) price.residuals(pointOf(i), residual[i], leastFrom[i]);
    // Candidate by candidate over all the vertices, so that each naming
    // cost is worked out once, and only as far as any vertex needs it.
    Pick best;
    for (int c = 0; c < p.count; ++c) {
        const double floor = price.choiceFloor(c);
        bool open = false;
        for (int i = 0; i < n; ++i) {
            // No candidate of vertex i from c on can cost less than this
            // (rounding is monotonic: a sum of larger terms is no smaller);
            // it could still win a tie if i comes before the best's vertex.
            const double least = leastFrom[i][c] + floor;
            if (least > best.bits || (least == best.bits && i >= best.vertex)) continue;
            open = true;
            const double cost = residual[i][c] + price.choice(c);
            if (cost < best.bits || (cost == best.bits && i < best.vertex)) best = {uint32_t(c), cost, i};
        }
        if (!open) break;  // bounds only grow with c, and the best only falls
    }
    return best;
}
Pick bestPrediction(const Pricing& price, const Predictions& p, GridPoint actual) {
    return cheapestPick(price, p, 1, [actual](int) { return actual; });
}

// Each residual group's context per axis. In format 3 the residual from the
// parent (the whole tree edge) takes its contexts from the local spacing
// instead (from its bit length, on the frame's tangent axes and, smaller,
// on the third, the normal when the frame is on): the residuals of the
// previous vertex and the parent are mostly small corrections from other
// candidates and say little about an edge's length (tree geometry -0.5 %;
// offsets 2 and 6 against 1-4 and 4-10: within 0.1 %).
void magnitudeContexts(const CodingState& s, const Predictions& p, uint32_t self, uint32_t parent,
                       int (*contexts)[3]) {
    for (int a = 0; a < 3; ++a) contexts[0][a] = contexts[1][a] = magnitudeContext(s, self, parent, a);
    if (!s.spacingContexts || p.spacing2 == 0) return;
    const int length = bitLength(uint64_t(p.spacing2));
    const auto clamped = [](int c) { return std::max(0, std::min(c, kMagnitudeContexts - 1)); };
    contexts[0][0] = contexts[0][1] = clamped(length - 2);
    contexts[0][2] = clamped(length - 6);
}

// Names candidate `best` (encoder) or reads which was named (decoder).
template <class Io>
uint32_t codeChoice(Io& io, CodingState& s, const Predictions& p, uint32_t best) {
    if (!s.choiceFlags) {
        AdaptiveFrequencies& model = s.predictorChoice[std::min<uint32_t>(s.previousChoice, kChoiceContexts - 1)];
        const uint32_t choice = io.symbol(model, best);
        if (choice >= uint32_t(p.count))
            throw Error(ErrorKind::Corrupt, "corrupt file: a geometry predictor choice is out of range");
        return choice;
    }
    // Each candidate that is not a repeat in turn, a flag for each but the last.
    for (int c = 0;;) {
        const int next = nextFlagged(p, c);
        if (next == p.count || io.bit(flagOf(s, p, c), best == uint32_t(c))) return uint32_t(c);
        c = next;
    }
}

// Codes (or decodes) vertex `self`, a child of `parent`, from the
// predictions p; `actual` is its position when encoding. An encoder that
// has already priced the candidates passes its pick as `chosen` (else the
// pick is made here). Returns the position.
constexpr uint32_t kNotChosen = kNoIndex;
template <class Io>
GridPoint codeChild(Io& io, CodingState& s, uint32_t self, uint32_t parent, const Predictions& p, GridPoint actual,
                    uint32_t chosen = kNotChosen) {
    int contexts[kResidualGroups][3];
    magnitudeContexts(s, p, self, parent, contexts);
    uint32_t best = 0;
    if (Io::kEncoding) best = chosen != kNotChosen ? chosen : bestPrediction(Pricing(s, p, contexts), p, actual).candidate;
    const uint32_t choice = codeChoice(io, s, p, best);
    s.previousChoice = choice;
    const GridPoint base = p.candidate(int(choice));
    const bool inFrame = framed(s.frameNow(), choice);
    s.framedResiduals += inFrame ? 1 : 0;
    GridPoint r = actual - base;
    if (Io::kEncoding && inFrame) r = toFrame(p.frame, r);
    int64_t out[3];
    const int32_t in[3] = {r.x, r.y, r.z};
    const int group = residualGroup(s.version2, choice);
    const bool tangentContexts = inFrame && s.tangentSigns;  // format 7
    const NearPointSides sides = tangentContexts ? nearPointSides(p) : NearPointSides();
    for (int a = 0; a < 3; ++a) {
        const auto signModel = [&](int length) -> BitModel& {
            if (tangentContexts && a < 2)
                return tangentSignModel(s, p, sides, a, length, a == 0 ? 0 : int32_t(out[0]));
            return s.axis[group][a].sign[signContext(s, self, parent, a)];
        };
        const int32_t coded = codeResidual(io, s.axis[group][a], contexts[group][a], signModel, in[a]);
        if (s.signContexts) s.signs[3 * size_t(self) + size_t(a)] = signOf(coded);
        ++s.residualsCoded[group][a][contexts[group][a]];
        s.magnitude[3 * size_t(self) + size_t(a)] = magnitudeOf(coded);
        out[a] = coded;
    }
    // Coded residuals are below 2^23 (kMaxLength bits), so back in the world
    // frame they stay far from overflowing; the decoder checks the grid.
    if (inFrame) p.frame.fromFrame(out);
    const GridPoint at = {int32_t(base.x + out[0]), int32_t(base.y + out[1]), int32_t(base.z + out[2])};
    // Every vertex, whichever candidate named it, tells how its tree edge
    // would have fared in the frame: the choice of candidate 0 itself
    // depends on the frame, so learning only from those would keep a frame
    // that is off from ever being tried (nefertiti-50k: -0.1 % instead of -5 %).
    if (s.framedParent)
        s.frameScore = s.frameScore - s.frameScore / CodingState::kFrameMemory + 256 * frameAdvantage(p.frame, at - p.candidate(0)) +
                       (s.tangentSigns ? CodingState::kFrameCredit : 0);
    return at;
}

template <class Io>
GridPoint codeChild(Io& io, CodingState& s, uint32_t self, uint32_t parent, GridPoint actual) {
    return codeChild(io, s, self, parent, predict(s, self, parent), actual);
}

template <class Io>
uint32_t codeChildCount(Io& io, CodingState& s, uint32_t self, uint32_t count) {
    const uint32_t symbol = io.symbol(s.childCountModel(self), std::min(count, kDirectChildCounts));
    s.childCountOf.push_back(uint8_t(symbol));
    if (symbol < kDirectChildCounts) return symbol;
    // Elias gamma of w >= 1: n - 1 zero bits, a one bit, then the n - 1 bits
    // below the leading one.
    const uint32_t w = Io::kEncoding ? count - kDirectChildCounts + 1 : 0;
    const int n = bitLength(w);
    int zeros = 0;
    while (io.plain(zeros < n - 1 ? 0 : 1, 1) == 0)
        if (++zeros > 31) throw Error(ErrorKind::Corrupt, "corrupt file: a child count in the geometry section is too long");
    const uint64_t decoded = (uint64_t(1) << zeros) | io.plain(w, zeros);
    return uint32_t(std::min<uint64_t>(decoded - 1 + kDirectChildCounts, 0xFFFFFFFFu));
}

}  // namespace

// The side of the cells the coders search for near points: about three
// times the typical distance to the kNearest-th neighbour, as a power of two
// (the search covers at least half a cell around the parent).
int cellBitsFor(double spacing, int bits) { return std::min(bits, bitLength(uint32_t(std::min(3 * spacing, 1e9)))); }
constexpr int kCellBitsWidth = 5;

namespace {

// How many nearest neighbours of each vertex the encoder's tree may take
// as its children (joined both ways): 4 by default (the corpus's geometry
// sections in total: 1,715,078 bytes over 4, 1,710,079 over 5, 1,711,209
// over 6, 1,714,852 over 8, 1,736,935 over 3). The count that codes
// smallest differs from mesh to mesh (the best of the trees and ways for
// each count: turbine 8,877 bytes over 4, 7,165 over 8; genus3
// 9,372 over 4, 8,740 over 2; igea 134,152 over 4, 137,483 over 8; the
// corpus -1.6 % with the best count of the six for each mesh, -1.3 % with
// the best of 4, 8 and 2, -1.0 % of 4 and 8; over 16, with a graph of 16
// nearest, turbine 6,084 and crank 57,602 against 66,154 over 4):
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
    CodingState s(cellBits, kFileFormatVersion, flagChoices, frame);
    s.pos.reserve(n);
    s.parentOf.reserve(n);
    s.magnitude.reserve(3 * n);
    if (s.signContexts) s.signs.reserve(3 * n);
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
    coder.encodeBits(frame ? 1 : 0, 1);  // G, from format 3
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
    CodingState s(cellBits, kFileFormatVersion, flagChoices, frame);  // for the child counts' models
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
// corpus at 12 bits the large meshes where the spanning tree wins (crank,
// octopus) stay under 1.00 from 4/16 on, those where it loses run over
// 1.015 all the way (format 6: igea 1.03, bunny 1.02, horse 1.05; format
// 7: igea and bunny 1.023 to 1.029 from 2/16 to 4/16); a comparison of
// the sections' sizes at the same fraction of the way would compare
// different vertices and could not tell igea from crank. Small meshes are
// left out: they cost little either way, and there the spanning tree can
// win after trailing by 10 % (teapot). The first sixteenth is left out of
// both sums: it is mostly the models learning, and it held a spanning tree
// that wins by half against what it would win later (a regular lattice of
// 20,000 points: 1.83 times the cheapest-first tree's bits over its first
// sixteenth, 1.48 over two, 0.51 at the end; octopus coded with one symbol
// per choice, 1.021 over two, 0.987 at the end).
constexpr size_t kSteps = 16;
constexpr double kAbandonOverRival = 1.015;
constexpr size_t kAbandonFromStep = 4;
constexpr size_t kAbandonFromVertices = 16384;
// Before that, from 2/16 on, a tree more than 1.8 % behind is given up:
// the clear losers are (format 7 at 12 bits, the first trial: igea 1.023
// at 2/16, bunny 1.029, nefertiti-50k 1.033, venus 1.045, horse 1.056,
// feline 1.062), the winners are not (crank 1.011, octopus 1.008,
// falconstatue 1.012); every corpus file is the same as with format 6's
// 3 % (igea was 1.038 then; at 3 %, format 7 would code igea's rival to
// 4/16: 2.7 % more instructions to encode it).
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
    CodingState s(cellBits, kFileFormatVersion, flagChoices, frame);
    s.pos.reserve(n);
    s.parentOf.reserve(n);
    s.magnitude.reserve(3 * n);
    if (s.signContexts) s.signs.reserve(3 * n);
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
// encoder.cpp).
constexpr double kRegularCountsMargin = 0.03;
// Above this many vertices FourUnlessRegular is Four: the search for 16
// nearest, the wider graphs and the pick bits would add to the encoder's
// peak memory, measured there (igea x4, docs/speed.md), and the vertex
// section is then coded beside the early connectivity (encoder.cpp).
constexpr size_t kRegularUpToVertices = size_t(1) << 18;

// Two trees, each with the choice coded both ways, the smallest section
// kept (the decoder reads any the same way): the cheapest-first tree wins
// on most meshes (fandisk 13.26 -> 10.30 bpv, bunny 11.44 -> 11.32), the
// minimum spanning tree with its children ordered straight on still wins on
// some regular CAD meshes (blade 3.67 against 4.20, tray-bottom 8.50
// against 9.56). Flags win on most meshes (bunny 11.31 -> 10.90 bpv); one
// symbol on coarse grids, where candidates pile up (refine's coarse tree:
// dinosaur-24k 14.05 -> 13.67), and on some artist meshes (hero 21.29 ->
// 20.91).
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
    // cheapest-first tree grows here (igea: 7 % of its encoding); it is
    // the same forest.
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
        // Scans log 11 to 15 words a vertex (igea 12.9, horse 13.9, igea x4
        // 11.3): reserved, the log is not grown by doubling, which held up
        // to three times its size while it moved.
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

std::vector<int32_t> decodeGeometryTree(const uint8_t* data, size_t size, uint64_t vertexCount, int bits, int formatVersion) {
    // Every vertex but a root codes at least four adaptive decisions (three
    // residual zero flags and a child count; a predictor choice too, unless
    // every candidate repeats the parent). No binary model gives a decision
    // a probability above 4095/4096, and a table of k symbols none above
    // 1 - (k-1)/65568, so a vertex costs at least ~0.0012 bits: at most
    // ~6500 vertices per byte. A count far beyond that is refused before
    // anything is allocated.
    constexpr uint64_t kMaxVerticesPerByte = 8192;
    if (vertexCount > (uint64_t(size) + 8) * kMaxVerticesPerByte)
        throw Error(ErrorKind::Corrupt, "corrupt file: " + std::to_string(vertexCount) + " vertices cannot fit in a geometry section of " +
                    std::to_string(size) + " bytes");
    const size_t n = size_t(vertexCount);
    const int32_t top = gridMax(bits);
    RangeDecoder coder(data, size);
    Reader io{coder};
    const int cellBits = int(coder.decodeBits(kCellBitsWidth));
    const bool flagChoices = formatVersion >= 2 && coder.decodeBits(1) == 1;
    const bool frame = formatVersion >= 3 && coder.decodeBits(1) == 1;
    if (cellBits > bits) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section's cell size is larger than the grid");
    // The count is only a claim until the stream delivers the vertices:
    // tables grow as they are decoded, so a short or garbage section fails
    // before memory is committed to it.
    CodingState s(cellBits, formatVersion, flagChoices, frame);
    // Room for as many vertices as the section holds at four bits each (the
    // corpus takes 5.8 to 33 bits), up to 4M: tables sized once are not
    // copied as they grow, and touch half the pages. A corrupt count can so
    // reserve (not touch) about 200 MB at most; past that, tables grow as
    // vertices are decoded.
    constexpr size_t kMostReserved = size_t(1) << 22;
    const size_t initial = std::min({n, std::max<size_t>(size_t(1) << 16, 2 * size), kMostReserved});
    s.pos.reserve(initial);
    s.parentOf.reserve(initial);
    s.magnitude.reserve(3 * initial);
    if (s.signContexts) s.signs.reserve(3 * initial);
    s.childCountOf.reserve(initial);
    s.cells.reserve(initial);
    TreeWalk walk;
    uint64_t promised = 0;  // children announced but not yet decoded
    for (uint32_t self = 0; self < n; ++self) {
        const uint32_t parent = walk.enter();
        s.begin(parent);
        GridPoint at;
        if (parent == kNoVertex) {
            if (promised != 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry tree is inconsistent");
            const int32_t x = int32_t(coder.decodeWideBits(bits));  // in order: x, y, z
            const int32_t y = int32_t(coder.decodeWideBits(bits));
            const int32_t z = int32_t(coder.decodeWideBits(bits));
            at = {x, y, z};
        } else {
            --promised;
            at = codeChild(io, s, self, parent, GridPoint{});
            if (at.x < 0 || at.y < 0 || at.z < 0 || at.x > top || at.y > top || at.z > top)
                throw Error(ErrorKind::Corrupt, "corrupt file: geometry vertex " + std::to_string(self) + " falls outside the grid");
        }
        s.place(self, at);
        const uint32_t childCount = codeChildCount(io, s, self, 0);
        promised += childCount;
        if (promised > n - 1 - self)
            throw Error(ErrorKind::Corrupt, "corrupt file: geometry vertex " + std::to_string(self) + " announces more children than remain");
        walk.expect(self, childCount);
        if (coder.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section ends early");
    }
    if (promised != 0) throw Error(ErrorKind::Corrupt, "corrupt file: the geometry section ends inside the tree");
    std::vector<int32_t> grid(3 * n);
    for (size_t v = 0; v < n; ++v) {
        grid[3 * v] = s.pos[v].x;
        grid[3 * v + 1] = s.pos[v].y;
        grid[3 * v + 2] = s.pos[v].z;
    }
    return grid;
}

}  // namespace drm
