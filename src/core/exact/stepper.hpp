#pragma once
// The exact step: event-driven hard discs. Every collision is resolved at the instant the two
// discs touch, so there is no overlap beyond rounding and nothing tunnels, whatever dt is.
//
//   World::step(dt)
//     │
//     ├─ state stale? (first step, or World said something changed since the last step:
//     │   add/remove, a setter, box/walls/restitution/friction, a step in another mode)
//     │        ──yes──► rebuild: copy particles, clamp into the box, sort them into cell
//     │                 order, predict every particle's two events, fill the queue
//     │
//     ├─ event loop, while the earliest event is at or before t + dt:
//     │
//     │     EventQueue: two keys per particle, 2i = its next collision, 2i+1 = its next cell
//     │     move; a calendar of time buckets in front of a small heap (event_queue.hpp);
//     │     ordered by (time, key)
//     │        │ top
//     │        ▼
//     │     ┌───────────────┬─────────────────────────────────────────────────────────────────┐
//     │     │ pair (i, j)   │ j's counter unchanged since the prediction?                     │
//     │     │               │  yes: advance i, j to the instant, collide (contact.hpp), bump  │
//     │     │               │       both counters, predict both collisions and cell moves    │
//     │     │               │  no:  j changed course since: stale, predict i's collision     │
//     │     │ wall          │ advance i, rebound (contact.hpp), bump counter, predict i       │
//     │     │ cell move     │ move i to the next cell; search only the 3 cells that just came │
//     │     │               │ into its 3 × 3 neighbourhood for an earlier collision           │
//     │     └───────────────┴─────────────────────────────────────────────────────────────────┘
//     │
//     └─ nothing else: the world's arrays are written only when someone reads them
//        (World::particles(), get(), a mutation, ...): sync() writes every particle's
//        state at the end of the last step in one pass. A run of frames that nobody looks
//        at costs its events and nothing per particle.
//
// Where each part is (src/core/exact/):
//   stepper.cpp      this loop: step(), runEvents(), sync()
//   body.hpp         the per-particle records (Body, Cold), events, motions; their memory layout
//   motion.hpp       lazy advance: where a particle is at a time, under gravity on a parabola
//   rebuild.cpp      the state rebuilt from the world's arrays; pairs placed overlapping
//   grid.cpp/.hpp    the fine cells with a skin, the size levels, the sort into cell order
//   prediction.cpp   a particle's next collision and next cell move; the cell move's search
//   collisions.cpp   pair and wall events: the rules for invalid states, inelastic collapse,
//                    held particles
//   resting.cpp      sleep and wake under gravity: the support test, provisional sleep,
//                    rattling, sleepers kept across a rebuild
//   obstacles.cpp    events with fixed pegs and segments; obstacle_cells.* lists them per cell
//   sliding.cpp      the sliding contact on a segment's face
//   rolling.cpp      a disc that turns slipping, then rolling, on a face or a wall
//   event_queue.*, cell_list.*, collision_rate.hpp, and the times of impact:
//   time_of_impact.hpp (straight lines), parabolic_impact.hpp (gravity),
//   obstacle_impact.hpp (obstacles)
//
// Ties. Events at the same instant are handled in key order (particle index, collision before
// cell move); equal candidate times in a prediction go to the lower partner index. Indices are
// the cell order of the last sort, which depends only on the state, so the same state always
// gives the same sequence.
//
// Walls off: no wall events, particles fly free; the cell grid folds onto itself
// (cell_list.hpp) so space is unbounded.
//
// The event budget (World::setExactEventBudget; none unless the caller sets one, as the
// interactive app does for its frames) ends a step that would process more events at the
// first event left: the state is the exact one at that instant (never a pair through each
// other, never a particle past a wall), step() returns the time it reached, and the rest of
// the step is not simulated. Without a budget a step always reaches its end.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

#include "contact.hpp"
#include "exact/body.hpp"
#include "exact/cell_list.hpp"
#include "exact/collision_rate.hpp"
#include "exact/collision_recorder.hpp"
#include "exact/event_queue.hpp"
#include "exact/grid.hpp"
#include "exact/jam_guard.hpp"
#include "exact/motion.hpp"
#include "exact/obstacle_cells.hpp"
#include "exact/placed_contacts.hpp"
#include "exact/rolls.hpp"
#include "exact/slides.hpp"

namespace psb::exact {

/// The TC model's contact duration t_c (seconds): a collision of a particle that already
/// collided less than t_c ago is elastic (see collisions.cpp). Ten microseconds: far below a
/// frame (16 ms) and the free flight times of the sandbox's scenes, far above the time between
/// the zero-gap collisions of a collapsing cluster.
inline constexpr double kContactDuration = 1e-5;

/// Impact speed (m/s) below which restitution rises linearly to 1 (see collisions.cpp).
/// One millimetre per second: far below the speeds of the sandbox's scenes (metres per second),
/// far above the rounding noise of their velocities.
inline constexpr double kElasticBelowSpeed = 1e-3;

/// Of the box's extent: how far past a wall its event may leave a particle's centre before
/// handleWall puts it back on the wall (rounding of the event's time at extreme speeds; found by
/// the world mutation fuzzer with 10¹³ m/s).
inline constexpr double kWallSlack = 1e-12;

/// Of the box's larger extent: the room across an axis (extent − 2r) below which a particle is
/// held on the centre line like one wider than the box (Cold::pinX, pinY). Found by the world
/// mutation fuzzer: a disc of 10⁻³⁰¹ m in a box 10⁻³⁰⁰ m wide and 2.7 m high bounced between
/// the side walls every 10⁻³⁰¹ s.
inline constexpr double kNoRoom = 1e-12;

/// Under gravity: hits on sleeping particles in one step after which a particle wakes the
/// sleepers it hits (see resting.cpp): a backstop for a particle wedged between sleepers,
/// far below any event budget a caller sets. No scene or test reaches it.
inline constexpr std::uint32_t kWakeAfterHits = 100000;

/// Under gravity with e < 1, the rattle guard (see resting.cpp): a particle that collides
/// more than kRattleLimit times within kRattleWindow seconds of simulated time falls asleep
/// where it is. 200 collisions in a millisecond (2·10⁵ per second): the rattles measured in the
/// frictionless pile preset were 10⁵ collisions of one pair within one 1/60 s step.
inline constexpr std::uint32_t kRattleLimit = 200;
inline constexpr double kRattleWindow = 1e-3;

/// Under gravity with e < 1: for this long after a rebuild (seconds) slow free neighbours do not
/// hold a particle up and the rattle guard leaves alone what the rebuild set free: ten times
/// the u_r/g = 5 ms in which a particle set free from rest is still slower than the rest speed.
inline constexpr double kSettleTime = 0.05;

/// Under gravity with e < 1: a sleep that needed slow free neighbours, or that the rattle guard
/// imposed, is checked again this long after (seconds; see resting.cpp). Ten milliseconds:
/// four times the 2.6 ms in which a neighbour at the rest speed moves out of the rest gap.
inline constexpr double kRecheckAfter = 0.01;

/// Under gravity with e < 1: speed (m/s) below which a particle comes to rest (see
/// resting.cpp). The guards' kElasticBelowSpeed: bounces above it follow the closed form h·e^(2n).
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

class ExactStepper {
  public:
    /// Advances the event state by dt seconds. Rebuilds it from `p` and `def` first if
    /// invalidate() was called since the last step (or there was none). Does not write `p`:
    /// the state at the end of the step is owed to it until sync(). Updates the counters
    /// (collisions, wallCollisions, wallImpulse, maxOverlap, steps, events, cutShort).
    /// `eventsPerParticle` > 0 is the budget: a step that would process more than that many
    /// events per particle (plus one particle's worth) ends at the first event left. Returns
    /// the seconds simulated: dt (exactly the argument), or less when the budget ran out.
    double step(ParticleArrays& p, const WorldDef& def, double dt, std::uint64_t eventsPerParticle,
                StepProfile& profile, StepCounters& counters);

    /// Whether `p` has not yet received the state of the last step.
    [[nodiscard]] bool owesSync() const { return syncOwed_; }
    /// Writes every particle's position and velocity (and, in a world that keeps rotation, its
    /// angle and angular velocity) at the end of the last step into `p`
    /// (the arrays the last rebuild read): one pass over the particles.
    void sync(ParticleArrays& p);

    /// Forces a rebuild at the next step: the world calls it whenever it changes anything the
    /// stepper read (particles, box, walls, material laws), after taking the owed sync.
    void invalidate() { stale_ = true; }

    /// Appends every resolved collision to `log` (nullptr to stop). Indices are storage
    /// indices of `p`; times restart from 0 at each rebuild.
    void setLog(std::vector<CollisionRecord>* log) { recorder_.setLog(log); }

    /// The world's record of collisions (collision_log.hpp) for the next step, nullptr for none;
    /// `worldTime` is World::time() at its start, the clock the records' times are on.
    void record(CollisionLog* log, double worldTime) { recorder_.setWorldLog(log, worldTime); }

    /// Bytes held by the event state (per-particle records, every level's cells, the queue,
    /// placed overlaps): what a copy of a world in this mode carries besides its own arrays.
    /// Small bookkeeping vectors are left out.
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    // --- the loop (stepper.cpp) ---------------------------------------------------------------
    // Handles the events up to tEnd; returns the time the state is exact at: tEnd, or, when
    // the budget (0: none) ran out, the time of the first event left.
    double runEvents(double tEnd, StepCounters& counters, std::uint64_t budget);

    // --- rebuild (rebuild.cpp) ----------------------------------------------------------------
    void rebuild(ParticleArrays& p, const WorldDef& def);
    [[nodiscard]] double bucketWidth() const;

    // Re-sorts the particles into cell order (grid.hpp), every per-particle array with them;
    // `midRun`: the scheduled events and the cell lists follow.
    void sortByCell(bool midRun);

    // --- motion (motion.hpp) ------------------------------------------------------------------
    // Particle i brought to time t; its acceleration and its motion at t (b: its record or a
    // copy of it).
    void advance(std::uint32_t i, double t) { exact::advance(i, bodies_[i], gravity_, slides_, t); }
    void accelerationOf(std::uint32_t i, const Body& b, double& ax, double& ay) const {
        exact::accelerationOf(i, b, gravity_, slides_, ax, ay);
    }
    [[nodiscard]] Motion motionAt(std::uint32_t i, const Body& b, double t) const {
        return exact::motionAt(i, b, gravity_, slides_, t);
    }

    // --- prediction (prediction.cpp) ----------------------------------------------------------
    void predictCollision(std::uint32_t i, double now);
    void predictWallsUnderGravity(std::uint32_t i, const Motion& m, double now, Event& best) const;
    void predictCell(std::uint32_t i, double now);
    void scanNeighbours(std::uint32_t i, double now, double ax, double ay, Event& best);
    void scanBlock(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                   std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1, Event& best);
    void scanCells(std::uint32_t i, double now, double ax, double ay, const CellList& list,
                   const std::uint32_t* cells, int cellCount, Event& best);
    [[nodiscard]] static double pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                                     const Motion& bm, double sigma,
                                                     double horizon);
    void handleCell(std::uint32_t i, double now);

    // --- pair and wall events (collisions.cpp) ------------------------------------------------
    void handlePair(std::uint32_t i, const Event& ev, StepCounters& counters);
    /// Particle i's inverse mass seen along n, w being its own: for one wider than the box
    /// along an axis, what is left of w along its free axis, w·|P n|² (collisions.cpp).
    [[nodiscard]] double inverseMassAlong(std::uint32_t i, Normal n, double w) const;
    /// After a collision of particle i that is wider than the box along an axis: its velocity
    /// change, found for the inverse mass `wSeen` it has along the normal, turned into the
    /// change along its free axis (collisions.cpp).
    void holdAcrossPinnedAxes(std::uint32_t i, const Vec2& before, double wSeen);
    void handleWall(std::uint32_t i, const Event& ev, StepCounters& counters);
    [[nodiscard]] static bool collidedWithin(const Body& b, double now);
    [[nodiscard]] double effectiveRestitution(double impactSpeed, bool recent) const;
    // Before a collision of i at time t: true while i is jammed (jam_guard.hpp), its velocity
    // absorbed.
    bool jamsAt(std::uint32_t i, double t);

    // --- resting, gravity only (resting.cpp) --------------------------------------------------
    // At a rebuild under unchanged laws: what slept and has not moved sleeps on; what the
    // changes touch wakes.
    struct Kept {
        Body body;
        std::uint32_t depth;
    };
    void keepSleepers(std::unordered_map<ParticleId, Kept>& before);
    // Changed particles beyond which a rebuild wakes everything (an O(N) search per change).
    static constexpr std::size_t kMaxDisturbances = 64;
    // What holds i up at time `now` (i is at its position then; see resting.cpp): `firm` if the
    // static supports do, with one of depth below `below` among them (depth: the sleeper's
    // `depth`, 1 + the least of theirs); `withFree` if they do only with the slow free
    // neighbours added.
    struct Hold {
        bool firm = false, withFree = false;
        std::uint32_t depth = kUngrounded;
    };
    static constexpr std::uint32_t kUngrounded = UINT32_MAX / 2;
    [[nodiscard]] Hold hold(std::uint32_t i, std::uint32_t below, double now) const;
    // `turns`: i is a disc that turns with rough contacts (a single tilted support cannot hold it).
    [[nodiscard]] bool holdsAgainstGravity(const double* nx, const double* ny, int count,
                                           bool turns) const;
    // After an event of i: asleep if slow and held, or caught rattling.
    void settle(std::uint32_t i, double now, bool slow);
    void handleRecheck(std::uint32_t i, const Event& ev);
    void sleepNeighboursAtRest(std::uint32_t i, double now);
    [[nodiscard]] bool mayRest(std::uint32_t i, double now) const {
        return now - wokeAt_[i] >= kContactDuration;
    }
    void fallAsleep(std::uint32_t i, double now, std::uint32_t depth, bool provisional);
    void wake(std::uint32_t i, double now);
    void liftPressedPair(std::uint32_t i, std::uint32_t j, Normal n, bool aSlid, bool bSlid);
    void settleAfterPair(std::uint32_t i, bool justWoken);
    [[nodiscard]] bool rattles(std::uint32_t i, double now) {
        return def_.restitution < 1.0 && rate_.exceeds(i, now, kRattleWindow, kRattleLimit);
    }

    // --- fixed obstacles (obstacles.cpp) ------------------------------------------------------
    // i's earliest impact with an obstacle of its cell's list, if earlier than best; the
    // rebound; the supports obstacles give a resting particle (normals appended to nx, ny up to
    // max, returns the new count).
    void predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best);
    void handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters);
    // The rebound off obstacle k at i's current state (a lift or a slide where gravity presses
    // i into it), without the event's bookkeeping.
    void reboundOffObstacle(std::uint32_t i, std::uint32_t k, bool recent, StepCounters& counters,
                            bool maySlide = true);
    int obstacleSupports(std::uint32_t i, double* nx, double* ny, int count, int max) const;

    // --- sliding on a segment's face (slides.hpp; obstacles.cpp) ------------------------------
    // Entering it at a rebound off a face (false where slides.hpp says no), its acceleration (a
    // block's, or a roll's for a disc that turns), the end-of-face and stop events; and the
    // face's answer to a slider hit by a pair that is still on it.
    bool startSliding(std::uint32_t i, std::uint32_t k, double nx, double ny);
    void setSlideAcceleration(std::uint32_t i);
    void handleSlide(std::uint32_t i, const Event& ev);
    // Ends i's slide, and its roll on a face or a wall if it rolls (i is at bodies_[i].t):
    // every event of a particle ends its contact's motion, and the event's handler starts it
    // again where the particle is still in contact.
    void stopSliding(std::uint32_t i) {
        Body& b = bodies_[i];
        b.flags &= ~kSliding;
        if (b.flags & kRolling) rolls_.end(i, b);
    }
    void keepOnFace(std::uint32_t i, StepCounters& counters, bool maySlide);

    // --- slipping and rolling on a face or a wall (rolls.hpp; obstacles.cpp) -----------------
    // The phase i's contact calls for at bodies_[i].t (Rolls::set); the slip-to-roll event.
    void setRoll(std::uint32_t i) {
        rolls_.set(i, bodies_[i], cold_[i], slides_, obstacles_, gravity_, def_.friction);
    }
    void handleRoll(std::uint32_t i, const Event& ev);

    WorldDef def_;
    bool stale_ = true;
    Gravity gravity_;         // def_.gravity
    double restSpeed_ = 0.0;  // see resting.cpp
    double restGap_ = 0.0;
    std::vector<std::uint32_t> wakeStack_;
    // Each particle's sliding contact, with gravity and obstacles or rough contacts only.
    Slides slides_;
    // Each particle's rotation, in a world that keeps rotation; whether contacts are rough.
    Rolls rolls_;
    // When each particle was last woken (gravity only): it does not fall asleep again within
    // kContactDuration, so a sleeper hit awake cannot be put back to sleep at the same instant
    // by the next event of the cascade that woke it.
    std::vector<double> wokeAt_;
    // Per sleeper (gravity only): its depth, 1 for one on a wall, an obstacle or a held
    // particle, else 1 + the least depth of the sleepers it rests on; and when a provisional
    // one is checked again.
    std::vector<std::uint32_t> depth_;
    std::vector<double> recheckAt_;
    CollisionRate rate_;  // the rattle guard's counts (gravity only)
    /// The last rebuild kept what slept (keepSleepers): only the particles it set free or added
    /// are settling (rate_.quietAt), not everything.
    bool keptSleepers_ = false;
    double clock_ = 0.0;  // seconds since the last rebuild
    // Particles are kept in cell order (rebuild sorts them) so that a 3 × 3 neighbourhood is
    // three short runs of memory; order_ maps this order back to the world's storage indices.
    std::vector<Body> bodies_;
    std::vector<Cold> cold_;
    std::vector<std::uint32_t> order_;
    std::vector<ParticleId> ids_;
    Grid grid_;                // the cells and size levels
    ObstacleCells obstacles_;  // the fixed obstacles each fine cell may reach
    EventQueue queue_;
    std::uint64_t eventsSinceSort_ = 0;
    double maxOverlap_ = 0.0;
    // Events handled in this step (pairs, stale pairs, walls, obstacles, slides, cell moves):
    // what step() adds to StepCounters::events.
    std::uint64_t events_ = 0;
    CollisionRecorder recorder_;  // where resolved collisions go (setLog, record)
    // Pairs found overlapping at the last rebuild (placed so from outside): the contact
    // distance each keeps until it is found apart.
    PlacedContacts placed_;
    bool syncOwed_ = false;  // the world's arrays do not hold the state at clock_ yet
    JamGuard jams_;
};

}  // namespace psb::exact
