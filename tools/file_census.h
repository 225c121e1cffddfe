// A second, independent look at a mesh file for `drm verify`: how many
// vertices and triangles the file itself describes, counted by a scan that
// shares no code with the readers (vcg_adapters). The round trip check
// compares the decoded mesh with what the reader gave; this compares what
// the reader gave with the file, so a reader that drops a solid, a face or a
// vertex in silence is caught rather than reported lossless.
#ifndef DRM_TOOLS_FILE_CENSUS_H
#define DRM_TOOLS_FILE_CENSUS_H

#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace cli {

struct FileCensus {
    bool known = false;        // false: a format or layout the scan does not count
    bool vertexCountKnown = false;
    uint64_t vertices = 0;     // as the file lists them (STL: not counted, it lists corners)
    uint64_t minTriangles = 0;  // the triangles the faces make (a polygon of n corners: n - 2) ...
    uint64_t maxTriangles = 0;  // ... within these bounds (equal where the scan counts them exactly)
};

// Counts by the file's extension (.ply, .obj, .off, .stl, any case):
// PLY: the header's vertex count and the corners of each face's
// vertex_indices list, found by walking every element's list counts (a file
// with tristrips or a range_grid: at least the faces' triangles); OBJ:
// `v` statements and
// the corners of `f` statements; OFF: the header's vertex count and each
// face's corner count; STL: facets (binary: the header's count; ASCII:
// `endfacet` statements in every solid). Never throws: what it cannot count
// is left unknown.
FileCensus takeCensus(const std::string& path, const std::vector<uint8_t>& bytes);

// "" when the mesh a reader gave (its vertex and triangle counts) agrees
// with the census, otherwise the difference as a sentence.
std::string censusMismatch(const FileCensus& census, uint64_t vertices, uint64_t triangles);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_FILE_CENSUS_H
