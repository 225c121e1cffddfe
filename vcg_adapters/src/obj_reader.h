// A small OBJ reader, used instead of vcglib's.
//
// vcglib 2020.09's ImporterOBJ silently drops every face that uses the
// file's first vertex (its index check rejects index 0 after converting to
// 0-based), faces whose normal index it cannot resolve, and faces repeating
// a vertex; a lossless codec cannot start from that. This reader keeps every
// vertex and face in file order and fan-splits polygons in place.
#ifndef DRM_VCG_OBJ_READER_H
#define DRM_VCG_OBJ_READER_H

#include <drmcodec/drmcodec.h>

#include <string>
#include <vector>

namespace drm {
namespace vcgio {

struct ObjContents {
    // Positions, triangles and what the file's statements give per vertex
    // and corner: colours (`v x y z r g b`), corner texture coordinates
    // (`vt`), normals (`vn`: per vertex when every corner of a vertex uses
    // the same normal, per corner otherwise), materials (`usemtl` names in
    // order of first use, faceMaterial for every face; faces before the first
    // `usemtl` use the material ""). Metadata and textures come from the
    // .mtl file, which the caller reads (see mtllib).
    drm::Mesh mesh;
    std::string mtllib;                // the first `mtllib` file name, or ""
    size_t otherLibraries = 0;         // further `mtllib` lines naming other files (not read)
    size_t polygons = 0;               // faces with more than 3 corners
    size_t trianglesFromPolygons = 0;
    // What the file holds that is not kept, or kept only in part.
    bool linesOrPoints = false;
    size_t cornersWithoutTexCoord = 0;  // in a file whose other corners have one (given 0, 0)
    size_t cornersWithoutNormal = 0;    // likewise (given 0, 0, 0)
    size_t verticesWithoutColour = 0;   // in a file whose other vertices have one (given white)
    bool coloursOver255 = false;        // colours given as 0..255, not 0..1
    bool texCoordW = false;             // some `vt` has a third (w) component other than 0
    bool unusedTexCoords = false;       // `vt` lines that no face uses
    bool unusedNormals = false;         // `vn` lines that no face uses
};

// Reads OBJ text: `v x y z [r g b]`, `vt u v [w]`, `vn x y z`, `usemtl`,
// `mtllib`, `f a b c ...` with `a`, `a/t`, `a//n` or `a/t/n` corners
// (1-based, or negative = relative to the last one read). Lines end in LF,
// CRLF or CR; a comment starts at a '#' at a line's start or after a blank
// (text_lines.h). Names (usemtl, mtllib) are the rest of their line. A
// UTF-8 byte order mark is skipped; UTF-16 text is refused. Throws
// drm::Error("line N: reason").
ObjContents readObj(const std::string& text);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_OBJ_READER_H
