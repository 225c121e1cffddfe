// A byte-oriented range coder: a 32-bit range over a 64-bit low register,
// with carries resolved by holding back the last byte and any run of 0xFF
// bytes until it is known whether a carry reaches them.
//
// Frequencies are integers and the arithmetic is integer only, so encoder and
// decoder agree bit for bit on every machine.
#ifndef DRM_RANGE_CODER_H
#define DRM_RANGE_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drm {

// Largest totalFreq the coders accept. The range never drops below 2^24, so
// each of the up to 2^16 slots keeps at least 2^8 range values.
constexpr uint32_t kRangeCoderMaxTotal = uint32_t(1) << 16;
// The range is renormalized to stay at or above this.
constexpr uint32_t kRangeCoderTop = uint32_t(1) << 24;

class RangeEncoder {
public:
    // Codes the symbol that owns [cumFreq, cumFreq + freq) of [0, totalFreq).
    // Requires 0 < freq, cumFreq + freq <= totalFreq <= kRangeCoderMaxTotal.
    void encode(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq);
    // Codes the low `count` bits of value (count in 0..16), each bit costing
    // exactly one bit; higher bits of value are ignored.
    void encodeBits(uint32_t value, int count);
    // Codes the low `count` bits of value (count in 0..64) as plain bits, in
    // chunks of at most 16, most significant chunk first. Decode with
    // decodeWideBits(count): the chunking must match exactly, since in a
    // range coder one 4-bit value and four single bits are different codes.
    void encodeWideBits(uint64_t value, int count);
    // Flushes the coder and hands over the bytes. The encoder is spent.
    // The stream omits its last three bytes, which are always zero: the
    // decoder supplies them itself.
    std::vector<uint8_t> finish();
    // A floor under the size finish() will hand over: the bytes written and
    // those held back (the cache and its run of 0xFF bytes), which every
    // later step keeps or adds to. An encoder comparing ways of coding can
    // stop one once this passes the best so far.
    size_t bytesAtLeast() const { return out_.size() + size_t(pendingFF_) + (cacheIsLeadingZero_ ? 0 : 1); }
    // The information coded so far, in bits, to a fraction of a bit: the
    // bytes shifted out and what the range has narrowed by since. The
    // difference over a stretch of symbols is what they cost (for encoders
    // comparing ways of coding the same symbols; not for the format).
    double bitsSoFar() const;

private:
    void shiftLow();
    void emit(uint8_t byte);

    uint64_t low_ = 0;              // bit 32 is a pending carry
    uint32_t range_ = 0xFFFFFFFFu;
    uint8_t cache_ = 0;             // last settled-but-unwritten byte
    uint64_t pendingFF_ = 0;        // 0xFF bytes after cache_ awaiting a carry
    bool cacheIsLeadingZero_ = true;  // cache_ is the value's integer part, never written
    std::vector<uint8_t> out_;
};

// The calls an encoder would make on a RangeEncoder, kept in order to be
// made later (replayInto): an encoder that must decide what its stream
// holds (the geometry tree's shape) before some of it can be written codes
// the rest into a log as it goes, instead of modelling it a second time.
// Two bytes a binary decision of a 12-bit model (the common call), eight
// for any other symbol; replaying makes exactly the same calls, so the
// bytes are those of coding directly.
class CodingLog {
public:
    void encode(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq);
    void encodeBits(uint32_t value, int count) { encodeWideBits(value, count); }  // count <= 16: the same calls
    void encodeWideBits(uint64_t value, int count);
    // Closes a unit: replayInto stops at the end of each.
    void endUnit() { words_.push_back(kEndOfUnit); }
    // Makes the calls logged from `at` up to the end of the unit there, and
    // returns where the next unit begins.
    size_t replayInto(RangeEncoder& coder, size_t at) const;
    size_t size() const { return words_.size(); }
    void reserve(size_t words) { words_.reserve(words); }

private:
    // Each call's first word says what it is by its top bits: 1 a binary
    // decision over 4096 (cum 0 or 4096 - freq, and freq below 4096), 01
    // plain bits (the count; the value follows in 16-bit words, most
    // significant first), 001 any symbol (bits 16 of cum, freq and total;
    // their low 16 bits follow), 0 the end of a unit.
    static constexpr uint16_t kBinary = 0x8000, kPlain = 0x4000, kSymbol = 0x2000, kEndOfUnit = 0;
    std::vector<uint16_t> words_;
};

class RangeDecoder {
public:
    // Reading past the end of data yields zero bytes (counted, see
    // bytesPastEnd), so any input is safe to decode.
    RangeDecoder(const uint8_t* data, size_t size);

    // The slot the next symbol falls in, in [0, totalFreq); corrupt input
    // is clamped into range. Must be followed by consume() of the symbol
    // that owns that slot.
    uint32_t decodeFreq(uint32_t totalFreq);
    void consume(uint32_t cumFreq, uint32_t freq, uint32_t totalFreq);
    // A binary decision over 2^totalBits slots (totalBits <= 16), the top
    // `ofOne` of them (0 < ofOne < 2^totalBits) meaning 1: returns it,
    // consumed. The same as decodeFreq and consume of the symbol owning
    // the slot, without their divisions (slot >= t exactly when code >=
    // t * step) or calls: adaptive bits are the decoders' commonest symbol.
    int decodeBinary(uint32_t ofOne, int totalBits) {
        const uint32_t step = range_ >> totalBits;
        const uint32_t ofZero = step * ((uint32_t(1) << totalBits) - ofOne);
        int bit = 0;
        if (code_ >= ofZero) {  // the second symbol, the last: it takes the remainder
            code_ -= ofZero;
            range_ -= ofZero;
            bit = 1;
        } else {
            range_ = ofZero;
        }
        normalize();
        return bit;
    }
    // Inverse of RangeEncoder::encodeBits.
    uint32_t decodeBits(int count);
    // Inverse of RangeEncoder::encodeWideBits.
    uint64_t decodeWideBits(int count);

    // Zero bytes invented past the end of the data, not counting the three
    // bytes finish() leaves off. After the last symbol of an intact stream
    // this is 0; more means the stream was truncated (or is not a stream).
    size_t bytesPastEnd() const;

private:
    uint8_t nextByte() {
        const size_t at = pos_++;
        return at < size_ ? data_[at] : 0;
    }
    void normalize() {
        while (range_ < kRangeCoderTop) {
            range_ <<= 8;
            code_ = (code_ << 8) | nextByte();
        }
    }

    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;   // bytes read, including invented ones
    uint32_t range_ = 0xFFFFFFFFu;
    uint32_t code_ = 0;  // offset of the coded value above the interval's low end
};

}  // namespace drm

#endif  // DRM_RANGE_CODER_H
