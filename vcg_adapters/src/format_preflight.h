// Checks run on a file's bytes before vcglib's readers see them.
//
// Those readers trust their input: vcglib's PLY reader copies a face's
// corners into a fixed array of 512 without checking the count, and does not
// check the last corner of a polygon; its OFF reader indexes its vertex
// array with unchecked face indices and reads past the end of its token list
// when the file has fewer faces than its header says; its ASCII STL reader
// loops forever on a file without a newline and its binary reader reads
// garbage from a truncated file. These checks refuse such files with a
// reason, so that the readers only ever see input they handle correctly.
// Each function throws drm::Error(reason) and returns if the file is fine.
#ifndef DRM_VCG_FORMAT_PREFLIGHT_H
#define DRM_VCG_FORMAT_PREFLIGHT_H

#include <cstdint>
#include <string>
#include <vector>

namespace drm {
namespace vcgio {

// Mirrors the layout rules of vcglib's ImporterOFF (header keyword, counts,
// per-vertex tokens, one face per line) and checks every face index.
// Returns the number of triangles the faces make (a polygon of n corners
// makes n - 2), to check vcglib's result against.
uint64_t preflightOff(const std::string& text);

// Walks the header and every element of the body as vcglib's plylib reads
// them: the file must hold all the items its header promises; faces need 3 to
// 127 corners, each an existing vertex; lists vcglib copies into fixed
// arrays must fit them. Returns the number of triangles of the "face"
// element, or -1 if the file has none (vcglib may still read tristrips).
// If `properties` is given, it receives the header's properties as
// "ELEMENT.NAME" in header order.
//
// If `plain` is given, it says whether the file has the plainest layout,
// binary little-endian with float x, y, z per vertex and a list uchar
// int|uint vertex_indices of exactly three per face, nothing else (the
// corpus's), and where its two elements start: loadPly copies such a body
// straight in, where vcglib's reader parses it field by field (a sixth of
// `drm encode`'s instructions on bunny).
struct PlainPly {
    bool plain = false;
    size_t vertexStart = 0, faceStart = 0;
    uint64_t vertexCount = 0, faceCount = 0;
};
int64_t preflightPly(const std::vector<uint8_t>& bytes, std::vector<std::string>* properties = nullptr,
                     PlainPly* plain = nullptr);

// Binary STL must be exactly 84 + 50 * triangle count bytes long; anything
// else must be plain ASCII text starting with "solid" and holding a newline.
// Returns true for binary STL.
bool preflightStl(const std::vector<uint8_t>& bytes);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_FORMAT_PREFLIGHT_H
