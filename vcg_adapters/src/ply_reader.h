// A PLY reader that takes every value from the file's bytes as its header
// types them.
//
// Any valid PLY reads: ascii, binary_little_endian and binary_big_endian;
// every scalar type for every property and for list counts; header lines
// ending in LF, CRLF or CR (the first line's ending is the header's);
// comments of any length; unknown elements and properties, which are read
// past and named. Values are kept as they are, or converted with a note
// (doubles rounded to float, float colours scaled to bytes), never changed
// in silence. Vertex and face order and corner order are the file's;
// polygons are fan-split in place as (0, i, i + 1).
//
// Every count read from the file is checked against the bytes left before
// anything is allocated, so a hostile header cannot make the reader
// allocate wildly, and every index is checked before it is stored.
// C++14, no vcglib.
#ifndef DRM_VCG_PLY_READER_H
#define DRM_VCG_PLY_READER_H

#include <drmcodec/drmcodec.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {

// What the file's properties become (names as MeshLab writes and reads
// them):
//   vertex  x y z; nx ny nz; red green blue [alpha], else diffuse_red
//           diffuse_green diffuse_blue [diffuse_alpha], else intensity (a
//           grey); quality, else confidence; texture_u texture_v, else s t,
//           else u v
//   face    vertex_indices, else vertex_index (the corners); texcoord (two
//           values per corner); texnumber; red green blue [alpha]; quality
//   tristrips vertex_indices (strips split by -1); range_grid vertex_indices
//           (cells of an obj_info num_cols x num_rows grid)
//   `comment TextureFile NAME` (or obj_info): a texture name, byte for byte
// Colours without alpha get 255. Face normals, per-corner colours, radii,
// edges and cameras are named in `dropped`; any other property or element
// is named in `otherProperties` or `otherElements`.
struct PlyContents {
    drm::Mesh mesh;
    size_t trianglesFromPolygons = 0;        // triangles split from faces of more than 3 corners
    std::vector<std::string> conversions;    // sentences: values changed on the way in, and how, or data past the last element
    std::vector<std::string> dropped;        // "per-face normals", "edges", ...
    std::vector<std::string> otherProperties;  // "vertex.curvature", in header order
    std::vector<std::string> otherElements;    // elements with items that are not read
};

// Throws drm::Error(ErrorKind::InvalidInput, reason), the reason naming the
// header line, or the element and item at fault ("the file ends inside face
// 12 (truncated?)", "header line 5: unknown type 'foo'").
PlyContents readPly(const uint8_t* bytes, size_t size);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_PLY_READER_H
