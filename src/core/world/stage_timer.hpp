#pragma once
// Times a scope into a milliseconds accumulator.

#include <chrono>

namespace psb {

class StageTimer {
  public:
    explicit StageTimer(double& accumulatorMs)
        : out_(accumulatorMs), start_(std::chrono::steady_clock::now()) {}
    ~StageTimer() {
        out_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
                    .count();
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

  private:
    double& out_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace psb
