// What both plugins tell the user when a codec or adapter call fails: one
// place that decides which exceptions are caught and how each reads, so the
// import, the export and the rank filter report failures alike. Call from
// inside a catch (...) block.
#ifndef DRM_MESHLAB_ERROR_MESSAGE_H
#define DRM_MESHLAB_ERROR_MESSAGE_H

#include <exception>
#include <new>
#include <string>

#include "drmcodec/drmcodec.h"

namespace drm_meshlab {

// The message of the exception being handled: a drm::Error's own sentence
// (of any kind), "not enough memory" for std::bad_alloc, what() of any
// other std::exception, "unknown error" otherwise.
inline std::string currentErrorMessage() {
    try {
        throw;
    } catch (const drm::Error& e) {
        return e.what();
    } catch (const std::bad_alloc&) {
        return "not enough memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown error";
    }
}

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_ERROR_MESSAGE_H
