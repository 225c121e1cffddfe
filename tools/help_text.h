// The limits and names the help texts quote, filled in from drmcodec.h when a
// help is printed, so `drm help encode` cannot drift from what the codec
// takes. A help text writes {bits} for "1..21", {levers} for "filter, gap,
// context, angle, front, boundary" and so on (the list is in help_text.cpp).
#ifndef DRM_TOOLS_HELP_TEXT_H
#define DRM_TOOLS_HELP_TEXT_H

#include <string>

namespace drm {
namespace cli {

// text with every {name} it knows replaced; unknown braces are left as
// they are.
std::string expandHelp(const char* text);

}  // namespace cli
}  // namespace drm

#endif  // DRM_TOOLS_HELP_TEXT_H
