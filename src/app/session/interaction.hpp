#pragma once
// What the left mouse button does to the world, kept free of SDL so it can be tested without a
// window. The app feeds it world-space pointer positions with timestamps; it grabs, moves,
// flings, launches and deletes particles through World's id-based API.
//
// Fixes to the original's mouse handling, each covered by a test:
// - Grabbing is edge-triggered: only the press grabs, and only the topmost particle under the
//   pointer (World::pick, in world units, so the whole disc is grabbable at every zoom).
// - The grab offset is kept: the particle does not jump to the cursor, and its velocity is the
//   pointer's velocity, so an off-centre grab does not drift after release.
// - The held particle is kinematic: collisions cannot push it, it pushes others with the
//   velocity of the hand, and the world keeps it inside the box.
// - A held particle is flung with the hand's velocity: psb::launchVelocity over the last ~100 ms
//   of samples, so a particle dropped after the hand stopped is released at rest. A release where
//   the last move left the pointer (a finger's lift, reported late by a slow page) flings with the
//   speed of the moves before it unless it came longer than the pointer's reporting takes after
//   them (psb::launchWindow): a finger and a mouse on the same path fling alike.
// - A new particle is launched like the original's launch vector: its velocity is the drag from
//   the press point to the release point divided by a launch time (the app passes the arrow
//   scale, so the preview line from the ghost disc to the pointer is exactly the velocity arrow
//   the particle will have). Dragging out and stopping still launches it.
// - Both speeds are capped at LaunchSettings::maxSpeed; ReleaseResult::capped says when the cap
//   applied, so the app can say so.
//
// A click (press and release within kClickSeconds, the pointer never further from the press
// point than the launch's minDistance, the same 4-pixel threshold that decides "at rest") is
// not a drag: on a particle it selects it and gives back the velocity it had at the press, so
// inspecting a moving particle does not stop it; on empty space it launches nothing (the app
// clears the selection). A longer still press keeps the old meaning: a particle is released at
// rest, and empty space gets a particle at rest.

#include <deque>
#include <optional>
#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/launch.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

/// What a newly launched particle is made of; the HUD shows it and keys change it. Its mass
/// and radius follow the scene: `size` times the scene's typical particle (the median mass and
/// the median radius), so a launch into a Galton board is a grain and into the default scene a
/// ball of about 10 kg. `[` and `]` change `size` in steps of a tenth, from a tenth to four
/// times (the original's 1..40 kg around 10 kg; radius and mass grow together, as in the
/// original's 2.5 length units per kg).
struct SpawnSettings {
    static constexpr double kMinSize = 0.1;
    static constexpr double kMaxSize = 4.0;
    static constexpr double kSizeStep = 0.1;
    double typicalMass = 10.0;    ///< kg
    double typicalRadius = 25.0;  ///< metres
    double size = 1.0;            ///< times the typical particle
    /// Set from the control panel: a fixed mass (kg), radius (m) or colour instead of the
    /// rule. A fixed mass with the radius left to the rule gives the radius of the typical
    /// particle times the mass ratio (radius and mass grow together, as `size` makes them).
    std::optional<double> fixedMass;
    std::optional<double> fixedRadius;
    std::optional<Color> fixedColor;
    /// New particles turn (friction spins them); false: fixed rotation, they slide without
    /// turning. A scene whose particles all have fixed rotation makes it false.
    bool turn = true;
    [[nodiscard]] double mass() const { return fixedMass ? *fixedMass : size * typicalMass; }
    [[nodiscard]] double radius() const {
        if (fixedRadius) return *fixedRadius;
        return fixedMass ? typicalRadius * (*fixedMass / typicalMass) : size * typicalRadius;
    }
    /// fixedColor, else a colour from the size, light enough to read on black.
    [[nodiscard]] Color color() const;
    /// `steps` tenths bigger (negative: smaller), kept in [kMinSize, kMaxSize]; a fixed mass
    /// becomes the size it has and is stepped from there.
    void changeSize(int steps);
};

/// The typical particle of `world` (see SpawnSettings): the median mass and the median radius
/// of its particles; in an empty world 10 kg and 25 m per 700 m of the smaller box side (the
/// original's particle, so a 7 m box gives the original's particles at 1 px = 1 cm).
void followScene(SpawnSettings& spawn, const World& world);

/// Flings and launches faster than this many box widths (the larger side) per second are cut to
/// it: faster is a slip of the hand, and would cross the box in a handful of steps.
inline constexpr double kMaxLaunchBoxesPerSecond = 2.0;
/// kMaxLaunchBoxesPerSecond for a box `def`, m/s.
[[nodiscard]] double maxLaunchSpeed(const WorldDef& def);

/// A free place for a disc of `radius` metres near `desired`: `desired` itself (clamped into
/// the box when walls are on) if no particle overlaps it there, otherwise the nearest free spot
/// found on rings of growing radius around it (within about 20 radii). nullopt when there is
/// none, or when the disc does not fit in the box at all.
[[nodiscard]] std::optional<Vec2> findFreeSpot(const World& world, const Vec2& desired,
                                               double radius);

/// The line the original printed when a held particle was deleted, with units, in `axes`.
[[nodiscard]] std::string deletionLogLine(const Particle& p, const Axes& axes);

/// What a release means. The hand only reads the world: the tools' handler has the document, the
/// world's owner, apply the result, and reports it for undo (tools_hand.cpp).
struct ReleaseResult {
    enum class Kind {
        None,      ///< nothing was held or being launched
        Flung,     ///< let the held particle `id` go at `position` with `velocity`
        Launched,  ///< add `launch`, a new particle at `position` with `velocity`
        Refused,   ///< no free spot for the new particle; `message` says so
        Clicked,   ///< a click: on the particle `id`, or on empty space when `id` is null; a
                   ///< held particle is let go at `position` with `velocity` as it had before
    };
    Kind kind = Kind::None;
    ParticleId id;
    Vec2 position = Vec2::Zero();  ///< metres
    Vec2 velocity = Vec2::Zero();  ///< m/s
    bool capped = false;           ///< the speed was cut to LaunchSettings::maxSpeed
    ParticleDef launch;            ///< Launched: the particle to add
    std::string message;
    /// The particle `id` was held (Flung, or Clicked with the Fling tool): it is let go at
    /// `position` with `velocity` and is free again.
    bool letGo = false;
    /// Flung: the hand had stopped (`velocity` is zero: it was put down, not thrown).
    bool handStopped = false;
    /// The held particle's velocity when the hand took it, m/s.
    Vec2 velocityBefore = Vec2::Zero();
};

/// `v` cut to `maxSpeed` (m/s) when longer and maxSpeed > 0; `capped` says whether it was.
struct CappedVelocity {
    Vec2 velocity = Vec2::Zero();
    bool capped = false;
};
[[nodiscard]] CappedVelocity capSpeed(const Vec2& v, double maxSpeed);

class Interaction {
  public:
    enum class Mode { Idle, Holding, Launching };

    /// How long pointer samples are kept, seconds (longer than any launch window).
    static constexpr double kHistorySeconds = 0.5;
    /// Longest press that can still be a click, seconds.
    static constexpr double kClickSeconds = 0.3;

    /// The left button went down at `point` (world metres) at `time` (seconds, any clock that
    /// the later calls share). Grabs the topmost particle there (unless `grab` is false): its
    /// id, which the caller makes kinematic while it is held; or starts a launch drag (nullopt).
    std::optional<ParticleId> press(const World& world, const Vec2& point, double time,
                                    bool grab = true);
    /// The pointer is now at `point` (a motion, or the camera moved under a still pointer).
    void moveTo(const Vec2& point, double time);
    /// Where the hand holds a particle: its id, the pointer + grab offset (kept in the box) and
    /// the hand's current velocity. nullopt when nothing held is in `world`.
    struct Hold {
        ParticleId id;
        Vec2 position = Vec2::Zero();
        Vec2 velocity = Vec2::Zero();
    };
    [[nodiscard]] std::optional<Hold> hold(const World& world, double now,
                                           const LaunchSettings& launch) const;
    /// The left button went up: what it means (see ReleaseResult). A launch gives the new
    /// particle (release - press) / `launchSeconds`. The hand is idle after it.
    ReleaseResult release(const World& world, const Vec2& point, double time,
                          const SpawnSettings& spawn, const LaunchSettings& launch,
                          double launchSeconds);
    /// The velocity a launch released at the current pointer would give (zero for a drag
    /// shorter than launch.minDistance), capped like release() caps it.
    [[nodiscard]] CappedVelocity launchVelocityNow(const LaunchSettings& launch,
                                                   double launchSeconds) const;
    /// Forgets everything (the world was replaced). Does not touch any world.
    void reset();

    [[nodiscard]] Mode mode() const { return mode_; }
    [[nodiscard]] ParticleId held() const { return held_; }
    /// The pointer went further from the press than a click may (`launch.minDistance`): the
    /// press is a drag.
    [[nodiscard]] bool dragged(const LaunchSettings& launch) const {
        return mode_ != Mode::Idle && travel_ >= launch.minDistance;
    }
    /// Where the current press happened, metres.
    [[nodiscard]] const Vec2& pressPoint() const { return pressPoint_; }
    /// The latest pointer position, metres.
    [[nodiscard]] Vec2 pointer() const;
    /// The hand's velocity at `now` (m/s): launchVelocity over the samples plus the pointer's
    /// position at `now`, so a hand that stopped has zero velocity.
    [[nodiscard]] Vec2 handVelocity(double now, const LaunchSettings& launch) const;

  private:
    void record(const Vec2& point, double time);

    Mode mode_ = Mode::Idle;
    ParticleId held_;
    Vec2 grabOffset_ = Vec2::Zero();
    Vec2 pressPoint_ = Vec2::Zero();
    double pressTime_ = 0.0;               ///< seconds
    double travel_ = 0.0;                  ///< farthest the pointer went from the press point, m
    Vec2 velocityAtPress_ = Vec2::Zero();  ///< of the held particle, m/s
    std::deque<TrajectorySample> samples_;
};

}  // namespace psb::app
