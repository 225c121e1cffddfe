// The bit models of the spanning-tree geometry coder's residuals (one set
// per axis) and the one function through which encoder and decoder code a
// residual with them (BitModel, Writer and Reader: bit_model.h).
#ifndef DRM_RESIDUAL_MODEL_H
#define DRM_RESIDUAL_MODEL_H

#include <algorithm>
#include <cstdint>

#include "entropy/bit_model.h"
#include "common.h"

namespace drm {

inline uint32_t magnitudeOf(int32_t v) { return uint32_t(v < 0 ? -int64_t(v) : v); }
// bitLength(magnitudeOf(v)) without a branch: 2m + 1 is never zero and has
// one bit more than m.
inline int lengthOf(int32_t v) { return 63 - __builtin_clzll(2 * uint64_t(magnitudeOf(v)) + 1); }

constexpr int kMagnitudeContexts = 8;
constexpr int kMaxLength = 23;      // bit lengths of residuals of 21-bit coordinates
constexpr int kAdaptiveLowBits = 2; // bits below the leading one with a model
// A residual's sign in a context of two signs already known (each none, +
// or -): the parent's on the same axis and this vertex's on the axis
// before. The topological coder uses model 0 alone.
constexpr int kSignContexts = 9;

// The models of one axis' residuals.
struct AxisModels {
    BitModel zero[kMagnitudeContexts];
    BitModel longer[kMagnitudeContexts][kMaxLength];  // unary bit length: "longer than k"
    BitModel sign[kSignContexts];
    BitModel low[kMaxLength + 1][kAdaptiveLowBits];  // by bit length, 1..kMaxLength

    // Every model agile (BitModel::agile), as the spanning-tree vertex
    // coder's are.
    void makeAgile() {
        for (BitModel& m : zero) m = BitModel::agile();
        for (auto& byContext : longer)
            for (BitModel& m : byContext) m = BitModel::agile();
        for (BitModel& m : sign) m = BitModel::agile();
        for (auto& byLength : low)
            for (BitModel& m : byLength) m = BitModel::agile();
    }
};

// A residual: zero or not, the bit length n >= 1 in unary, the sign (in
// the model signModel(n) gives: the sign may depend on the length, known
// by then), then the bits below the leading one (the first two adaptive,
// per n).
template <class Io, class SignModel>
int32_t codeResidual(Io& io, AxisModels& m, int context, SignModel signModel, int32_t r) {
    const uint32_t magnitude = magnitudeOf(r);
    if (io.bit(m.zero[context], magnitude == 0)) return 0;
    const int n = bitLength(magnitude);
    int length = 1;
    while (length < kMaxLength && io.bit(m.longer[context][length], n > length)) ++length;
    const bool negative = io.bit(signModel(length), r < 0) != 0;
    uint32_t value = 1;
    for (int k = 0; k < std::min(length - 1, kAdaptiveLowBits); ++k)
        value = (value << 1) | uint32_t(io.bit(m.low[length][k], (magnitude >> (length - 2 - k)) & 1));
    const int rest = length - 1 - std::min(length - 1, kAdaptiveLowBits);
    value = (value << rest) | io.plain(magnitude, rest);
    return negative ? -int32_t(value) : int32_t(value);
}

// The encoder's estimate of codeResidual's cost, in bits, by bit length:
// an encoder prices many residuals under the same models (each candidate
// prediction of each possible next vertex), and the cost depends on the
// length alone (an approximation: the sign and the bits below the leading
// one count one bit each, though the sign and the first two of those bits
// are coded adaptively). Lengths are priced as they are first asked for,
// shortest first (residuals rarely reach half of kMaxLength); the models
// must not change while the prices are in use.
class ResidualCosts {
public:
    ResidualCosts() = default;
    ResidualCosts(const AxisModels& m, int context) : models_(&m), context_(context) {}
    double operator()(int32_t r) const {
        const int n = bitLength(magnitudeOf(r));
        if (n > priced_) priceUpTo(n);
        return ofLength_[n];
    }
    // The prices of lengths 0 .. n, by length (lengthOf): for a caller that
    // knows the longest residual it will price, each price is then one load.
    const double* upTo(int n) const {
        if (n > priced_) priceUpTo(n);
        return ofLength_;
    }
    // The models changed: every price is to be worked out again.
    void forget() { priced_ = -1; }

private:
    void priceUpTo(int n) const {
        if (priced_ < 0) {
            ofLength_[0] = models_->zero[context_].cost(1);
            nonZero_ = models_->zero[context_].cost(0) + 1.0;  // and the sign, as one bit
            longer_ = 0;
            priced_ = 0;
        }
        for (int k = priced_ + 1; k <= n; ++k) {
            ofLength_[k] = nonZero_ + (k - 1) + longer_ + (k < kMaxLength ? models_->longer[context_][k].cost(0) : 0.0);
            if (k < kMaxLength) longer_ += models_->longer[context_][k].cost(1);  // "longer than k"
        }
        priced_ = n;
    }

    const AxisModels* models_ = nullptr;
    int context_ = 0;
    mutable int priced_ = -1;  // lengths 0 .. priced_ have their price
    mutable double nonZero_ = 0, longer_ = 0;
    mutable double ofLength_[kMaxLength + 1] = {};
};

}  // namespace drm

#endif  // DRM_RESIDUAL_MODEL_H
