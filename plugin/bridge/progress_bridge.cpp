#include "bridge/progress_bridge.h"

#include <memory>

namespace drm_meshlab {

drm::Progress progressTo(vcg::CallBackPos* cb) {
    if (cb == nullptr) return drm::Progress();
    // Shared, because std::function copies its target.
    auto lastPercent = std::make_shared<int>(-1);
    return [cb, lastPercent](double fraction, const char* stage) {
        const int percent = fraction <= 0 ? 0 : (fraction >= 1 ? 100 : int(fraction * 100.0));
        if (percent == *lastPercent) return true;
        *lastPercent = percent;
        return cb(percent, stage != nullptr ? stage : "");
    };
}

}  // namespace drm_meshlab
