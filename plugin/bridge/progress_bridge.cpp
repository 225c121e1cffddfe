#include "bridge/progress_bridge.h"

#include "bridge/host.h"

#include <memory>
#include <set>
#include <string>

namespace drm_meshlab {

drm::Progress progressTo(vcg::CallBackPos* cb, ProgressStyle style) {
    if (style == ProgressStyle::Lines) {
        // Each stage once per operation: the encoder goes through some stages
        // once per attempt (both predictors, say), which reads as repetition.
        auto stagesSeen = std::make_shared<std::set<std::string>>();
        return [cb, stagesSeen](double /*fraction*/, const char* stage) {
            const std::string label = stage != nullptr ? stage : "";
            if (label.empty() || !stagesSeen->insert(label).second) return true;
            const std::string line = "drm: " + label;
            // meshlabserver opens and saves with no callback: the line goes
            // where it prints the IO plugin's other words.
            if (cb == nullptr) {
                printToServerOutput(line);
                return true;
            }
            // meshlabserver keeps the last percentage in a static and ignores
            // a call repeating it, so each line gets a number of its own,
            // counted across every operation of the process.
            static int calls = 0;
            calls = (calls + 1) % 1000000;
            return cb(calls, (line + "\n").c_str());
        };
    }
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

drm::Progress progressTo(vcg::CallBackPos* cb) {
    return progressTo(cb, inMeshlabserver() ? ProgressStyle::Lines : ProgressStyle::StatusBar);
}

}  // namespace drm_meshlab
