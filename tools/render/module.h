// The renderer as a module of its own (drm-render.so), loaded by `drm
// render` only: it is the one part of the tool that needs Qt, and loading
// Qt's libraries (Qt5Gui brings GL, X11, ICU, HarfBuzz, ...) at the start of
// every `drm` process would take about 11 ms of CPU, 2 to 5 % of a whole
// `drm decode` of a bunny-sized mesh. The module's one entry point takes the
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
// returns 1 + the drm::ErrorKind of the failure, its message in error, or
// kRenderOutOfMemory.
extern "C" int drm_render_png(const drm::render::Scene* scene, std::vector<uint8_t>* png, std::string* error);
// Which build the module comes from: the library's version and the layout
// of the types above (kRenderModuleAbi), so that a module left from another
// build is refused with a message instead of being called.
extern "C" const char* drm_render_build();
constexpr int kRenderOutOfMemory = 100;
// Raise when Scene, LegendEntry or the entry points change.
constexpr int kRenderModuleAbi = 1;

namespace drm {
namespace render {

// The module's file name and where the tool looks for it, relative to the
// directory of the running executable: beside it (the build tree, with
// DRM_RENDER_MODULE_DIR) and in the installed library directory.
extern const char* const kModuleName;

// What drm_render_build() answers for this build (module and tool alike).
inline std::string renderModuleBuild() { return std::string(drm::version()) + " abi " + std::to_string(kRenderModuleAbi); }

// renderPng, from the module (loaded once, on first use). Throws drm::Error
// (Io) naming the places looked at when the module cannot be loaded or
// comes from another build, the module's own errors as drm::Error of their
// kind, and std::bad_alloc when it ran out of memory.
std::vector<uint8_t> renderPngInModule(const Scene& scene);

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_MODULE_H
