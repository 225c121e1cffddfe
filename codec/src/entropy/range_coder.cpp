// The coded value is a fraction in [0, 1) written in base 256. The encoder
// narrows [low, low + range) symbol by symbol; whenever range falls below
// 2^24 the top byte of low is final except for a possible carry, so it is
// shifted out into a one-byte cache (plus a count of 0xFF bytes behind it,
// which a carry would turn into 0x00) and written once no carry can reach it.
#include "entropy/range_coder.h"

#include <cassert>
#include <cmath>
#include <utility>

namespace drm {

namespace {

constexpr uint32_t kTop = kRangeCoderTop;
constexpr uint64_t kCarry = uint64_t(1) << 32;
// finish() picks a final value whose low three bytes are zero and leaves
// them off; the decoder reads them as the zeros it invents past the end.
constexpr size_t kImpliedTailBytes = 3;

}  // namespace

void RangeEncoder::encode(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq) {
    assert(freq > 0 && totalFreq <= kRangeCoderMaxTotal && cumFreq + freq <= totalFreq);
    const uint32_t step = range_ / totalFreq;
    low_ += uint64_t(step) * cumFreq;
    // The last symbol also takes the remainder range_ % totalFreq, which
    // would otherwise be wasted.
    range_ = cumFreq + freq < totalFreq ? step * freq : range_ - step * cumFreq;
    while (range_ < kTop) {
        range_ <<= 8;
        shiftLow();
    }
}

void RangeEncoder::encodeBits(uint32_t value, int count) {
    assert(count >= 0 && count <= 16);
    if (count <= 0) return;
    const uint32_t total = uint32_t(1) << count;
    encode(value & (total - 1), 1, total);
}

double RangeEncoder::bitsSoFar() const { return 8.0 * double(bytesAtLeast()) + 32.0 - std::log2(double(range_)); }

void RangeEncoder::shiftLow() {
    // A top byte below 0xFF cannot be reached by a later carry (the carry
    // stops at it), and a set carry bit settles everything held back.
    if (low_ < 0xFF000000u || low_ >= kCarry) {
        const uint8_t carry = uint8_t(low_ >> 32);
        // The leading cache is the value's integer part: always 0, and
        // never carried into because the interval stays inside [0, 1).
        if (!cacheIsLeadingZero_) emit(uint8_t(cache_ + carry));
        for (; pendingFF_ > 0; --pendingFF_) emit(uint8_t(0xFF + carry));
        cache_ = uint8_t(low_ >> 24);
        cacheIsLeadingZero_ = false;
    } else {
        ++pendingFF_;
    }
    low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::emit(uint8_t byte) { out_.push_back(byte); }

std::vector<uint8_t> RangeEncoder::finish() {
    // Any value in [low, low + range) identifies the stream. Since
    // range >= 2^24, rounding low up to a multiple of 2^24 stays inside and
    // leaves only one byte (plus carry) that is not zero.
    low_ = (low_ + (kTop - 1)) & ~uint64_t(kTop - 1);
    shiftLow();  // moves that byte into the cache
    shiftLow();  // low is now 0, so this writes the cache and any 0xFF run
    range_ = 0;  // spent
    return std::move(out_);
}

RangeDecoder::RangeDecoder(const uint8_t* data, size_t size) : data_(data), size_(size) {
    for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | nextByte();
}

uint32_t RangeDecoder::decodeFreq(uint32_t totalFreq) {
    assert(totalFreq > 0 && totalFreq <= kRangeCoderMaxTotal);
    const uint32_t slot = code_ / (range_ / totalFreq);
    // Values in the last symbol's remainder (or from corrupt input) land
    // past the end; they belong to the last slot.
    return slot < totalFreq ? slot : totalFreq - 1;
}

void RangeDecoder::consume(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq) {
    assert(freq > 0 && totalFreq <= kRangeCoderMaxTotal && cumFreq + freq <= totalFreq);
    const uint32_t step = range_ / totalFreq;
    code_ -= step * cumFreq;
    range_ = cumFreq + freq < totalFreq ? step * freq : range_ - step * cumFreq;
    normalize();
}

uint32_t RangeDecoder::decodeBits(int count) {
    assert(count >= 0 && count <= 16);
    if (count <= 0) return 0;
    const uint32_t total = uint32_t(1) << count;
    const uint32_t value = decodeFreq(total);
    consume(value, 1, total);
    return value;
}

size_t RangeDecoder::bytesPastEnd() const {
    const size_t invented = pos_ > size_ ? pos_ - size_ : 0;
    return invented > kImpliedTailBytes ? invented - kImpliedTailBytes : 0;
}

void RangeEncoder::encodeWideBits(uint64_t value, int count) {
    while (count > 0) {
        const int chunk = count < 16 ? count : 16;
        count -= chunk;
        encodeBits(uint32_t(value >> count), chunk);
    }
}

uint64_t RangeDecoder::decodeWideBits(int count) {
    uint64_t value = 0;
    while (count > 0) {
        const int chunk = count < 16 ? count : 16;
        count -= chunk;
        value = (value << chunk) | decodeBits(chunk);
    }
    return value;
}

void CodingLog::encode(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq) {
    assert(freq > 0 && totalFreq <= kRangeCoderMaxTotal && cumFreq + freq <= totalFreq);
    if (totalFreq == 4096 && freq < 4096 && (cumFreq == 0 || cumFreq + freq == totalFreq)) {
        words_.push_back(uint16_t(kBinary | (cumFreq == 0 ? 0 : 0x1000) | freq));
        return;
    }
    words_.push_back(uint16_t(kSymbol | (cumFreq >> 16) | (freq >> 16) << 1 | (totalFreq >> 16) << 2));
    for (uint32_t v : {cumFreq, freq, totalFreq}) words_.push_back(uint16_t(v));
}

void CodingLog::encodeWideBits(uint64_t value, int count) {
    assert(count >= 0 && count <= 64);
    if (count <= 0) return;
    words_.push_back(uint16_t(kPlain | count));
    for (int shift = (count - 1) / 16 * 16; shift >= 0; shift -= 16) words_.push_back(uint16_t(value >> shift));
}

size_t CodingLog::replayInto(RangeEncoder& coder, size_t at) const {
    while (at < words_.size()) {
        const uint16_t word = words_[at++];
        if (word & kBinary) {
            const uint32_t freq = word & 0x0FFFu;
            coder.encode(word & 0x1000 ? 4096 - freq : 0, freq, 4096);
        } else if (word & kPlain) {
            const int count = word & 0x7F;
            uint64_t value = 0;
            for (int chunks = (count + 15) / 16; chunks > 0; --chunks) value = value << 16 | words_[at++];
            coder.encodeWideBits(value, count);
        } else if (word & kSymbol) {
            const uint32_t cum = uint32_t(word & 1) << 16 | words_[at];
            const uint32_t freq = uint32_t(word >> 1 & 1) << 16 | words_[at + 1];
            const uint32_t total = uint32_t(word >> 2 & 1) << 16 | words_[at + 2];
            at += 3;
            coder.encode(cum, freq, total);
        } else {
            break;  // kEndOfUnit
        }
    }
    return at;
}

}  // namespace drm
