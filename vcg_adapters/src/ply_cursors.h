// The PLY reader's cursors over a body: BinaryCursor reads values of the
// header's types in either byte order, AsciiCursor reads them as
// blank-separated tokens. Both have the same calls (read, readCount,
// bytesLeft, entryBytes, problem), so the item-by-item reader
// (ply_items.cpp) is one template for all three encodings; load() also
// serves the binary reader's loops (ply_binary_body.cpp). Private to readPly.
#ifndef DRM_VCG_PLY_CURSORS_H
#define DRM_VCG_PLY_CURSORS_H

#include "ply_header.h"
#include "ply_values.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace drm {
namespace vcgio {
namespace ply {

#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostBigEndian = true;
#else
constexpr bool kHostBigEndian = false;
#endif

template <class T, bool BigEndian>
inline T load(const uint8_t* at) {
    T value;
    if (BigEndian == kHostBigEndian) {
        std::memcpy(&value, at, sizeof(T));
    } else {
        uint8_t swapped[sizeof(T)];
        for (size_t i = 0; i < sizeof(T); ++i) swapped[i] = at[sizeof(T) - 1 - i];
        std::memcpy(&value, swapped, sizeof(T));
    }
    return value;
}

enum class ReadStatus { Ok, End, Bad };

template <bool BigEndian>
class BinaryCursor {
public:
    BinaryCursor(const uint8_t* at, const uint8_t* end) : at_(at), end_(end) {}
    template <class T>
    ReadStatus read(T& value) {
        if (size_t(end_ - at_) < sizeof(T)) return ReadStatus::End;
        value = load<T, BigEndian>(at_);
        at_ += sizeof(T);
        return ReadStatus::Ok;
    }
    ReadStatus readCount(Scalar type, int64_t& entries) {
        ReadStatus status = ReadStatus::Ok;
        withType(type, [&](auto tag) {
            decltype(tag) value{};
            status = this->read(value);
            entries = toWhole(value);
        });
        return status;
    }
    size_t bytesLeft() const { return size_t(end_ - at_); }
    // The fewest bytes a list entry of `type` takes.
    static size_t entryBytes(Scalar type) { return describe(type).size; }
    std::string problem() const { return ""; }

private:
    const uint8_t* at_;
    const uint8_t* end_;
};

// ASCII values: blank-separated tokens, wherever the lines break. Floats are
// parsed by strtof (float) or strtod (double), as the header types them;
// integers must be whole numbers in their type's range.
class AsciiCursor {
public:
    AsciiCursor(const uint8_t* at, const uint8_t* end) : at_(at), end_(end) {}
    template <class T>
    ReadStatus read(T& value) {
        while (at_ < end_ && isBlank(*at_)) ++at_;
        if (at_ == end_) return ReadStatus::End;
        const uint8_t* start = at_;
        while (at_ < end_ && !isBlank(*at_)) ++at_;
        token_.assign(reinterpret_cast<const char*>(start), size_t(at_ - start));
        return parse(value) ? ReadStatus::Ok : ReadStatus::Bad;
    }
    // Any whole number: the count's type gives its width in binary files
    // only, and a count beyond the file is refused as such.
    ReadStatus readCount(Scalar, int64_t& entries) { return read(entries); }
    size_t bytesLeft() const { return size_t(end_ - at_); }
    // A blank and a character at least.
    static size_t entryBytes(Scalar) { return 2; }
    // Why the last token was refused: "'abc' is not a number".
    std::string problem() const {
        const std::string shown = token_.size() > 40 ? token_.substr(0, 40) + "..." : token_;
        return "'" + shown + "' " + why_;
    }

private:
    bool parse(float& value) {
        char* stop = nullptr;
        value = std::strtof(token_.c_str(), &stop);
        why_ = "is not a number";
        return stop == token_.c_str() + token_.size();
    }
    bool parse(double& value) {
        char* stop = nullptr;
        value = std::strtod(token_.c_str(), &stop);
        why_ = "is not a number";
        return stop == token_.c_str() + token_.size();
    }
    template <class I>
    bool parse(I& value) {
        errno = 0;
        char* stop = nullptr;
        long long whole = std::strtoll(token_.c_str(), &stop, 10);
        if (stop != token_.c_str() + token_.size() || errno != 0) {
            // "3.0" for an integer is still 3.
            const double number = std::strtod(token_.c_str(), &stop);
            if (stop != token_.c_str() + token_.size() || toWhole(number) == kNotWhole) {
                why_ = "is not a whole number";
                return false;
            }
            whole = toWhole(number);
        }
        if (whole < static_cast<long long>(std::numeric_limits<I>::min()) || whole > static_cast<long long>(std::numeric_limits<I>::max())) {
            why_ = std::string("is outside the range of ") + typeName(I());
            return false;
        }
        value = I(whole);
        return true;
    }

    static const char* typeName(int8_t) { return "char"; }
    static const char* typeName(uint8_t) { return "uchar"; }
    static const char* typeName(int16_t) { return "short"; }
    static const char* typeName(uint16_t) { return "ushort"; }
    static const char* typeName(int32_t) { return "int"; }
    static const char* typeName(uint32_t) { return "uint"; }
    static const char* typeName(int64_t) { return "a count"; }

    const uint8_t* at_;
    const uint8_t* end_;
    std::string token_;
    std::string why_;
};

}  // namespace ply
}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_PLY_CURSORS_H
