// An adaptive binary model for the range coder, and the Writer / Reader
// pair through which encoder and decoder run the same coding functions.
// Shared by the geometry coders and the attribute coders.
#ifndef DRM_BIT_MODEL_H
#define DRM_BIT_MODEL_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"
#include "entropy/rank_coder.h"

namespace drm {

// An adaptive binary model: the probability of a 1 in 1/4096ths, mixed
// from a fast and a slow estimate (the fast one follows local changes, the
// slow one holds the long-run rate). Integer arithmetic only.
class BitModel {
public:
    BitModel() = default;
    // Starts with P(1) = ofOne65536 / 65536 (the default is 1/2).
    explicit BitModel(uint32_t ofOne65536) : fast_(ofOne65536), slow_(ofOne65536) {}
    // A model that learns its first bits faster: each estimate is the plain
    // average of what it has seen (rate 1/2, 1/3, ...) until that rate
    // falls to its own fixed one. Small inputs, whose models see few bits,
    // pay much less for learning.
    static BitModel agile(uint32_t ofOne65536 = 32768) {
        BitModel m(ofOne65536);
        m.seen_ = 0;
        return m;
    }
    // Coder: a RangeEncoder or a CodingLog.
    template <class Coder>
    void encode(Coder& coder, int bit) {
        const uint32_t p1 = probabilityOfOne();
        if (bit) coder.encode(kOne - p1, p1, kOne);
        else coder.encode(0, kOne - p1, kOne);
        update(bit);
    }
    int decode(RangeDecoder& coder) {
        const int bit = coder.decodeBinary(probabilityOfOne(), kOneBits);  // as encode() codes it
        update(bit);
        return bit;
    }

    // Learns `bit` without coding it.
    void observe(int bit) { update(bit); }

    // The encoder's estimate of the cost of coding `bit`, in bits.
    double cost(int bit) const {
        const uint32_t p1 = probabilityOfOne();
        return costTable()[bit ? p1 : kOne - p1];
    }

private:
    static const double* costTable() {
        static const std::vector<double> table = [] {
            std::vector<double> t(kOne + 1, 0.0);
            for (uint32_t i = 1; i <= kOne; ++i) t[i] = -std::log2(double(i) / kOne);
            return t;
        }();
        return table.data();
    }
    static constexpr int kOneBits = 12;
    static constexpr uint32_t kOne = 1u << kOneBits;
    static constexpr int kFast = 4, kSlow = 7;
    uint32_t probabilityOfOne() const {
        const uint32_t p = (fast_ + slow_) >> 5;  // two 16-bit estimates to 12 bits
        return std::min(std::max(p, 1u), kOne - 1);
    }
    void update(int bit) {
        if (seen_ < kSlowAfter) {
            ++seen_;
            const int32_t target = bit ? 65536 : 0, divisor = int32_t(seen_) + 1;
            fast_ = uint32_t(int32_t(fast_) + (target - int32_t(fast_)) / std::min(divisor, int32_t(1) << kFast));
            slow_ = uint32_t(int32_t(slow_) + (target - int32_t(slow_)) / divisor);
            return;
        }
        if (bit) {
            fast_ += (65536 - fast_) >> kFast;
            slow_ += (65536 - slow_) >> kSlow;
        } else {
            fast_ -= fast_ >> kFast;
            slow_ -= slow_ >> kSlow;
        }
    }
    uint32_t fast_ = 32768, slow_ = 32768;
    // Bits seen while agile; kSlowAfter (and so from the start, unless
    // agile()) once the rates are the fixed ones.
    static constexpr uint32_t kSlowAfter = (1u << kSlow) - 1;
    uint32_t seen_ = kSlowAfter;
};

// Encoder and decoder run the same coding functions through one of these:
// the writer codes the value it is given and returns it, the reader ignores
// it and returns what it decodes. So both sides take every decision in the
// same code.
// A CodingLog in place of the RangeEncoder keeps the calls to make later.
template <class Coder>
struct BasicWriter {
    Coder& coder;
    static constexpr bool kEncoding = true;
    int bit(BitModel& m, int b) { m.encode(coder, b); return b; }
    uint32_t plain(uint32_t v, int count) { coder.encodeWideBits(v, count); return v & uint32_t((uint64_t(1) << count) - 1); }
    uint64_t wide(uint64_t v, int count) { coder.encodeWideBits(v, count); return count >= 64 ? v : v & ((uint64_t(1) << count) - 1); }
    uint32_t symbol(AdaptiveFrequencies& m, uint32_t s) { m.encode(coder, s); return s; }
};
using Writer = BasicWriter<RangeEncoder>;
using LogWriter = BasicWriter<CodingLog>;
struct Reader {
    RangeDecoder& coder;
    static constexpr bool kEncoding = false;
    int bit(BitModel& m, int) { return m.decode(coder); }
    uint32_t plain(uint32_t, int count) { return uint32_t(coder.decodeWideBits(count)); }
    uint64_t wide(uint64_t, int count) { return coder.decodeWideBits(count); }
    uint32_t symbol(AdaptiveFrequencies& m, uint32_t) { return m.decode(coder); }
};

}  // namespace drm

#endif  // DRM_BIT_MODEL_H
