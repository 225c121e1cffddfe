#include "mesh/repair_section.h"

#include <algorithm>

#include <string>

#include "common.h"
#include "drmcodec/drmcodec.h"
#include "entropy/rank_coder.h"

namespace drm {
namespace {

// Bits for an index below count: at least one, so that every index costs
// a bit and a count times the width bounds the bytes it needs.
int indexBits(uint64_t count) {
    return count <= 2 ? 1 : std::min(32, bitLength(count - 1));
}

// Elias gamma code of x >= 1 in plain bits: as many zeros as x has bits
// after its leading one, a one, then those bits.
void putGamma(RangeEncoder& coder, uint64_t x) {
    const int n = std::max(0, bitLength(x) - 1);
    for (int i = 0; i < n; ++i) coder.encodeBits(0, 1);
    coder.encodeBits(1, 1);
    coder.encodeWideBits(x, n);
}

uint64_t getGamma(RangeDecoder& coder) {
    int n = 0;
    while (coder.decodeBits(1) == 0)
        if (++n > 33) throw Error(ErrorKind::Corrupt, "corrupt file: a vertex copy in the repairs section is out of range");
    return (uint64_t(1) << n) | coder.decodeWideBits(n);
}

AdaptiveFrequencies flipModel() { return AdaptiveFrequencies(std::vector<uint16_t>{1, 1}); }

std::string tooMany(uint64_t count, const char* what, size_t size) {
    return "corrupt file: the repairs section claims " + std::to_string(count) + " " + what + ", more than its " +
           std::to_string(size) + " bytes can hold";
}

}  // namespace

std::vector<uint8_t> encodeRepairs(const Repairs& repairs, uint64_t vertexCount) {
    const int width = indexBits(vertexCount);
    RangeEncoder coder;
    uint32_t previous = 0;
    for (uint32_t v : repairs.copyOf) {
        putGamma(coder, uint64_t(v - previous) + 1);
        previous = v;
    }
    coder.encodeWideBits(repairs.looseCount(), 32);
    for (uint32_t v : repairs.looseTriangles) coder.encodeWideBits(v, width);
    coder.encodeWideBits(repairs.duplicateOf.size(), 32);

    bool anyFlip = false;
    for (uint8_t f : repairs.flipped) anyFlip |= f != 0;
    coder.encodeBits(anyFlip ? 1 : 0, 1);
    if (anyFlip) {
        AdaptiveFrequencies model = flipModel();
        for (uint8_t f : repairs.flipped) model.encode(coder, f ? 1 : 0);
    }
    const int positionWidth = indexBits(repairs.flipped.size());
    for (size_t i = 0; i < repairs.duplicateOf.size(); ++i) {
        coder.encodeWideBits(repairs.duplicateOf[i], positionWidth);
        coder.encodeBits(repairs.duplicateReversed[i], 1);
    }
    return coder.finish();
}

RepairReader::RepairReader(const uint8_t* data, size_t size, uint64_t vertexCount, uint64_t copies,
                           uint64_t faceCount)
    : coder_(data, size), size_(size), bitsLeft_(8 * (uint64_t(size) + 3)) {  // finish() leaves off 3 zero bytes
    if (copies > bitsLeft_) throw Error(ErrorKind::Corrupt, tooMany(copies, "vertex copies", size));
    bitsLeft_ -= copies;
    repairs_.copyOf.resize(size_t(copies));
    uint64_t previous = 0;
    for (uint32_t& v : repairs_.copyOf) {
        const uint64_t value = previous + getGamma(coder_) - 1;
        if (value >= vertexCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section copies vertex " + std::to_string(value) + " of " +
                        std::to_string(vertexCount));
        if (coder_.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section ends early");
        v = uint32_t(value);
        previous = value;
    }

    const int width = indexBits(vertexCount);
    const uint64_t loose = coder_.decodeWideBits(32);
    if (loose > faceCount)
        throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section claims " + std::to_string(loose) +
                    " faces repeating a vertex, more than the header's " + std::to_string(faceCount) + " faces");
    if (3 * loose * uint64_t(width) > bitsLeft_) throw Error(ErrorKind::Corrupt, tooMany(loose, "faces repeating a vertex", size));
    bitsLeft_ -= 3 * loose * uint64_t(width);
    repairs_.looseTriangles.resize(size_t(3 * loose));
    for (uint32_t& v : repairs_.looseTriangles) {
        v = uint32_t(coder_.decodeWideBits(width));
        if (v >= vertexCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: a face in the repairs section refers to vertex " + std::to_string(v) +
                        " of " + std::to_string(vertexCount));
    }

    duplicates_ = coder_.decodeWideBits(32);
    if (duplicates_ > faceCount - loose)
        throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section claims " + std::to_string(duplicates_) +
                    " repeated faces, more than the header's faces leave room for");
    if (2 * duplicates_ > bitsLeft_) throw Error(ErrorKind::Corrupt, tooMany(duplicates_, "repeated faces", size));
    if (coder_.bytesPastEnd() > 0) throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section ends early");
}

void RepairReader::readAfterTraversal(size_t faceCount) {
    repairs_.flipped.assign(faceCount, 0);
    if (coder_.decodeBits(1)) {
        AdaptiveFrequencies model = flipModel();
        for (uint8_t& f : repairs_.flipped) f = uint8_t(model.decode(coder_));
    }
    const int positionWidth = indexBits(faceCount);
    repairs_.duplicateOf.resize(size_t(duplicates_));
    repairs_.duplicateReversed.resize(size_t(duplicates_));
    for (size_t i = 0; i < duplicates_; ++i) {
        const uint64_t position = coder_.decodeWideBits(positionWidth);
        if (position >= faceCount)
            throw Error(ErrorKind::Corrupt, "corrupt file: a repeated face in the repairs section repeats face " +
                        std::to_string(position) + " of " + std::to_string(faceCount));
        repairs_.duplicateOf[i] = uint32_t(position);
        repairs_.duplicateReversed[i] = uint8_t(coder_.decodeBits(1));
    }
    if (coder_.bytesPastEnd() > 0)
        throw Error(ErrorKind::Corrupt, "corrupt file: the repairs section (" + std::to_string(size_) + " bytes) ends early");
}

void undoCut(std::vector<uint32_t>& t, const Repairs& r, size_t vertexCount) {
    const size_t faceCount = t.size() / 3;
    for (uint32_t& v : t)
        if (v >= vertexCount) v = r.copyOf[v - vertexCount];
    for (size_t f = 0; f < faceCount && f < r.flipped.size(); ++f)
        if (r.flipped[f]) std::swap(t[3 * f + 1], t[3 * f + 2]);
    t.reserve(t.size() + 3 * (r.duplicateOf.size() + r.looseCount()));
    for (size_t i = 0; i < r.duplicateOf.size(); ++i) {
        const size_t f = r.duplicateOf[i];
        const uint32_t a = t[3 * f], b = t[3 * f + 1], c = t[3 * f + 2];
        if (r.duplicateReversed[i]) t.insert(t.end(), {a, c, b});
        else t.insert(t.end(), {a, b, c});
    }
    t.insert(t.end(), r.looseTriangles.begin(), r.looseTriangles.end());
}

}  // namespace drm
