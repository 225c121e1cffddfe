#include "bridge/progress_bridge.h"

#include "bridge/host.h"

#include <memory>
#include <string>

namespace drm_meshlab {

drm::Progress progressTo(vcg::CallBackPos* cb, ProgressStyle style) {
    if (cb == nullptr) return drm::Progress();
    if (style == ProgressStyle::Lines) {
        // meshlabserver keeps the last percentage in a static and ignores a
        // call repeating it, so each line gets a number of its own, counted
        // across every operation of the process.
        static int calls = 0;
        auto lastStage = std::make_shared<std::string>();
        return [cb, lastStage](double /*fraction*/, const char* stage) {
            const std::string label = stage != nullptr ? stage : "";
            if (label.empty() || label == *lastStage) return true;
            *lastStage = label;
            calls = (calls + 1) % 1000000;
            return cb(calls, ("drm: " + label + "\n").c_str());
        };
    }
    // Shared, because std::function copies its target.
    auto lastPercent = std::make_shared<int>(-1);
    return [cb, lastPercent](double fraction, const char* stage) {
        const int percent = fraction <= 0 ? 0 : (fraction >= 1 ? 100 : int(fraction * 100.0));
        if (percent == *lastPercent) return true;
        *lastPercent = percent;
        return cb(percent, stage != nullptr ? stage : "");
    };
}

drm::Progress progressTo(vcg::CallBackPos* cb) {
    return progressTo(cb, inMeshlabserver() ? ProgressStyle::Lines : ProgressStyle::StatusBar);
}

}  // namespace drm_meshlab
