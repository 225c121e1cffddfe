// Finds and loads drm-render.so for `drm render` (module.h).
#include "module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <new>

namespace drm {
namespace render {

const char* const kModuleName = "drm-render.so";

namespace {

// The directory of the running executable, with its trailing slash. Not
// the current directory when /proc is missing: a module is loaded only
// from where the tool itself lies.
std::string executableDirectory() {
    char path[PATH_MAX];
    const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    const std::string exe = length > 0 ? std::string(path, size_t(length)) : std::string();
    const size_t slash = exe.rfind('/');
    if (slash == std::string::npos)
        throw Error(ErrorKind::Io, std::string("drm render needs its renderer, ") + kModuleName +
                                       ", beside the drm executable, whose folder cannot be found (/proc/self/exe)");
    return exe.substr(0, slash + 1);
}

using RenderPng = int (*)(const Scene*, std::vector<uint8_t>*, std::string*);
using RenderBuild = const char* (*)();

RenderPng loadModule() {
    static RenderPng loaded = nullptr;
    if (loaded) return loaded;
    const std::string here = executableDirectory();
    // The build tree keeps the module beside the executable; an installed
    // drm finds it under the library directory (paths set by CMake).
    const std::string places[] = {here + DRM_RENDER_MODULE_DIR "/" + kModuleName,
                                  here + DRM_RENDER_INSTALLED_DIR "/" + kModuleName};
    const std::string wanted = renderModuleBuild();
    std::string tried;
    auto note = [&](const std::string& place, const std::string& why) {
        tried += (tried.empty() ? " " : "; ") + place + " (" + why + ")";
    };
    for (const std::string& place : places) {
        void* module = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            const char* why = dlerror();
            note(place, why ? why : "cannot be loaded");
            continue;
        }
        const auto build = reinterpret_cast<RenderBuild>(dlsym(module, "drm_render_build"));
        const auto render = reinterpret_cast<RenderPng>(dlsym(module, "drm_render_png"));
        if (!build || !render) {
            note(place, "not drm's renderer");
        } else if (build() != wanted) {
            note(place, std::string("from another build: ") + build() + ", drm is " + wanted);
        } else {
            loaded = render;
            return loaded;
        }
        dlclose(module);
    }
    throw Error(ErrorKind::Io, std::string("drm render needs its renderer, ") + kModuleName +
                                   ", which could not be loaded: looked at" + tried);
}

}  // namespace

std::vector<uint8_t> renderPngInModule(const Scene& scene) {
    const RenderPng render = loadModule();
    std::vector<uint8_t> png;
    std::string error;
    const int status = render(&scene, &png, &error);
    if (status == kRenderOutOfMemory) throw std::bad_alloc();
    if (status != 0) throw Error(ErrorKind(status - 1), error);
    return png;
}

}  // namespace render
}  // namespace drm
