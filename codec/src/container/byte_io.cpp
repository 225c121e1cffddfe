#include "container/byte_io.h"

#include <cstring>
#include <utility>

#include "drmcodec/drmcodec.h"

namespace drm {

namespace {

void appendLittleEndian(std::vector<uint8_t>& out, uint64_t value, int byteCount) {
    for (int i = 0; i < byteCount; ++i) out.push_back(uint8_t(value >> (8 * i)));
}

constexpr int kMaxVarintBytes = 10;  // ceil(64 / 7)

}  // namespace

void ByteWriter::u8(uint8_t value) { buffer_.push_back(value); }
void ByteWriter::u16(uint16_t value) { appendLittleEndian(buffer_, value, 2); }
void ByteWriter::u32(uint32_t value) { appendLittleEndian(buffer_, value, 4); }

void ByteWriter::f64(double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    appendLittleEndian(buffer_, bits, 8);
}

void ByteWriter::varint(uint64_t value) {
    for (; value >= 0x80; value >>= 7) buffer_.push_back(uint8_t(value | 0x80));
    buffer_.push_back(uint8_t(value));
}

void ByteWriter::bytes(const uint8_t* data, size_t size) {
    if (size > 0) buffer_.insert(buffer_.end(), data, data + size);
}

void ByteWriter::bytes(const std::vector<uint8_t>& data) {
    buffer_.insert(buffer_.end(), data.begin(), data.end());
}

ByteReader::ByteReader(const uint8_t* data, size_t size, std::string what, size_t baseOffset)
    : data_(data), size_(data ? size : 0), what_(std::move(what)), baseOffset_(baseOffset) {}

void ByteReader::require(size_t n, const char* field) const {
    if (n <= remaining()) return;
    const size_t missing = n - remaining();
    throw Error(ErrorKind::Corrupt, "truncated file: " + what_ + " field \"" + field + "\" needs " +
                std::to_string(missing) + " more byte" + (missing == 1 ? "" : "s") +
                " at offset " + std::to_string(baseOffset_ + pos_));
}

void ByteReader::corrupt(const char* field, const std::string& problem, size_t at) const {
    throw Error(ErrorKind::Corrupt, "corrupt file: " + what_ + " field \"" + field + "\" " + problem + " at offset " +
                std::to_string(baseOffset_ + at));
}

uint64_t ByteReader::littleEndian(int byteCount, const char* field) {
    require(size_t(byteCount), field);
    uint64_t value = 0;
    for (int i = 0; i < byteCount; ++i) value |= uint64_t(data_[pos_ + size_t(i)]) << (8 * i);
    pos_ += size_t(byteCount);
    return value;
}

uint8_t ByteReader::u8(const char* field) { return uint8_t(littleEndian(1, field)); }
uint16_t ByteReader::u16(const char* field) { return uint16_t(littleEndian(2, field)); }
uint32_t ByteReader::u32(const char* field) { return uint32_t(littleEndian(4, field)); }

double ByteReader::f64(const char* field) {
    const uint64_t bits = littleEndian(8, field);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

uint64_t ByteReader::varint(const char* field) {
    const size_t start = pos_;
    uint64_t value = 0;
    for (int i = 0; i < kMaxVarintBytes; ++i) {
        if (pos_ >= size_) {
            // Report the whole field, as the fixed-size reads do.
            pos_ = start;
            require(size_t(i) + 1, field);
        }
        const uint8_t byte = data_[pos_++];
        // The tenth byte holds bit 63 only.
        if (i == kMaxVarintBytes - 1 && byte > 1) corrupt(field, "does not fit in 64 bits", start);
        value |= uint64_t(byte & 0x7F) << (7 * i);
        if ((byte & 0x80) == 0) {
            if (byte == 0 && i > 0) corrupt(field, "has an overlong encoding", start);
            return value;
        }
    }
    return value;  // not reached: the tenth byte either ends the varint or is rejected
}

uint64_t ByteReader::count(const char* field, uint64_t maxAllowed) {
    const size_t start = pos_;
    const uint64_t value = varint(field);
    if (value > maxAllowed)
        corrupt(field,
                "= " + std::to_string(value) + " exceeds the limit " + std::to_string(maxAllowed),
                start);
    return value;
}

const uint8_t* ByteReader::bytes(size_t n, const char* field) {
    require(n, field);
    const uint8_t* at = data_ + pos_;
    pos_ += n;
    return at;
}

}  // namespace drm
