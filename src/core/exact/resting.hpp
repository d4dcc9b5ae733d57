#pragma once
// The exact stepper's resting contacts (gravity only): when a particle falls asleep, what holds
// it up, when it wakes, and what a rebuild keeps asleep. Why and how: resting.cpp.
//
// Resting owns each particle's rest state besides its flags (kAsleep, kProvisional, kRestX,
// kRestY in its Body): its depth in the pile of sleepers, when it was last woken, when a
// provisional sleep is checked again, the rattle guard's counts, and the rest speed and gap
// of the scene. It decides; the stepper acts: it moves the particle to the instant, puts it
// to sleep or wakes it through the calls below, and predicts its events again.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/world_def.hpp>

#include "contact/contact.hpp"
#include "exact/body.hpp"
#include "exact/collision_rate.hpp"
#include "exact/grid.hpp"
#include "exact/obstacle_cells.hpp"
#include "exact/rolls.hpp"
#include "exact/slides.hpp"

namespace psb::exact {

/// Under gravity: hits on sleeping particles in one step after which a particle wakes the
/// sleepers it hits: a backstop for a particle wedged between sleepers, far below any event
/// budget a caller sets. No scene or test reaches it.
inline constexpr std::uint32_t kWakeAfterHits = 100000;

/// Under gravity with e < 1, the rattle guard: a particle that collides more than kRattleLimit
/// times within kRattleWindow seconds of simulated time falls asleep where it is. 200
/// collisions in a millisecond (2·10⁵ per second): the rattles measured in the frictionless pile
/// preset were 10⁵ collisions of one pair within one 1/60 s step.
inline constexpr std::uint32_t kRattleLimit = 200;
inline constexpr double kRattleWindow = 1e-3;

/// Under gravity with e < 1: for this long after a rebuild (seconds) slow free neighbours do not
/// hold a particle up and the rattle guard leaves alone what the rebuild set free: ten times
/// the u_r/g = 5 ms in which a particle set free from rest is still slower than the rest speed.
inline constexpr double kSettleTime = 0.05;

/// Under gravity with e < 1: a sleep that needed slow free neighbours, or that the rattle guard
/// imposed, is checked again this long after (seconds). Ten milliseconds: four times the 2.6 ms
/// in which a neighbour at the rest speed moves out of the rest gap.
inline constexpr double kRecheckAfter = 0.01;

/// Under gravity with e < 1: speed (m/s) below which a particle comes to rest. The guards'
/// kElasticBelowSpeed (collision_rules.hpp): bounces above it follow the closed form h·e^(2n).
inline constexpr double kRestSpeed = 0.05;

/// Under gravity with e < 1: the rest speed is at least that of a hop this many smallest
/// radii high, √(2·g·kRestHop·r): 5·10⁻⁴ is the hop at kRestSpeed of a 0.25 m disc under
/// 9.81 m/s² (the pile preset), so scenes at that scale keep kRestSpeed, and a scene of 2.5 m
/// discs under 343 m/s² (the gas preset with the app's gravity) rests below 0.93 m/s.
inline constexpr double kRestHop = 5e-4;

/// Under gravity with e = 1: the fall, as a fraction of the box's larger side, that sets the
/// rest speed, √(2·g·fall). 10⁻¹² is a few thousand ulps of a coordinate: a particle placed at
/// rest on the floor rests, a particle that moves never does.
inline constexpr double kRestRoundingGap = 1e-12;

/// What resting reads around a particle, and the records it marks asleep or awake: the
/// stepper's particles, their cells, the obstacles, what moves them (gravity, slides), whether
/// a disc turns (rolls), the box and its laws. Built by the stepper for each call.
struct Surroundings {
    std::vector<Body>& bodies;
    const std::vector<Cold>& cold;
    const Grid& grid;
    const ObstacleCells& obstacles;
    const Slides& slides;
    const Rolls& rolls;
    const Gravity& gravity;
    const WorldDef& def;
};

class Resting {
  public:
    /// What a rebuild keeps of a particle, by id: its record as sync() wrote it, and its depth.
    struct Kept {
        Body body;
        std::uint32_t depth;
    };
    using Snapshot = std::unordered_map<ParticleId, Kept>;
    /// A place where something changed at a rebuild (a particle removed, added, moved, set in
    /// motion): the sleepers within the rest gap of it wake.
    struct Spot {
        double x, y, r;
    };
    /// Whether a particle falls asleep, at what depth, and whether provisionally.
    struct Sleep {
        bool falls = false;
        std::uint32_t depth = 0;
        bool provisional = false;
    };
    /// What becomes of a sleeper when something it may rest on woke, or at its recheck: held
    /// still (Holds), held only with slow free neighbours' help (Provisional: a recheck is
    /// due), or its support gone (Gone: it wakes).
    enum class Support { Holds, Provisional, Gone };

    // --- a rebuild ----------------------------------------------------------------------------
    /// Before a rebuild under unchanged laws: every particle as sync() wrote it (the state at
    /// `clock`), with its depth, by id.
    void remember(const std::vector<Body>& bodies, const std::vector<ParticleId>& ids,
                  const Gravity& g, const Slides& slides, double clock, Snapshot& out) const;
    /// The scene's rest speed and gap (gravity `g`, the laws of `def`, the radii of `p`), and
    /// each of `n` particles awake, never woken, nothing to recheck, nothing counted (no
    /// arrays without gravity).
    void reset(const WorldDef& def, const Gravity& g, const ParticleArrays& p, std::uint32_t n);
    /// After the rebuild: what slept as `before` has it and has not moved sleeps on, at its
    /// depth; `spots` gets every change, `carried` (per particle) what goes on awake as it
    /// was. False (everything left awake) if the changes are too many: a setter or a load.
    bool keep(Snapshot& before, std::vector<Body>& bodies, const std::vector<ParticleId>& ids,
              std::vector<Spot>& spots, std::vector<bool>& carried);
    /// Whether sleeper b rests within reach of spot s.
    [[nodiscard]] bool touches(const Spot& s, const Body& b) const;
    /// After the wakes of keep()'s spots: the rattle guard leaves alone for a while what the
    /// changes set free (awake, not carried).
    void settleFreed(const std::vector<Body>& bodies, const std::vector<bool>& carried);

    // --- after an event -----------------------------------------------------------------------
    [[nodiscard]] double restSpeed() const { return restSpeed_; }
    /// Slower than the rest speed.
    [[nodiscard]] bool slow(const Body& b) const {
        return b.vx * b.vx + b.vy * b.vy < restSpeed_ * restSpeed_;
    }
    /// Particle i was not woken within the contact duration before `now`: it may fall asleep.
    [[nodiscard]] bool mayRest(std::uint32_t i, double now) const;
    /// After an event of particle i at `now` (at its position then; `slow`: slower than the
    /// rest speed and free to rest): asleep if slow and held, or caught rattling.
    Sleep settle(std::uint32_t i, double now, bool slow, const Surroundings& s);
    /// Particle i caught where it is at `now` (rattling, jammed): asleep there, for good if
    /// what does not move holds it, else provisionally.
    [[nodiscard]] Sleep caught(std::uint32_t i, double now, const Surroundings& s) const;
    /// A free neighbour q of particle i with no velocity and no acceleration (it has no event
    /// of its own to fall asleep at): asleep for good now if what does not move holds it.
    [[nodiscard]] Sleep atRestBeside(std::uint32_t q, std::uint32_t i, double now,
                                     const Surroundings& s) const;
    /// Particle i (record b, brought to `now`) falls asleep: no velocity, at `depth`, and if
    /// `provisional` checked again kRecheckAfter later.
    void fallAsleep(std::uint32_t i, Body& b, double now, std::uint32_t depth, bool provisional);
    /// Sleeper i (record b) turns provisional at `now`: checked again kRecheckAfter later.
    void makeProvisional(std::uint32_t i, Body& b, double now);
    /// Particle i (record b) wakes at `now`; it still rests on the walls it rested on.
    void rouse(std::uint32_t i, Body& b, double now);
    /// Sleeper q near particle p, which woke at `now`: Holds (also when q is not asleep or not
    /// within the rest gap of p), Provisional (it was not: now it is), or Gone.
    Support afterWake(std::uint32_t q, std::uint32_t p, double now, const Surroundings& s);
    /// The recheck of provisional sleeper i at `now`: Holds (asleep for good, at its depth or
    /// nearer the ground), Provisional (again; the stepper makes it so), or Gone.
    Support recheck(std::uint32_t i, double now, const Surroundings& s);
    /// When provisional sleeper i is checked again.
    [[nodiscard]] double recheckAt(std::uint32_t i) const { return recheckAt_[i]; }
    /// A pair (i, j) that gravity presses together, leaving a collision along n slower than
    /// half the rest speed, leaves at it (aSlid, bSlid: slid on a face until the pair event).
    void liftPressedPair(std::uint32_t i, std::uint32_t j, Normal n, bool aSlid, bool bSlid,
                         const Surroundings& s) const;

    /// Follows a renumbering of the particles: particle i is now to[i] (gravity only).
    void renumber(const std::vector<std::uint32_t>& to);
    /// Bytes held by the rattle guard's counts (the per-particle times and depths are left
    /// out, as the stepper's other bookkeeping is).
    [[nodiscard]] std::size_t memoryBytes() const { return rate_.memoryBytes(); }

  private:
    // What holds i up at time `now` (i is at its position then): `firm` if the static supports
    // do, with one of depth below `below` among them (depth: the sleeper's, 1 + the least of
    // theirs); `withFree` if they do only with the slow free neighbours added.
    struct Hold {
        bool firm = false, withFree = false;
        std::uint32_t depth = kUngrounded;
    };
    static constexpr std::uint32_t kUngrounded = UINT32_MAX / 2;
    // Changed particles beyond which a rebuild wakes everything (an O(N) search per change).
    static constexpr std::size_t kMaxDisturbances = 64;

    [[nodiscard]] Hold hold(std::uint32_t i, std::uint32_t below, double now,
                            const Surroundings& s) const;
    // `turns`: i is a disc that turns with rough contacts (a single tilted support cannot hold
    // it).
    [[nodiscard]] static bool holdsAgainstGravity(const double* nx, const double* ny, int count,
                                                  bool turns, const Gravity& g, double friction);
    // The supports obstacles give particle i (normals appended to nx, ny up to max); the new
    // count.
    int obstacleSupports(std::uint32_t i, double* nx, double* ny, int count, int max,
                         const Surroundings& s) const;
    [[nodiscard]] bool rattles(std::uint32_t i, double now, double restitution) {
        return restitution < 1.0 && rate_.exceeds(i, now, kRattleWindow, kRattleLimit);
    }

    double restSpeed_ = 0.0;
    double restGap_ = 0.0;  // the height of a hop at the rest speed
    // When each particle was last woken: it does not fall asleep again within the contact
    // duration, so a sleeper hit awake cannot be put back to sleep at the same instant by the
    // next event of the cascade that woke it.
    std::vector<double> wokeAt_;
    // Per sleeper: its depth, 1 for one on a wall, an obstacle or a held particle, else 1 + the
    // least depth of the sleepers it rests on; and when a provisional one is checked again.
    std::vector<std::uint32_t> depth_;
    std::vector<double> recheckAt_;
    CollisionRate rate_;  // the rattle guard's counts
    // The last rebuild kept what slept (keep()): only the particles it set free or added are
    // settling (rate_.quietAt), not everything.
    bool keptSleepers_ = false;
};

}  // namespace psb::exact
