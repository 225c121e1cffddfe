// Throttled progress reporting and cancellation for long encodes and decodes.
// The fraction reported never falls: the encoder's later attempts start
// their stages again from low fractions, and a progress bar must not run
// backwards.
#ifndef DRM_PROGRESS_H
#define DRM_PROGRESS_H

#include "drmcodec/drmcodec.h"

namespace drm {

class ProgressReporter {
public:
    explicit ProgressReporter(const Progress& callback) : callback_(callback) {}

    void stage(const char* name, double fraction) {
        stage_ = name;
        report(fraction);
    }

    // Called once per coded edge; reports every few thousand calls only.
    void tick(double fraction) {
        if (callback_ && ++ticks_ % 4096 == 0) report(fraction);
    }
    // The same, with the fraction worked out only when it is reported.
    template <class Fraction>
    void tickWith(Fraction fraction) {
        if (callback_ && ++ticks_ % 4096 == 0) report(fraction());
    }

private:
    void report(double fraction) {
        if (fraction > highest_) highest_ = fraction;
        if (callback_ && !callback_(highest_, stage_)) throw Error(ErrorKind::Cancelled, "cancelled");
    }

    const Progress& callback_;
    const char* stage_ = "";
    unsigned ticks_ = 0;
    double highest_ = 0;
};

}  // namespace drm

#endif  // DRM_PROGRESS_H
