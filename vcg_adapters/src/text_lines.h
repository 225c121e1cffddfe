// Lines and comments of line-based text formats (OBJ, MTL).
#ifndef DRM_VCG_TEXT_LINES_H
#define DRM_VCG_TEXT_LINES_H

#include <cstddef>
#include <string>
#include <vector>

#include "drm_vcg/joined_list.h"  // joinList, used with these

namespace drm {
namespace vcgio {

// The line that starts at `position`, without its ending (LF, CRLF or a lone
// CR, as old Mac tools write), and moves `position` past that ending.
std::string takeLine(const std::string& text, size_t& position);

// The words of a line: runs of characters between blanks (space, tab, CR,
// form feed, vertical tab).
std::vector<std::string> splitWords(const std::string& line);

// Cuts a statement's comment off, from a '#' that starts the line or follows
// a blank ("usemtl red # shiny" is the material "red"; "tex#1.png" keeps its
// '#'), then the blanks at both ends.
void stripComment(std::string& line);

// Whether `text` holds a control character other than tab (a line break,
// a form feed, an escape, ...).
bool holdsControlCharacter(const std::string& text);

// Why a name (material, texture or library file) cannot be written as the
// rest of a line and be read back the same, or nullptr if it can: a control
// character would end or bend the line. In OBJ and MTL (objOrMtl) blanks at
// either end are trimmed by readers and a '#' at the start or after a blank
// starts a comment; drm's PLY reader keeps the rest of a comment line as it
// is.
const char* unwritableNameReason(const std::string& name, bool objOrMtl);

// The name for a message: control characters as \n, \r, \t or \xNN.
std::string printableName(const std::string& name);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_TEXT_LINES_H
