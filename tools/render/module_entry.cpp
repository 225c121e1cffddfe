// The module's entry points (module.h): renderPng behind a C name, its
// errors as a code and a message; nothing is thrown across.
#include "module.h"

#include <exception>
#include <new>

extern "C" __attribute__((visibility("default"))) int drm_render_png(const drm::render::Scene* scene,
                                                                    std::vector<uint8_t>* png, std::string* error) {
    try {
        *png = drm::render::renderPng(*scene);
        return 0;
    } catch (const drm::Error& e) {
        *error = e.what();
        return 1 + int(e.kind());
    } catch (const std::bad_alloc&) {
        return kRenderOutOfMemory;
    } catch (const std::exception& e) {
        *error = e.what();
        return 1 + int(drm::ErrorKind::Internal);
    } catch (...) {
        *error = "internal error: an unknown exception in the renderer";
        return 1 + int(drm::ErrorKind::Internal);
    }
}

extern "C" __attribute__((visibility("default"))) const char* drm_render_build() {
    static const std::string build = drm::render::renderModuleBuild();
    return build.c_str();
}
