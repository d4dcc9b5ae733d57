#include "session/lab_stopwatch.hpp"

#include <cstdio>

namespace psb::app {

void LabStopwatch::start(double now) {
    if (running()) return;
    if (!start_) {
        start_ = now;
    } else if (stoppedAt_ && now > *stoppedAt_) {
        *start_ += now - *stoppedAt_;  // the time it was stopped does not count
    }
    stoppedAt_.reset();
}

void LabStopwatch::stop(double now) {
    if (running()) stoppedAt_ = now;
}

void LabStopwatch::lap(double now) {
    if (!running()) return;
    if (laps_.size() == kMaxLaps) laps_.erase(laps_.begin());
    laps_.push_back(reading(now));
}

void LabStopwatch::reset() {
    start_.reset();
    stoppedAt_.reset();
    laps_.clear();
}

double LabStopwatch::reading(double now) const {
    if (!start_) return 0.0;
    return (stoppedAt_ ? *stoppedAt_ : now) - *start_;
}

std::string stopwatchLine(const LabStopwatch& watch, double now, bool touch) {
    if (!watch.used()) return {};
    char buf[160];
    if (watch.beforeStart(now)) {
        std::snprintf(buf, sizeof buf, "Stopwatch: time went back %.3f s before its start (%s)",
                      -watch.reading(now), touch ? "Time: stopwatch Reset" : "Shift+U resets");
        return buf;
    }
    std::snprintf(buf, sizeof buf, "Stopwatch %.3f s%s", watch.reading(now),
                  watch.running() ? "" : " (stopped)");
    std::string line = buf;
    if (!watch.laps().empty()) {
        std::snprintf(buf, sizeof buf, " | lap %zu: %.3f s", watch.laps().size(),
                      watch.laps().back());
        line += buf;
    }
    return line;
}

}  // namespace psb::app
