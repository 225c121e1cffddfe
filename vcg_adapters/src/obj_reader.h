// A small OBJ reader, used instead of vcglib's.
//
// vcglib 2020.09's ImporterOBJ silently drops every face that uses the
// file's first vertex (its index check rejects index 0 after converting to
// 0-based), faces whose normal index it cannot resolve, and faces repeating
// a vertex; a lossless codec cannot start from that. This reader keeps every
// vertex and face in file order and fan-splits polygons in place.
#ifndef DRM_VCG_OBJ_READER_H
#define DRM_VCG_OBJ_READER_H

#include <drm/drm.h>

#include <string>
#include <vector>

namespace drm {
namespace vcgio {

struct ObjContents {
    drm::Mesh mesh;
    size_t polygons = 0;               // faces with more than 3 corners
    size_t trianglesFromPolygons = 0;
    // What the file holds beyond positions and faces (none of it is kept).
    bool vertexColours = false;
    bool textureCoordinates = false;
    bool normals = false;
    bool materials = false;
    bool linesOrPoints = false;
};

// Reads OBJ text: `v x y z [r g b]`, `f a b c ...` with `a`, `a/t`, `a//n`
// or `a/t/n` corners (1-based, or negative = relative to the last vertex).
// Throws drm::Error("line N: reason").
ObjContents readObj(const std::string& text);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_OBJ_READER_H
