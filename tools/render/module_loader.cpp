// Finds and loads drm-render.so for `drm render` (module.h).
#include "module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>

namespace drm {
namespace render {

const char* const kModuleName = "drm-render.so";

namespace {

// The directory of the running executable, with its trailing slash.
std::string executableDirectory() {
    char path[PATH_MAX];
    const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length <= 0) return "./";
    const std::string exe(path, size_t(length));
    const size_t slash = exe.rfind('/');
    return slash == std::string::npos ? "./" : exe.substr(0, slash + 1);
}

using RenderPng = int (*)(const Scene*, std::vector<uint8_t>*, std::string*);

RenderPng loadModule() {
    static RenderPng loaded = nullptr;
    if (loaded) return loaded;
    const std::string here = executableDirectory();
    // The build tree keeps the module beside the executable; an installed
    // drm finds it under the library directory (paths set by CMake).
    const std::string places[] = {here + DRM_RENDER_MODULE_DIR "/" + kModuleName,
                                  here + DRM_RENDER_INSTALLED_DIR "/" + kModuleName};
    std::string tried;
    for (const std::string& place : places) {
        void* module = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            const char* why = dlerror();
            tried += (tried.empty() ? " " : "; ") + place + (why ? std::string(" (") + why + ")" : std::string());
            continue;
        }
        loaded = reinterpret_cast<RenderPng>(dlsym(module, "drm_render_png"));
        if (loaded) return loaded;
        tried += (tried.empty() ? " " : "; ") + place + " (no drm_render_png in it)";
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
    if (status != 0) throw Error(ErrorKind(status - 1), error);
    return png;
}

}  // namespace render
}  // namespace drm
