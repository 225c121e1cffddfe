// Wavefront material libraries (.mtl) as drm keeps them.
//
// A .drm file stores the statements of a library that were understood, one
// per line, never the file's raw text: what an OBJ's library holds beyond
// materials (comments, unknown statements, anything a hostile file slips in)
// is named in a note and left out, and the same parse runs again before a
// library is written, so a damaged or hand-made .drm cannot make drm write
// anything but material statements.
#ifndef DRM_VCG_MTL_LIBRARY_H
#define DRM_VCG_MTL_LIBRARY_H

#include <string>
#include <utility>
#include <vector>

namespace drm {
namespace vcgio {

struct MtlLibrary {
    // The statements kept, in file order, one per line: `KEYWORD ARGUMENTS`
    // with single blanks between the keyword and numeric arguments; a
    // material or texture file name is kept byte for byte.
    std::string text;
    // (material name, map_Kd file name) for each map_Kd, in file order.
    std::vector<std::pair<std::string, std::string>> textures;
    // Statements left out, as "line N (KEYWORD)", for a note: the first
    // few, then how many in all.
    std::vector<std::string> dropped;
    size_t droppedCount = 0;
};

// Parses .mtl text (statement lines as text_lines.h reads them). Never
// throws on content.
MtlLibrary readMtl(const std::string& text);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_MTL_LIBRARY_H
