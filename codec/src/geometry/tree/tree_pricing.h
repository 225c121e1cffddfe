// The encoder's price of coding a vertex from each of its candidates under
// the current models, and the cheapest pick among several vertices.
// Encoder only: the choice is transmitted, the decoder never prices.
#ifndef DRM_TREE_PRICING_H
#define DRM_TREE_PRICING_H

#include <cstdint>

#include "geometry/tree/tree_model.h"

namespace drm {
namespace tree_coding {

// What coding the next vertex from each candidate costs under the current
// models, in bits: the residual per axis by its bit length, and naming the
// candidate. Built once per step of the encoder, which then prices the
// candidates of every vertex it might code next. (Floating point is fine
// here: the choice is transmitted, the decoder never repeats this.)
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
        : s_(s), p_(p), frameNow_(s.frameNow()), flags_(s.choiceFlags) {
        for (int g = 0; g < kResidualGroups; ++g)
            for (int a = 0; a < 3; ++a) axis_[g][a] = &s.residualCosts(g, a, contexts[g][a]);
        others_ = axis_[residualGroup(1)];
        if (!flags_) {
            symbols_ = &s.predictorChoice[std::min<uint32_t>(s.previousChoice, kChoiceContexts - 1)];
            symbolTotal_ = symbols_->totalCount();
        }
    }
    double residual(GridPoint r, uint32_t c) const {
        const bool inFrame = framed(frameNow_, c);
        const ResidualCosts* const* a = axis_[residualGroup(c)];
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
inline Pick bestPrediction(const Pricing& price, const Predictions& p, GridPoint actual) {
    return cheapestPick(price, p, 1, [actual](int) { return actual; });
}

}  // namespace tree_coding
}  // namespace drm

#endif  // DRM_TREE_PRICING_H
