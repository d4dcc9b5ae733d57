#include "session/data_recorder.hpp"

#include <algorithm>

namespace psb::app {
void DataRecorder::restartRun() {
    run_.clear();
    runStride_ = 1;
    runSkipped_ = 0;
    stop();
}

void DataRecorder::sample(const ObservablesSample& s) {
    if (!run_.empty() && s.time < run_.back().time) {
        // The plots' series follows the world back; a recording does only while it goes on
        // (a stopped one is whole, to export, until the next starts).
        dropRunAfter(s.time);
        if (recording_) dropAfter(s.time);
    }
    if (!run_.empty() && s.time == run_.back().time) {
        // Nothing stepped, but the world may have changed (particles placed before Play): the
        // row for this time is the state as last seen.
        run_.back() = s;
        return;
    }
    if (!run_.empty() && ++runSkipped_ < runStride_) return;
    runSkipped_ = 0;
    run_.push_back(s);
    if (run_.size() < kMaxRunSamples) return;
    // Full: keep every other sample, the first (t = 0) included. Each keeps its collision
    // rate, which counts over a window of simulated time, not since the row before.
    std::size_t out = 1;
    for (std::size_t k = 2; k < run_.size(); k += 2)
        run_[out++] = run_[k];
    run_.resize(out);
    runStride_ *= 2;
}

void DataRecorder::start(const World& world, std::vector<ParticleId> ids, int every) {
    every_ = std::clamp(every, 1, kMaxEvery);
    trajectory_ = Trajectory(ids);
    collisions_.clear();
    stopReason_.clear();
    recordedHeight_ = world.def().height;
    recordedRotation_ = world.rotationInUse();
    recording_ = true;
    stepsToSample_ = every_;
    trajectory_.record(world);
}

void DataRecorder::stop() {
    recording_ = false;
}

std::string DataRecorder::takeStopReason() {
    std::string r;
    r.swap(stopReason_);
    return r;
}

void DataRecorder::dropRunAfter(double time) {
    while (!run_.empty() && run_.back().time > time)
        run_.pop_back();
}

void DataRecorder::dropAfter(double time) {
    trajectory_.dropAfter(time);
    while (!collisions_.empty() && collisions_.back().time > time)
        collisions_.pop_back();
}

std::optional<CollisionLog> DataRecorder::collisionsWanted() const {
    if (!recording_) return std::nullopt;
    return CollisionLog(trajectory_.ids());
}

void DataRecorder::beforeStep(const World& world) {
    if (!recording_) return;
    dropRunAfter(world.time());
    dropAfter(world.time());
}

void DataRecorder::afterStep(const World& world, const std::vector<Collision>& heard) {
    if (!recording_) return;
    const CollisionLog chosen(trajectory_.ids());
    for (const Collision& c : heard) {
        if (chosen.chosen(c.a) || (!c.b.isNull() && chosen.chosen(c.b))) collisions_.push_back(c);
    }
    if (--stepsToSample_ <= 0) {
        stepsToSample_ = every_;
        trajectory_.record(world);
    }
    if (trajectory_.full() || collisions_.size() >= kMaxCollisions) {
        stopReason_ = trajectory_.full()
                          ? "the trajectories reached their limit of " +
                                std::to_string(trajectory_.samples().size()) + " samples"
                          : "the collision log reached its limit of " +
                                std::to_string(collisions_.size()) + " collisions";
        stop();
    }
}

}  // namespace psb::app
