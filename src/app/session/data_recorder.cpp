#include "session/data_recorder.hpp"

#include <algorithm>

namespace psb::app {
namespace {

/// The collision rate of `s` since `previous`, 1/s (TimeSeries's rule).
double rateSince(const ObservablesSample& previous, const ObservablesSample& s) {
    if (!(s.time > previous.time) || s.collisions < previous.collisions) return 0.0;
    return static_cast<double>(s.collisions - previous.collisions) / (s.time - previous.time);
}

}  // namespace

void DataRecorder::restart(World& world) {
    run_.clear();
    runStride_ = 1;
    runSkipped_ = 0;
    stop(world);
    trajectory_ = Trajectory();
    collisions_.clear();
}

void DataRecorder::restartRun(World& world) {
    run_.clear();
    runStride_ = 1;
    runSkipped_ = 0;
    stop(world);
}

void DataRecorder::sample(const ObservablesSample& s) {
    if (!run_.empty() && s.time < run_.back().time) dropAfter(s.time);
    if (!run_.empty() && s.time == run_.back().time) {
        // Nothing stepped, but the world may have changed (particles placed before Play): the
        // row for this time is the state as last seen.
        ObservablesSample kept = s;
        kept.collisionRate = run_.size() > 1 ? rateSince(run_[run_.size() - 2], kept) : 0.0;
        run_.back() = kept;
        return;
    }
    if (!run_.empty() && ++runSkipped_ < runStride_) return;
    runSkipped_ = 0;
    ObservablesSample kept = s;
    kept.collisionRate = run_.empty() ? 0.0 : rateSince(run_.back(), kept);
    run_.push_back(kept);
    if (run_.size() < kMaxRunSamples) return;
    // Full: keep every other sample, the first (t = 0) included; rates over the longer spans.
    std::size_t out = 1;
    for (std::size_t k = 2; k < run_.size(); k += 2) {
        run_[out] = run_[k];
        run_[out].collisionRate = rateSince(run_[out - 1], run_[out]);
        ++out;
    }
    run_.resize(out);
    runStride_ *= 2;
}

void DataRecorder::start(World& world, std::vector<ParticleId> ids, int every) {
    every_ = std::clamp(every, 1, kMaxEvery);
    trajectory_ = Trajectory(ids);
    collisions_.clear();
    stopReason_.clear();
    recording_ = true;
    stepsToSample_ = every_;
    (void)world.takeCollisions();
    world.recordCollisions(CollisionLog(std::move(ids)));
    trajectory_.record(world);
}

void DataRecorder::stop(World& world) {
    recording_ = false;
    world.stopRecordingCollisions();
}

std::string DataRecorder::takeStopReason() {
    std::string r;
    r.swap(stopReason_);
    return r;
}

void DataRecorder::dropAfter(double time) {
    while (!run_.empty() && run_.back().time > time)
        run_.pop_back();
    trajectory_.dropAfter(time);
    while (!collisions_.empty() && collisions_.back().time > time)
        collisions_.pop_back();
}

void DataRecorder::beforeStep(World& world) {
    if (!recording_) {
        if (world.recordingCollisions()) world.stopRecordingCollisions();
        return;
    }
    // Whatever the world holds now was not recorded by this recording's steps (a world put
    // back by an undo, or rebuilt for a past frame, carries the log it had then).
    if (!world.recordingCollisions()) {
        world.recordCollisions(CollisionLog(trajectory_.ids()));
    } else {
        (void)world.takeCollisions();
    }
    dropAfter(world.time());
}

void DataRecorder::afterStep(World& world) {
    if (!recording_) return;
    const std::vector<Collision> more = world.takeCollisions();
    collisions_.insert(collisions_.end(), more.begin(), more.end());
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
        stop(world);
    }
}

}  // namespace psb::app
