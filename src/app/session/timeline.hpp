#pragma once
// Step back in time: the world's recent past, kept so that a paused user can step backwards
// frame by frame and scrub over at least the last 10 s of simulated time, in every step mode.
//
// How. The step is deterministic and a World copy carries all of the world's state (the exact
// mode's event state included, world.hpp), so the past is stored as keyframes (copies of the
// world) and, for the frames between them, a log of what led there: the steps, and the edits
// made through the timeline's own setters (a held particle moved, pushed, let go). A past frame
// is rebuilt by copying the keyframe at or before it and replaying the log: the same calls on
// the same state give the state the world had then, bit for bit. Any other edit is not
// replayed: the frame it happens in is stored as a keyframe.
//
//   frames:   K  .  .  .  .  K  .  .  E  .  .  K  .  .  .      K keyframe (every `spacing` s)
//   log:         ▲ each "." holds its steps and    E keyframe forced by an edit
//                  replayable edits, in order
//   seek(f):  copy the K at or before f, replay the frames' logs up to f
//
// What the session calls:
//   after each world.step(dt) ............ stepped(dt)
//   to move, push or hold a particle ..... setPosition / setVelocity / setKinematic(world, ...)
//                                          instead of World's own (a drag then costs a few bytes
//                                          a step, not a copy of the world a frame)
//   after any other change to the world .. edited()       (spawn, delete, edit, settings,
//                                                          clear, reset, load: anything)
//   at the end of every frame ............ record(world)  (nothing is stored for a frame in
//                                                          which nothing happened)
//   to show past frame f (paused) ........ const World& w = seek(f)   (valid until the next
//                                                          seek, record or discardAfter)
//   when the user acts from frame f ...... discardAfter(f), then carry on from a copy of
//                                          seek(f): the frames after f are another future now
// Edits made while paused on the latest frame replace that frame's stored state (the frame
// before still shows the past); undoing an edit is the undo history's job, not this. A world
// whose clock went back (reset to the scene as loaded, another scene opened) starts a new
// history, numbered on from the old one: stepping back does not cross a reset (undo does).
//
// record() checks what it is told: if world.time() is not the last frame's time plus the
// reported steps, or the particle count changed with no edit reported, something changed the
// world unreported; the frame is then stored as a keyframe (so the history stays right) and
// unreportedChanges() counts it. A change made with World's own setters and not reported is
// not seen: the history would then replay without it.
//
// Memory budget (the rule). Everything the timeline holds counts: keyframes (World::stateBytes
// each), the step lists, and the one rebuilt world of seek(). Keyframes are spaced so that
// the horizon fits the budget with room for two more:
//
//   spacing = max(minSpacing, horizon / max(1, budget / keyframeBytes - 3))   simulated seconds
//
// (minSpacing, 0.1 s by default, because a keyframe per frame would make every frame pay for a
// copy of the world to save the re-simulation of a few frames when stepping back; at 60 frames
// per second it bounds a step back to re-simulating 5 frames when the budget allows)
// and after every record the oldest frames are dropped while the history would still reach
// back `horizon` seconds without them, then while the budget is exceeded (which only frequent
// edits through edited() cause: each is a keyframe). coveredSeconds() says how far back the
// history reaches.
// A step back costs one keyframe copy plus at most `spacing` seconds of re-simulation.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include <particle_sandbox/world.hpp>

namespace psb::app {

struct TimelineSettings {
    double horizonSeconds = 10.0;                  ///< simulated seconds kept, at least
    std::size_t budgetBytes = 200u * 1000 * 1000;  ///< everything the timeline holds
    double minSpacingSeconds = 0.1;  ///< simulated seconds between keyframes, at least (0: none)
};

class Timeline {
  public:
    explicit Timeline(const TimelineSettings& settings = {});

    /// The world was advanced by world.step(dt).
    void stepped(double dt);
    /// The world was changed other than by a step or the setters below.
    void edited();

    /// World::setPosition / setVelocity / setKinematic, logged so that a past frame replays
    /// them instead of needing a keyframe. They throw (and log nothing) as World's do.
    void setPosition(World& world, ParticleId id, const Vec2& position);
    void setVelocity(World& world, ParticleId id, const Vec2& velocity);
    void setKinematic(World& world, ParticleId id, bool kinematic);
    /// Ends a frame: stores what happened since the last record (nothing, when nothing did).
    /// Returns the index of the latest frame.
    std::int64_t record(const World& world);

    /// No frame recorded yet (or all discarded).
    [[nodiscard]] bool empty() const { return frames_.empty(); }
    /// Oldest and latest frame still held (indices count records since the start).
    [[nodiscard]] std::int64_t firstFrame() const { return first_; }
    [[nodiscard]] std::int64_t lastFrame() const {
        return first_ + static_cast<std::int64_t>(frames_.size()) - 1;
    }
    /// Simulated time of a held frame, seconds. Throws std::out_of_range.
    [[nodiscard]] double timeOf(std::int64_t frame) const;
    /// The latest held frame at or before `seconds` (the first frame for earlier times).
    /// Throws std::out_of_range when empty.
    [[nodiscard]] std::int64_t frameAt(double seconds) const;
    /// Simulated seconds between the first and the latest frame.
    [[nodiscard]] double coveredSeconds() const;

    /// The world as it was at the end of `frame`, rebuilt. Throws std::out_of_range for a
    /// frame not held. The reference is valid until the next seek, record or discardAfter.
    const World& seek(std::int64_t frame);
    /// Forgets the frames after `frame` (and any steps or edits reported since the last
    /// record): the world carries on from `frame`. Throws std::out_of_range.
    void discardAfter(std::int64_t frame);

    /// Bytes held: keyframes, step lists, the rebuilt world of seek().
    [[nodiscard]] std::size_t memoryBytes() const;
    /// Seconds of simulated time between scheduled keyframes, as last computed.
    [[nodiscard]] double keyframeSpacing() const { return spacing_; }
    [[nodiscard]] std::size_t keyframeCount() const { return keyframes_; }
    /// Frames stored as keyframes because record() found a change nobody reported.
    [[nodiscard]] std::uint64_t unreportedChanges() const { return unreported_; }
    /// Frames re-simulated by the last seek (0 when it was a keyframe or already built).
    [[nodiscard]] std::size_t lastSeekReplayed() const { return lastReplayed_; }

  private:
    // One logged call: a step (a = dt) or a replayable edit (a, b = the vector or the flag).
    struct Op {
        enum class Kind : std::uint8_t { Step, SetPosition, SetVelocity, SetKinematic };
        Kind kind = Kind::Step;
        ParticleId id{};
        double a = 0.0, b = 0.0;
    };
    struct Frame {
        double time = 0.0;                 // world.time() at the end of the frame
        std::size_t particles = 0;         // world.size() then
        std::vector<Op> log;               // what happened since the previous frame, in order
        std::unique_ptr<const World> key;  // a keyframe's copy of the world
        std::size_t keyBytes = 0;
    };

    [[nodiscard]] std::size_t indexOf(std::int64_t frame) const;
    [[nodiscard]] bool matchesReported(const World& world) const;
    void storeKey(Frame& f, const World& world);
    /// Takes a frame's log and keyframe out of the accounting (and frees them).
    void forget(Frame& f);
    void dropOldest();
    /// Forgets every frame: the world's clock went back.
    void restart();
    void trim();

    TimelineSettings settings_;
    std::deque<Frame> frames_;
    std::int64_t first_ = 0;
    static void replay(World& world, const std::vector<Op>& log);

    std::vector<Op> pending_;         // logged since the last record
    bool pendingReplayable_ = false;  // pending_ holds edits, not only steps
    bool pendingEdit_ = false;
    double lastKeyTime_ = 0.0;
    double spacing_ = 0.0;
    std::size_t keyframes_ = 0;
    std::size_t bytes_ = 0;  // keyframes and step lists (not the rebuilt world)
    std::uint64_t unreported_ = 0;
    // seek()'s rebuilt world and the frame it is at (-1: none).
    std::unique_ptr<World> cursor_;
    std::int64_t cursorFrame_ = -1;
    std::size_t lastReplayed_ = 0;
};

}  // namespace psb::app
