#pragma once
// Where the exact stepper's resolved collisions go: its own log, for tests and diagnostics
// (CollisionRecord: stepper indices mapped to storage indices, times on the stepper's clock),
// and the world's record (collision_log.hpp: ids, velocities, impulses, times on the world's
// clock). Neither is state: the world sets them before a step.

#include <cstdint>
#include <vector>

#include <particle_sandbox/collision_log.hpp>

namespace psb::exact {

/// One resolved collision, for tests and diagnostics. `j` is a particle index for a pair,
/// kWall + w for wall w (0 = left, 1 = right, 2 = top, 3 = bottom), or kObstacle + k for the
/// world's obstacle k.
struct CollisionRecord {
    static constexpr std::uint32_t kWall = UINT32_MAX - 3;
    static constexpr std::uint32_t kObstacle = 1u << 31;  ///< particle indices stay below it
    double time;  ///< seconds since the stepper's last rebuild
    std::uint32_t i;
    std::uint32_t j;
};

class CollisionRecorder {
  public:
    /// Appends every resolved collision to `log` (nullptr to stop).
    void setLog(std::vector<CollisionRecord>* log) { log_ = log; }
    /// The world's record for the next step (nullptr for none); `worldTime` is World::time() at
    /// its start, the clock the records' times are on.
    void setWorldLog(CollisionLog* log, double worldTime) {
        worldLog_ = log;
        worldTime_ = worldTime;
    }
    /// At the start of a step: the stepper's clock reads `clock` (it restarts at each rebuild).
    void startStep(double clock) { offset_ = worldTime_ - clock; }

    /// Whether anyone keeps a record.
    [[nodiscard]] bool on() const { return log_ != nullptr || worldLog_ != nullptr; }
    /// A resolved collision: `r` into the log; `collision(t)` makes the world's record of it at
    /// the world's time t, called only when the world keeps one.
    template <typename Make>
    void add(const CollisionRecord& r, Make&& collision) {
        if (log_) log_->push_back(r);
        if (worldLog_) worldLog_->add(collision(offset_ + r.time));
    }

  private:
    std::vector<CollisionRecord>* log_ = nullptr;
    CollisionLog* worldLog_ = nullptr;
    double worldTime_ = 0.0;
    double offset_ = 0.0;  // the world's time minus the stepper's clock
};

}  // namespace psb::exact
