#include "progress_bar.hpp"

#include <cstdio>
#include <string>

namespace psb::cli {

ProgressBar::ProgressBar(std::ostream& out, bool terminal, bool requested)
    : out_(out), terminal_(terminal), requested_(requested) {}

ProgressBar::~ProgressBar() {
    finish();
}

void ProgressBar::update(std::uint64_t done, std::uint64_t total) {
    if (!terminal_ || total == 0) return;
    const Clock::time_point now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (!requested_ && elapsed < kQuietSeconds) return;
    if (drawn_ && done != total && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    constexpr int kWidth = 30;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const int filled = static_cast<int>(fraction * kWidth);
    char line[160];
    std::snprintf(line, sizeof line, "\r[%s%s] %3d%%  %llu/%llu steps  %.1f s",
                  std::string(static_cast<std::size_t>(filled), '#').c_str(),
                  std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(),
                  static_cast<int>(fraction * 100.0), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total), elapsed);
    out_ << line << std::flush;
    drawn_ = true;
}

void ProgressBar::finish() {
    if (drawn_) out_ << '\n' << std::flush;
    drawn_ = false;
}

}  // namespace psb::cli
