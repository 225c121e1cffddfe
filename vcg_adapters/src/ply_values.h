// How the PLY reader turns a value of the file's type into what drm::Mesh
// holds: floats (doubles rounded, with a count for the note), colour bytes
// (floats and ushorts scaled, other integers clamped, with counts) and whole
// numbers (indices, counts, texture numbers), and how a message shows a
// value. Overloaded per type, so that the body's loops, compiled once per
// type, convert without a switch. Private to readPly.
#ifndef DRM_VCG_PLY_VALUES_H
#define DRM_VCG_PLY_VALUES_H

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

namespace drm {
namespace vcgio {
namespace ply {

// A value as a message shows it.
template <class I> inline std::string show(I value) { return std::to_string(int64_t(value)); }
inline std::string show(uint32_t value) { return std::to_string(value); }
inline std::string show(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}
inline std::string show(float value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

// How a group of values (positions, say) came to be floats: how many were
// rounded, and from which types, for the note.
struct FloatStats {
    size_t changed = 0;
    unsigned sourceTypes = 0;  // bits of the types other than float
};

// How a group of colour values came to be bytes.
struct ColourStats {
    unsigned scaledTypes = 0;   // float, double (0..1) and ushort (0..65535) scale
    size_t clampedUnit = 0;     // float values outside 0..1
    size_t clampedInteger = 0;  // integer values outside 0..255
    bool grey = false;          // read from `intensity`
};

// False if a double is beyond float's range (the conversion would be
// undefined, and infinity is not the file's value).
inline bool toFloat(float value, float& out, FloatStats&) {
    out = value;
    return true;
}
inline bool toFloat(double value, float& out, FloatStats& stats) {
    if (std::isfinite(value) && std::fabs(value) > double(FLT_MAX)) return false;
    out = float(value);
    if (double(out) != value && !std::isnan(value)) ++stats.changed;
    return true;
}
template <class I>
inline bool toFloat(I value, float& out, FloatStats& stats) {
    out = float(value);
    if (double(out) != double(value)) ++stats.changed;
    return true;
}

inline uint8_t unitToByte(double value, ColourStats& stats) {
    if (!(value >= 0.0)) {  // negative or NaN
        ++stats.clampedUnit;
        return 0;
    }
    if (value > 1.0) {
        ++stats.clampedUnit;
        return 255;
    }
    return uint8_t(std::lround(value * 255.0));
}
inline uint8_t toByte(uint8_t value, ColourStats&) { return value; }
inline uint8_t toByte(float value, ColourStats& stats) { return unitToByte(double(value), stats); }
inline uint8_t toByte(double value, ColourStats& stats) { return unitToByte(value, stats); }
inline uint8_t toByte(uint16_t value, ColourStats&) { return uint8_t((uint32_t(value) * 255u + 32767u) / 65535u); }
template <class I>
inline uint8_t toByte(I value, ColourStats& stats) {
    const int64_t wide = int64_t(value);
    if (wide < 0 || wide > 255) {
        ++stats.clampedInteger;
        return wide < 0 ? 0 : 255;
    }
    return uint8_t(wide);
}

// A whole number (vertex index, texture number, list count), or kNotWhole.
constexpr int64_t kNotWhole = std::numeric_limits<int64_t>::min();
template <class I>
inline int64_t toWhole(I value) {
    return int64_t(value);
}
inline int64_t toWhole(double value) {
    return (value == std::floor(value) && std::fabs(value) < 9.0e18) ? int64_t(value) : kNotWhole;
}
inline int64_t toWhole(float value) { return toWhole(double(value)); }

}  // namespace ply
}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_PLY_VALUES_H
