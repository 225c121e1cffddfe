// The module's entry point (module.h): renderPng behind a C name, its errors
// as a code and a message.
#include "module.h"

#include <exception>

extern "C" __attribute__((visibility("default"))) int drm_render_png(const drm::render::Scene* scene,
                                                                    std::vector<uint8_t>* png, std::string* error) {
    try {
        *png = drm::render::renderPng(*scene);
        return 0;
    } catch (const drm::Error& e) {
        *error = e.what();
        return 1 + int(e.kind());
    } catch (const std::exception& e) {
        *error = e.what();
        return 1 + int(drm::ErrorKind::Internal);
    }
}
