// The functions through which the spanning-tree coder's encoder writes and
// its decoder reads one vertex (its candidate choice, residual and child
// count): templates over the Writer / Reader pair of bit_model.h, so that
// both run the same code.
#ifndef DRM_TREE_CODING_H
#define DRM_TREE_CODING_H

#include <algorithm>
#include <cstdint>

#include "geometry/tree/tree_model.h"
#include "geometry/tree/tree_pricing.h"

namespace drm {
namespace tree_coding {

// Each residual group's context per axis. The residual from the parent
// (the whole tree edge) takes its contexts from the local spacing instead
// when there is one (from its bit length, on the frame's tangent axes and,
// smaller, on the third, the normal when the frame is on): the residuals
// of the previous vertex and the parent are mostly small corrections from
// other candidates and say little about an edge's length (docs/tuning.md).
inline void magnitudeContexts(const CodingState& s, const Predictions& p, uint32_t self, uint32_t parent,
                       int (*contexts)[3]) {
    for (int a = 0; a < 3; ++a) contexts[0][a] = contexts[1][a] = magnitudeContext(s, self, parent, a);
    if (p.spacing2 == 0) return;
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
    const int group = residualGroup(choice);
    const bool tangentContexts = inFrame && s.tangentSigns;  // the tangent sign models
    const NearPointSides sides = tangentContexts ? nearPointSides(p) : NearPointSides();
    for (int a = 0; a < 3; ++a) {
        const auto signModel = [&](int length) -> BitModel& {
            if (tangentContexts && a < 2)
                return tangentSignModel(s, p, sides, a, length, a == 0 ? 0 : int32_t(out[0]));
            return s.axis[group][a].sign[signContext(s, self, parent, a)];
        };
        const int32_t coded = codeResidual(io, s.axis[group][a], contexts[group][a], signModel, in[a]);
        s.signs[3 * size_t(self) + size_t(a)] = signOf(coded);
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
    // that is off from ever being tried (a scan such as nefertiti-50k would
    // then lose nearly all the frame's gain).
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

}  // namespace tree_coding
}  // namespace drm

#endif  // DRM_TREE_CODING_H
