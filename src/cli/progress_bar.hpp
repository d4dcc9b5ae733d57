#pragma once
// A progress bar on stderr for long headless runs.

#include <chrono>
#include <cstdint>
#include <ostream>

namespace psb::cli {

/// Draws `[#####.....]  45%  450/1000 steps  3.1 s` on one line, redrawn at most ten times a
/// second. Shown only on a terminal, and only when asked for or once the run has taken longer
/// than `kQuietSeconds`: short runs and redirected stderr stay clean.
class ProgressBar {
  public:
    static constexpr double kQuietSeconds = 2.0;

    ProgressBar(std::ostream& out, bool terminal, bool requested);
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;
    ~ProgressBar();

    void update(std::uint64_t done, std::uint64_t total);
    /// Ends the bar's line (if one was drawn).
    void finish();

  private:
    using Clock = std::chrono::steady_clock;
    std::ostream& out_;
    bool terminal_;
    bool requested_;
    bool drawn_ = false;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDraw_{};
};

}  // namespace psb::cli
