// Checks run on a file's bytes before vcglib's readers see them.
//
// Those readers trust their input: vcglib's OFF reader indexes its vertex
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

// Binary STL must be exactly 84 + 50 * triangle count bytes long; anything
// else must be plain ASCII text starting with "solid" and holding a newline.
// Returns true for binary STL.
bool preflightStl(const std::vector<uint8_t>& bytes);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_FORMAT_PREFLIGHT_H
