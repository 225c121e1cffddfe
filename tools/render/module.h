// The renderer as a module of its own (drm-render.so), loaded by `drm
// render` only: it is the one part of the tool that needs Qt, and loading
// Qt's libraries (Qt5Gui brings GL, X11, ICU, HarfBuzz, ...) at the start of
// every `drm` process took about 11 ms of CPU, 2 to 5 % of a whole `drm
// decode` of a bunny-sized mesh. The module's one entry point takes the
// scene and gives the PNG or an error; nothing crosses the boundary as an
// exception. Module and tool come from the same build (same compiler and
// standard library), so they share the C++ types of picture.h.
#ifndef DRM_TOOLS_RENDER_MODULE_H
#define DRM_TOOLS_RENDER_MODULE_H

#include "picture.h"

#include <cstdint>
#include <string>
#include <vector>

// What the module exports: renders the scene into png and returns 0, or
// returns 1 + the drm::ErrorKind of the failure, its message in error.
extern "C" int drm_render_png(const drm::render::Scene* scene, std::vector<uint8_t>* png, std::string* error);

namespace drm {
namespace render {

// The module's file name and where the tool looks for it, relative to the
// directory of the running executable: beside it (the build tree, with
// DRM_RENDER_MODULE_DIR) and in the installed library directory.
extern const char* const kModuleName;

// renderPng, from the module (loaded once, on first use). Throws drm::Error
// (Io) naming the places looked at when the module cannot be loaded, and
// the module's own errors as drm::Error of their kind.
std::vector<uint8_t> renderPngInModule(const Scene& scene);

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_MODULE_H
