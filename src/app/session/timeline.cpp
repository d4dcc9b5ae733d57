#include "session/timeline.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "session/frame_step.hpp"

namespace psb::app {

Timeline::Timeline(const TimelineSettings& settings) : settings_(settings) {
    if (!(settings_.horizonSeconds > 0.0)) {
        throw std::invalid_argument("Timeline: horizon must be > 0 seconds (got " +
                                    std::to_string(settings_.horizonSeconds) + ")");
    }
    if (settings_.budgetBytes == 0) throw std::invalid_argument("Timeline: budget must be > 0");
    if (!(settings_.minSpacingSeconds >= 0.0) ||
        settings_.minSpacingSeconds > settings_.horizonSeconds) {
        throw std::invalid_argument("Timeline: the least keyframe spacing must be in [0, horizon]");
    }
    spacing_ = settings_.horizonSeconds;
}

void Timeline::stepped(double dt) {
    pending_.push_back({Op::Kind::Step, {}, dt, 0.0});
}

void Timeline::setPosition(World& world, ParticleId id, const Vec2& position) {
    world.setPosition(id, position);
    pending_.push_back({Op::Kind::SetPosition, id, position.x(), position.y()});
    pendingReplayable_ = true;
}

void Timeline::setVelocity(World& world, ParticleId id, const Vec2& velocity) {
    world.setVelocity(id, velocity);
    pending_.push_back({Op::Kind::SetVelocity, id, velocity.x(), velocity.y()});
    pendingReplayable_ = true;
}

void Timeline::setKinematic(World& world, ParticleId id, bool kinematic) {
    world.setKinematic(id, kinematic);
    pending_.push_back({Op::Kind::SetKinematic, id, kinematic ? 1.0 : 0.0, 0.0});
    pendingReplayable_ = true;
}

void Timeline::replay(World& world, const std::vector<Op>& log) {
    for (const Op& op : log) {
        switch (op.kind) {
            case Op::Kind::Step:
                (void)stepFrame(world, op.a);
                break;
            case Op::Kind::SetPosition:
                world.setPosition(op.id, Vec2(op.a, op.b));
                break;
            case Op::Kind::SetVelocity:
                world.setVelocity(op.id, Vec2(op.a, op.b));
                break;
            case Op::Kind::SetKinematic:
                world.setKinematic(op.id, op.a != 0.0);
                break;
        }
    }
}

void Timeline::edited() {
    pendingEdit_ = true;
}

bool Timeline::matchesReported(const World& world) const {
    const Frame& last = frames_.back();
    double t = last.time;
    for (const Op& op : pending_) {
        if (op.kind == Op::Kind::Step) t += op.a;  // World::step's additions, in its order
    }
    return t == world.time() && (pendingEdit_ || world.size() == last.particles);
}

void Timeline::storeKey(Frame& f, const World& world) {
    f.key = std::make_unique<const World>(world);
    f.keyBytes = world.stateBytes();
    bytes_ += f.keyBytes;
    ++keyframes_;
    lastKeyTime_ = f.time;
}

std::int64_t Timeline::record(const World& world) {
    if (!frames_.empty() && world.time() < frames_.back().time) restart();
    const bool honest = frames_.empty() || matchesReported(world);
    const bool advanced = !frames_.empty() && world.time() != frames_.back().time;
    if (!frames_.empty() && !advanced && !pendingEdit_ && !pendingReplayable_ && honest) {
        pending_.clear();
        return lastFrame();
    }
    if (!honest) ++unreported_;

    // The rule: room for the horizon's keyframes plus the one before it, the newest and the
    // rebuilt world of seek().
    const std::size_t keyBytes = std::max<std::size_t>(world.stateBytes(), 1);
    const std::size_t slots = settings_.budgetBytes / keyBytes;
    spacing_ = std::max(settings_.minSpacingSeconds,
                        settings_.horizonSeconds / static_cast<double>(slots > 4 ? slots - 3 : 1));

    if (!frames_.empty() && !advanced) {
        // Edits while paused (a particle dragged too): the latest frame now ends in the edited
        // state.
        Frame& f = frames_.back();
        forget(f);
        f.particles = world.size();
        storeKey(f, world);
        if (cursorFrame_ == lastFrame()) cursorFrame_ = -1;
    } else {
        Frame f;
        f.time = world.time();
        f.particles = world.size();
        const bool due =
            frames_.empty() || pendingEdit_ || !honest || world.time() - lastKeyTime_ >= spacing_;
        if (due) {
            storeKey(f, world);
        } else {
            f.log = pending_;
            bytes_ += sizeof(Op) * f.log.capacity();
        }
        frames_.push_back(std::move(f));
    }
    pending_.clear();
    pendingEdit_ = false;
    pendingReplayable_ = false;
    trim();
    return lastFrame();
}

void Timeline::forget(Frame& f) {
    bytes_ -= sizeof(Op) * f.log.capacity();
    f.log = {};
    if (f.key) {
        bytes_ -= f.keyBytes;
        --keyframes_;
        f.key.reset();
    }
}

void Timeline::restart() {
    const std::int64_t next = lastFrame() + 1;
    while (!frames_.empty()) {
        forget(frames_.back());
        frames_.pop_back();
    }
    first_ = next;  // frame numbers are never reused
    cursor_.reset();
    cursorFrame_ = -1;
}

void Timeline::dropOldest() {
    // Drops the first keyframe and the frames that replay from it, up to the next keyframe.
    do {
        forget(frames_.front());
        frames_.pop_front();
        ++first_;
    } while (!frames_.empty() && !frames_.front().key);
    if (cursorFrame_ < first_) cursorFrame_ = -1;
}

void Timeline::trim() {
    const double latest = frames_.back().time;
    while (keyframes_ >= 2) {
        std::size_t second = 1;
        while (!frames_[second].key)
            ++second;
        const bool reachesWithout = frames_[second].time <= latest - settings_.horizonSeconds;
        if (!reachesWithout && memoryBytes() <= settings_.budgetBytes) break;
        dropOldest();
    }
}

std::size_t Timeline::indexOf(std::int64_t frame) const {
    if (frames_.empty() || frame < first_ || frame > lastFrame()) {
        throw std::out_of_range("Timeline: frame " + std::to_string(frame) + " is not held (" +
                                (frames_.empty() ? std::string("none are")
                                                 : "held: " + std::to_string(first_) + " to " +
                                                       std::to_string(lastFrame())) +
                                ")");
    }
    return static_cast<std::size_t>(frame - first_);
}

double Timeline::timeOf(std::int64_t frame) const {
    return frames_[indexOf(frame)].time;
}

std::int64_t Timeline::frameAt(double seconds) const {
    if (frames_.empty()) throw std::out_of_range("Timeline: no frames");
    const auto after = std::upper_bound(frames_.begin(), frames_.end(), seconds,
                                        [](double t, const Frame& f) { return t < f.time; });
    if (after == frames_.begin()) return first_;
    return first_ + static_cast<std::int64_t>(after - frames_.begin()) - 1;
}

double Timeline::coveredSeconds() const {
    return frames_.empty() ? 0.0 : frames_.back().time - frames_.front().time;
}

const World& Timeline::seek(std::int64_t frame) {
    const std::size_t target = indexOf(frame);
    std::size_t key = target;
    while (!frames_[key].key)
        --key;  // the first frame is always a keyframe
    std::size_t at = key;
    if (cursor_ && cursorFrame_ >= first_ + static_cast<std::int64_t>(key) &&
        cursorFrame_ <= frame) {
        at = static_cast<std::size_t>(cursorFrame_ - first_);  // carry on from the last seek
    } else {
        cursor_ = std::make_unique<World>(*frames_[key].key);
    }
    lastReplayed_ = target - at;
    for (std::size_t j = at + 1; j <= target; ++j)
        replay(*cursor_, frames_[j].log);
    cursorFrame_ = frame;
    return *cursor_;
}

void Timeline::discardAfter(std::int64_t frame) {
    const std::size_t keep = indexOf(frame) + 1;
    while (frames_.size() > keep) {
        forget(frames_.back());
        frames_.pop_back();
    }
    if (cursorFrame_ > frame) {
        cursor_.reset();
        cursorFrame_ = -1;
    }
    pending_.clear();
    pendingEdit_ = false;
    pendingReplayable_ = false;
    for (std::size_t i = frames_.size(); i-- > 0;) {
        if (frames_[i].key) {
            lastKeyTime_ = frames_[i].time;
            break;
        }
    }
}

std::size_t Timeline::memoryBytes() const {
    std::size_t bytes = bytes_ + sizeof(Frame) * frames_.size() + sizeof(Op) * pending_.capacity();
    // The rebuilt world: its state and its step scratch (World::memoryBytes counts the arrays
    // again, so this errs high).
    if (cursor_) bytes += cursor_->stateBytes() + cursor_->memoryBytes();
    return bytes;
}

}  // namespace psb::app
