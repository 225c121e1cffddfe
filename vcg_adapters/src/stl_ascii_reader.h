// A reader of ASCII STL: every solid of the file, facet by facet.
//
// A file may hold several `solid ... endsolid` blocks (one per part, as CAD
// tools export assemblies); all of them are read, in file order, as one
// triangle soup that stl_weld.h then welds.
#ifndef DRM_VCG_STL_ASCII_READER_H
#define DRM_VCG_STL_ASCII_READER_H

#include <drmcodec/drmcodec.h>

#include <cstddef>
#include <string>

namespace drm {
namespace vcgio {

struct AsciiStl {
    drm::Mesh soup;      // three new vertices per facet, in file order
    size_t solids = 0;   // `solid` blocks read
};

// Reads ASCII STL text (keywords in any case; lines ending in LF, CRLF or
// CR). Throws drm::Error("line N: reason") for a facet that does not hold
// exactly three vertices, a number that is not one, a statement out of
// place, or a file that ends inside a solid.
AsciiStl readAsciiStl(const std::string& text);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_STL_ASCII_READER_H
