#include "session/interaction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace psb::app {

void SpawnSettings::changeSize(int steps) {
    if (fixedMass) {
        size = typicalMass > 0.0 ? *fixedMass / typicalMass : 1.0;
        fixedMass.reset();
    }
    // Whole tenths, so that ten presses up and ten down come back to exactly where they began.
    const double tenths = std::round(size / kSizeStep) + steps;
    size = std::clamp(tenths * kSizeStep, kMinSize, kMaxSize);
}

Color SpawnSettings::color() const {
    if (fixedColor) return *fixedColor;
    const double s = typicalMass > 0.0 ? mass() / typicalMass : size;
    const double t = std::clamp((s - kMinSize) / (kMaxSize - kMinSize), 0.0, 1.0);
    return {static_cast<std::uint8_t>(120 + 135 * t), 200,
            static_cast<std::uint8_t>(255 - 135 * t)};
}

namespace {

struct Disc {
    double x, y, r;
};

bool fitsInBox(const World& world, double radius) {
    const WorldDef& d = world.def();
    return !d.walls || (2.0 * radius <= d.width && 2.0 * radius <= d.height);
}

Vec2 clampIntoBox(const World& world, const Vec2& p, double radius) {
    const WorldDef& d = world.def();
    if (!d.walls) return p;
    return {std::clamp(p.x(), radius, d.width - radius),
            std::clamp(p.y(), radius, d.height - radius)};
}

bool insideBox(const World& world, const Vec2& p, double radius) {
    const WorldDef& d = world.def();
    if (!d.walls) return true;
    return p.x() >= radius && p.x() <= d.width - radius && p.y() >= radius &&
           p.y() <= d.height - radius;
}

/// Whether a disc of `radius` at `p` overlaps none of the discs `near` and no obstacle.
bool isFree(const std::vector<Disc>& near, const Obstacles& obstacles, const Vec2& p,
            double radius) {
    for (const Disc& d : near) {
        const double dx = p.x() - d.x, dy = p.y() - d.y, reach = radius + d.r;
        if (dx * dx + dy * dy < reach * reach) return false;
    }
    // A new particle inside a peg or a wall would be stuck there, impaled (the exact mode keeps
    // a placed overlap as it was placed).
    for (const Obstacle& o : obstacles)
        if (!o.clears(p, radius)) return false;
    return true;
}

}  // namespace

std::optional<Vec2> findFreeSpot(const World& world, const Vec2& desired, double radius) {
    if (!(radius > 0.0) || !desired.allFinite() || !fitsInBox(world, radius)) return std::nullopt;
    const Vec2 start = clampIntoBox(world, desired, radius);

    // Rings every half radius out to kRings half-radii; only particles that could touch a
    // candidate on those rings are tested, so a spawn in a crowded world stays cheap.
    constexpr int kRings = 40;
    const double step = 0.5 * radius;
    const double searchRadius = kRings * step;
    const ParticleArrays& p = world.particles();
    double maxR = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        maxR = std::max(maxR, p.radius[i]);
    const double reach = searchRadius + radius + maxR;
    std::vector<Disc> near;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double dx = p.x[i] - start.x(), dy = p.y[i] - start.y();
        if (dx * dx + dy * dy < reach * reach) near.push_back({p.x[i], p.y[i], p.radius[i]});
    }

    const Obstacles& obstacles = world.obstacles();
    if (isFree(near, obstacles, start, radius)) return start;
    for (int k = 1; k <= kRings; ++k) {
        const double ringR = k * step;
        const int n = std::max(8, static_cast<int>(std::ceil(2.0 * std::numbers::pi * k)));
        // Of the free candidates on this ring, the one nearest the desired point (they differ
        // only when the desired point was clamped into the box).
        std::optional<Vec2> best;
        double bestD = 0.0;
        for (int a = 0; a < n; ++a) {
            const double t = 2.0 * std::numbers::pi * a / n;
            const Vec2 c = start + ringR * Vec2(std::cos(t), std::sin(t));
            if (!insideBox(world, c, radius) || !isFree(near, obstacles, c, radius)) continue;
            const double d = (c - desired).squaredNorm();
            if (!best || d < bestD) {
                best = c;
                bestD = d;
            }
        }
        if (best) return best;
    }
    return std::nullopt;
}

namespace {

/// The median of `values`, or `fallback` when there are none or it is not a positive number.
double medianOr(std::vector<double> values, double fallback) {
    if (values.empty()) return fallback;
    const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid > 0.0 && std::isfinite(*mid) ? *mid : fallback;
}

}  // namespace

void followScene(SpawnSettings& spawn, const World& world) {
    const ParticleArrays& p = world.particles();
    const WorldDef& d = world.def();
    std::vector<double> masses(p.mass.begin(), p.mass.end());
    std::vector<double> radii(p.radius.begin(), p.radius.end());
    // A scene that starts empty but for its ball droppers is at the scale of their balls.
    if (masses.empty()) {
        for (const Dropper& dropper : world.droppers()) {
            masses.push_back(dropper.mass);
            radii.push_back(dropper.radius);
        }
    }
    spawn.typicalMass = medianOr(std::move(masses), 10.0);
    spawn.typicalRadius = medianOr(std::move(radii), 25.0 * std::min(d.width, d.height) / 700.0);
    // A mass or radius chosen for another scene would not fit this one; a colour still does.
    spawn.fixedMass.reset();
    spawn.fixedRadius.reset();
    // New particles are made like the scene's: a scene of grains set not to turn gets more.
    spawn.turn = !(p.rotation && p.size() > 0 &&
                   std::all_of(p.fixedRotation.begin(), p.fixedRotation.end(),
                               [](std::uint8_t fixed) { return fixed != 0; }));
}

double maxLaunchSpeed(const WorldDef& def) {
    return kMaxLaunchBoxesPerSecond * std::max(def.width, def.height);
}

CappedVelocity capSpeed(const Vec2& v, double maxSpeed) {
    const double speed = v.norm();
    if (maxSpeed > 0.0 && speed > maxSpeed) return {v * (maxSpeed / speed), true};
    return {v, false};
}

std::string deletionLogLine(const Particle& p, const Axes& axes) {
    const Vec2 at = axes.point(p.position), v = axes.vector(p.velocity);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "[I] Deleted particle at [%.2f, %.2f] with x velocity %.2f m/s, y velocity "
                  "%.2f m/s and mass %.2f kg!",
                  at.x(), at.y(), v.x(), v.y(), p.mass);
    return buf;
}

void Interaction::record(const Vec2& point, double time) {
    if (!point.allFinite() || !std::isfinite(time)) return;
    // launchVelocity needs non-decreasing times; a sample from the past is dropped.
    if (!samples_.empty() && time < samples_.back().time) return;
    travel_ = std::max(travel_, (point - pressPoint_).norm());
    samples_.push_back({time, point});
    while (samples_.size() > 2 && samples_.back().time - samples_.front().time > kHistorySeconds) {
        samples_.pop_front();
    }
}

std::optional<ParticleId> Interaction::press(const World& world, const Vec2& point, double time,
                                             bool grab) {
    if (mode_ != Mode::Idle) return std::nullopt;  // a second press while one is active is ignored
    samples_.clear();
    pressPoint_ = point;
    pressTime_ = time;
    travel_ = 0.0;
    record(point, time);
    if (const auto id = grab ? world.pick(point) : std::nullopt) {
        held_ = *id;
        const Particle p = world.get(*id);
        grabOffset_ = p.position - point;
        velocityAtPress_ = p.velocity;
        mode_ = Mode::Holding;
        return id;
    }
    mode_ = Mode::Launching;
    return std::nullopt;
}

void Interaction::moveTo(const Vec2& point, double time) {
    if (mode_ == Mode::Idle) return;
    record(point, time);
}

Vec2 Interaction::pointer() const {
    return samples_.empty() ? pressPoint_ : samples_.back().position;
}

Vec2 Interaction::handVelocity(double now, const LaunchSettings& launch) const {
    std::vector<TrajectorySample> s(samples_.begin(), samples_.end());
    if (!s.empty() && now > s.back().time) s.push_back({now, s.back().position});
    return launchVelocity(s, launch);
}

std::optional<Interaction::Hold> Interaction::hold(const World& world, double now,
                                                   const LaunchSettings& launch) const {
    if (mode_ != Mode::Holding || !world.contains(held_)) return std::nullopt;
    const double r = world.get(held_).radius;
    const Vec2 target = fitsInBox(world, r) ? clampIntoBox(world, pointer() + grabOffset_, r)
                                            : Vec2(pointer() + grabOffset_);
    return Hold{held_, target, handVelocity(now, launch)};
}

CappedVelocity Interaction::launchVelocityNow(const LaunchSettings& launch,
                                              double launchSeconds) const {
    const Vec2 drag = pointer() - pressPoint_;
    if (!(launchSeconds > 0.0) || drag.norm() < launch.minDistance) return {};
    return capSpeed(drag / launchSeconds, launch.maxSpeed);
}

ReleaseResult Interaction::release(const World& world, const Vec2& point, double time,
                                   const SpawnSettings& spawn, const LaunchSettings& launch,
                                   double launchSeconds) {
    ReleaseResult result;
    if (mode_ == Mode::Idle) return result;
    LaunchSettings uncapped = launch;
    uncapped.maxSpeed = 0.0;
    // A release where the last move left the pointer is no sample of the hand's speed. A page
    // drawing slow frames delivers one move a frame and the release a frame or more after the
    // last (a finger's lift is not rAF-aligned, and SDL keeps no position of its own for it):
    // measured up to the release, the window would hold the last move alone, and a quick fling
    // read as a hand at rest. Let go within the time the pointer takes to report (the launch
    // window, widened by its spacing), the hand had the speed of its last moves; a hand that
    // stayed still longer than that was seen to stop, and lets go at rest.
    Vec2 velocity = Vec2::Zero();
    bool stopped = false;
    if (!samples_.empty() && point == samples_.back().position) {
        const std::vector<TrajectorySample> moves(samples_.begin(), samples_.end());
        stopped = time - moves.back().time > launchWindow(moves, uncapped);
        velocity = stopped ? Vec2::Zero() : launchVelocity(moves, uncapped);
        record(point, time);
    } else {
        record(point, time);
        velocity = handVelocity(time, uncapped);
    }
    const CappedVelocity hand = capSpeed(velocity, launch.maxSpeed);
    const bool click = travel_ < launch.minDistance && time - pressTime_ <= kClickSeconds;
    const std::optional<Hold> held = hold(world, time, launch);
    if (click) {
        result.kind = ReleaseResult::Kind::Clicked;
        result.position = pressPoint_;
        if (held) {
            result.id = held_;
            result.letGo = true;
            result.position = held->position;
            result.velocity = velocityAtPress_;
        }
    } else if (held) {
        result.kind = ReleaseResult::Kind::Flung;
        result.id = held_;
        result.letGo = true;
        result.position = held->position;
        result.velocity = hand.velocity;
        result.capped = hand.capped;
        result.handStopped = stopped || hand.velocity.isZero();
        result.velocityBefore = velocityAtPress_;
    } else if (mode_ == Mode::Launching) {
        if (const auto spot = findFreeSpot(world, pressPoint_, spawn.radius())) {
            const CappedVelocity launched = launchVelocityNow(launch, launchSeconds);
            result.kind = ReleaseResult::Kind::Launched;
            result.launch.position = *spot;
            result.launch.velocity = launched.velocity;
            result.launch.mass = spawn.mass();
            result.launch.radius = spawn.radius();
            result.launch.color = spawn.color();
            result.launch.fixedRotation = !spawn.turn;
            result.position = *spot;
            result.velocity = launched.velocity;
            result.capped = launched.capped;
        } else {
            result.kind = ReleaseResult::Kind::Refused;
            result.position = pressPoint_;
            result.message = "No room for a new particle here";
        }
    }
    reset();
    return result;
}

void Interaction::reset() {
    mode_ = Mode::Idle;
    held_ = kNullParticle;
    grabOffset_ = Vec2::Zero();
    travel_ = 0.0;
    velocityAtPress_ = Vec2::Zero();
    samples_.clear();
}

}  // namespace psb::app
