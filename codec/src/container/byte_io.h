// Little-endian byte IO for the .drm file format. The writer appends to a
// growing buffer; the reader checks every read against the bytes it was
// given and throws drm::Error naming the field and its file offset, so the
// decoder never reads out of bounds and never sizes an allocation from an
// unchecked value (count() bounds untrusted counts first).
#ifndef DRM_BYTE_IO_H
#define DRM_BYTE_IO_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace drm {

class ByteWriter {
public:
    void u8(uint8_t value);
    void u16(uint16_t value);
    void u32(uint32_t value);
    void f64(double value);      // the IEEE-754 bit pattern, little-endian
    void varint(uint64_t value); // LEB128: 7 bits a byte, low bits first
    void bytes(const uint8_t* data, size_t size);
    void bytes(const std::vector<uint8_t>& data);

    size_t size() const { return buffer_.size(); }
    std::vector<uint8_t>& buffer() { return buffer_; }

private:
    std::vector<uint8_t> buffer_;
};

class ByteReader {
public:
    // what names the part of the file read (e.g. "header") in messages;
    // baseOffset is the file offset of data[0], so messages give file offsets.
    ByteReader(const uint8_t* data, size_t size, std::string what, size_t baseOffset = 0);

    // Each read names its field for the error message should it fail.
    uint8_t u8(const char* field);
    uint16_t u16(const char* field);
    uint32_t u32(const char* field);
    double f64(const char* field);
    // Rejects encodings longer than 10 bytes, values past 64 bits and
    // overlong encodings (a final zero byte), which the writer never makes.
    uint64_t varint(const char* field);
    // A varint that must not exceed maxAllowed: use it for every count
    // that sizes a loop or an allocation.
    uint64_t count(const char* field, uint64_t maxAllowed);
    // n bytes in place (valid while the caller's data lives).
    const uint8_t* bytes(size_t n, const char* field);

    size_t offset() const { return pos_; }  // bytes read so far, from data[0]
    size_t remaining() const { return size_ - pos_; }

private:
    void require(size_t n, const char* field) const;
    uint64_t littleEndian(int byteCount, const char* field);
    [[noreturn]] void corrupt(const char* field, const std::string& problem, size_t at) const;

    const uint8_t* data_;
    size_t size_;
    std::string what_;
    size_t baseOffset_;
    size_t pos_ = 0;
};

}  // namespace drm

#endif  // DRM_BYTE_IO_H
