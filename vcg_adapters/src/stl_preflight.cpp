// preflightStl: see format_preflight.h for why.
#include "format_preflight.h"

#include <drmcodec/drmcodec.h>

#include <algorithm>
#include <cctype>

namespace drm {
namespace vcgio {

bool preflightStl(const std::vector<uint8_t>& bytes) {
    // vcglib calls a file binary exactly when its size matches the triangle
    // count in bytes 80..83, so an exact match is all a binary file needs.
    if (bytes.size() >= 84) {
        const uint64_t triangles = uint64_t(bytes[80]) | uint64_t(bytes[81]) << 8 |
                                   uint64_t(bytes[82]) << 16 | uint64_t(bytes[83]) << 24;
        if (84 + 50 * triangles == bytes.size()) return true;
    }
    const bool plainText = std::all_of(bytes.begin(), bytes.end(), [](uint8_t b) {
        return b >= 32 ? b < 127 : (b == '\n' || b == '\r' || b == '\t' || b == '\f' || b == '\v');
    });
    if (!plainText)
        throw Error(ErrorKind::InvalidInput, "not an STL file: as binary STL its size does not match its triangle count, "
                    "and it is not ASCII text");
    const size_t start = std::min(bytes.size(), size_t(std::find_if(bytes.begin(), bytes.end(), [](uint8_t b) {
                                                          return b != ' ' && b != '\t' && b != '\r' && b != '\n';
                                                      }) - bytes.begin()));
    const std::string solid = "solid";
    if (bytes.size() - start < solid.size() ||
        !std::equal(solid.begin(), solid.end(), bytes.begin() + long(start),
                    [](char a, uint8_t b) { return a == char(std::tolower(b)); }))
        throw Error(ErrorKind::InvalidInput, "not an STL file: ASCII STL starts with \"solid\"");
    if (std::find_if(bytes.begin() + long(start), bytes.end(), [](uint8_t b) { return b == '\n' || b == '\r'; }) == bytes.end())
        throw Error(ErrorKind::InvalidInput, "not an STL file: ASCII STL without a single line break");
    return false;
}

}  // namespace vcgio
}  // namespace drm
