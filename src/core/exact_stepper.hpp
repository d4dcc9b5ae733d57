#pragma once
// The exact step: event-driven hard discs. Every collision is resolved at the instant the two
// discs touch, so there is no overlap beyond rounding and nothing tunnels, whatever dt is.
//
//   World::step(dt)
//     │
//     ├─ state stale? (first step, or anything in the world changed since the last step:
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
//     └─ sync: write every particle's state at t + dt into the world's arrays, and keep a
//        snapshot of them to detect any change before the next step
//
// Lazy advance (Lubachevsky 1991). Each particle keeps the position it had at its last
// velocity change; an event touches only its one or two particles, so an event costs a search
// of the cells around a particle and an O(1)–O(log N) queue update, not O(N). Positions for
// the outside world are computed at the end of the step and never fed back, so how dt is
// chopped does not change the trajectory (only, in the last bits, the time t + dt itself).
//
// Two scheduled events per particle (after Smallenburg 2022). A particle's collision key holds
// only its earliest collision (pair or wall) and its cell key only its next cell move. That is
// enough: a later collision of i would come after its earliest one, when i is predicted again;
// an event of i with j that j's own collisions make wrong is caught by j's counter (bumped at
// every velocity change); and a particle that comes near i does so at a cell move of its own or
// of i, which searches the newly adjacent cells. A candidate (i, j) later than j's own scheduled
// collision is not even kept: j is predicted again against everything around it by then.
//
// Cells with a skin. Cells are at least one largest diameter plus twice a skin wide, and a
// particle moves to the next cell only once its centre is a skin's width past the face (not at
// the face). Two touching discs are then still in neighbouring cells, and a particle that just
// moved is a skin inside its new cell, so it does not flicker across a face: about half as
// many cell moves as with plain cells at the same search cost.
//
// Memory. Events come in time order, which is random in space, so at 10^5 particles nearly
// every particle an event touches is a cache miss. What an event reads about a neighbour is one
// 64-byte line (Body), what it reads about its own particle another (Cold); particles are
// re-sorted into cell order every kResortEvery·N events (indices only: nothing physical
// changes), a neighbourhood's members are gathered and prefetched before they are tested, and
// the particle of the likely next event is prefetched while this one is handled.
//
// Rules for invalid states (Bannerman et al. 2014), so rounding never decides:
//   - no event is scheduled before the current time (times of impact are durations >= 0);
//   - an overlapping pair collides at once if it approaches and is left alone if it separates;
//   - but a pair already overlapping at a rebuild was placed so (rounding leaves a few ulps at
//     most): its contact distance is the distance it was placed at until a prediction finds it
//     apart. The rule above alone would be a ratchet (every drift apart kept), squeezing the
//     overlaps of a box too full for its discs into the others' gaps until the pile jams;
//   - a disc past a wall collides with it at once if moving outward, else is left alone;
//   - a collision whose pair turns out not to approach at its instant changes nothing.
// Ties: events at the same instant are handled in key order (particle index, collision before
// cell move); equal candidate times in a prediction go to the lower partner index. Indices are
// the cell order of the last sort, which depends only on the state, so the same state always
// gives the same sequence.
//
// Inelastic collapse. With e < 1 a cluster can collide infinitely often in finite time, and an
// event-driven code then stalls; with e = 0 it does so at once (a pair leaves a collision
// touching, at zero relative speed, so the next collision in the cluster is at zero gap). Two
// guards make restitution tend to 1 where the collapse would happen:
//   - the TC model (Luding & McNamara 1998): a particle that collided less than
//     kContactDuration ago collides elastically, so a cascade of near-simultaneous collisions
//     re-opens gaps instead of closing them;
//   - impacts slower than kElasticBelowSpeed use e_eff = 1 − (1 − e)·u/u_c, rising linearly to
//     1 as the speed goes to 0, so ever slower collisions lose ever less energy.
// A cooling pile therefore settles to small speeds with a bounded number of events per step.
//
// Held (kinematic) particles. Infinite mass, straight lines: they push and are not pushed
// (contact.hpp's kinematic limit). A held particle that reaches a wall stops moving across it.
// A free particle squeezed between a held one and a wall or another held one would collide
// infinitely often; after kJamLimit collisions with held particles in one step it is allowed to
// pass through held particles for the rest of that step.
//
// Particles that do not fit. A particle wider than the box along an axis stays on the box's
// centre line on that axis (as in the discrete mode); the walls absorb at once any velocity it
// gains across it. Such a particle makes the cells as large as the box: correct but O(N) per
// event.
//
// Walls off: no wall events, particles fly free; the cell grid folds onto itself
// (cell_list.hpp) so space is unbounded.
//
// Gravity. Between events a free particle flies on a parabola, r(t) = r₀ + v₀t + ½gt², and
// lazy advance stays as it is (a particle's stored state is the one at its last velocity
// change). Two free particles fall alike, so their relative motion is a straight line and their
// time of impact the quadratic above. A free particle against one that does not fall (held,
// asleep, or resting on a wall) needs the first root of a quartic; walls and cell faces are
// crossed at the root of a quadratic, either face of a cell (a particle thrown up falls back
// through the face it came in by). All in exact_parabolic_impact.hpp. A world without gravity
// takes none of these paths: its trajectories are bit for bit those of the linear code.
//
// Resting (gravity only; Bannerman et al. 2014, DynamO's sleeping particles, after Luding &
// McNamara 1998). A ball with e < 1 makes infinitely many bounces in finite time, and the guards
// above only slow the cascade, so particles that come to rest are taken out of the dynamics:
//   - a wall that gravity presses a particle into: a rebound slower than restSpeed_ ends with
//     the particle resting on the wall (its velocity and acceleration across the wall zero); it
//     still slides along it;
//   - a particle slower than restSpeed_ after an event falls asleep (zero velocity, no
//     acceleration, no cell events) if the supports within restGap_ (walls, sleepers, held
//     particles at rest) hold it: one whose contact normal is within kRestSlope of gravity, or
//     two on either side of it, each normal's cone widened by the friction angle atan(mu);
//     a particle woken less than kContactDuration ago does not fall asleep again;
//   - a sleeping particle hit at a normal speed above 2·restSpeed_ (or by a held particle, or,
//     as a backstop, by a particle that already hit sleepers kWakeAfterHits times in this step)
//     wakes, with every sleeper it supported (transitively: the ones resting
//     on it); slower hits bounce off it as off an infinitely heavy disc;
//   - a pair that gravity presses together (one falls and the other does not: it is asleep,
//     held or resting on a wall) and that leaves a collision slower than restSpeed_ / 2 leaves
//     at restSpeed_ / 2 (an impulse shared as the collision shares it): a particle on the side
//     of its support hops down it instead of making ever faster tiny bounces on it, and no
//     pair is ever predicted to touch again at the same instant.
// restSpeed_ is kRestSpeed for e < 1; with e = 1 it is the speed of a fall through rounding
// (kRestRoundingGap of the box), so that only particles placed at rest on a support rest, and
// nothing moving ever sleeps. restGap_ is the height of a hop at restSpeed_, restSpeed_²/(2g):
// waking a sleeper lets it fall at most that far, which reaches only restSpeed_ and does not
// wake what is under it. A rebuild (any change to the world) wakes everything; a settled pile
// settles again in a few events per particle, so a removed support lets the ones above fall.
// Limit: a frictionless pile, or one with e = 0, does not settle yet (docs/exact.md).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

#include "cell_list.hpp"
#include "contact.hpp"
#include "event_queue.hpp"

namespace psb::exact {

/// The TC model's contact duration t_c (seconds): a collision of a particle that already
/// collided less than t_c ago is elastic (see the design note). Ten microseconds: far below a
/// frame (16 ms) and the free flight times of the sandbox's scenes, far above the time between
/// the zero-gap collisions of a collapsing cluster.
inline constexpr double kContactDuration = 1e-5;

/// Impact speed (m/s) below which restitution rises linearly to 1 (see the design note).
/// One millimetre per second: far below the speeds of the sandbox's scenes (metres per second),
/// far above the rounding noise of their velocities.
inline constexpr double kElasticBelowSpeed = 1e-3;

/// Collisions with held particles after which a squeezed particle passes through them for the
/// rest of the step.
inline constexpr std::uint32_t kJamLimit = 1000;

/// Events one step may process per particle (plus a fixed allowance) before the rest of the
/// step is flown without collisions: a last-resort guard that keeps the app responsive. It is
/// never reached by the scenes and tests; if it is, the next step starts from a rebuild, where
/// the invalid-state rules above resolve any overlap left behind.
inline constexpr std::uint64_t kMaxEventsPerParticlePerStep = 10000;

/// Under gravity: hits on sleeping particles in one step after which a particle wakes the
/// sleepers it hits (see the design note): a backstop for a particle wedged between sleepers,
/// below the step's event budget. No scene or test reaches it.
inline constexpr std::uint32_t kWakeAfterHits = 100000;

/// Under gravity: a slow particle rests on one support whose contact normal is within this
/// angle (radians) of gravity; beyond it, only between two.
inline constexpr double kRestSlope = 1.0471975511965976;  // 60°

/// Under gravity with e < 1: speed (m/s) below which a particle comes to rest (see the design
/// note). The guards' kElasticBelowSpeed: bounces above it follow the closed form h·e^(2n).
inline constexpr double kRestSpeed = 0.05;

/// Under gravity with e = 1: the fall, as a fraction of the box's larger side, that sets the
/// rest speed, √(2·g·fall). 10⁻¹² is a few thousand ulps of a coordinate: a particle placed at
/// rest on the floor rests, a particle that moves never does.
inline constexpr double kRestRoundingGap = 1e-12;

/// One resolved collision, for tests and diagnostics. `j` is a particle index for a pair, or
/// kWall + w for wall w (0 = left, 1 = right, 2 = top, 3 = bottom).
struct CollisionRecord {
    static constexpr std::uint32_t kWall = UINT32_MAX - 3;
    double time;  ///< seconds since the stepper's last rebuild
    std::uint32_t i;
    std::uint32_t j;
};

class ExactStepper {
  public:
    /// Advances `p` by dt seconds: on return every particle is at its exact state at t + dt.
    /// Rebuilds first if `p` or `def` differ from what the last step left. Updates the
    /// counters (collisions, wallCollisions, wallImpulse, maxOverlap, steps, events).
    void step(ParticleArrays& p, const WorldDef& def, double dt, StepProfile& profile,
              StepCounters& counters);

    /// Forces a rebuild at the next step.
    void invalidate() { stale_ = true; }

    /// Appends every resolved collision to `log` (nullptr to stop). Indices are storage
    /// indices of `p`; times restart from 0 at each rebuild.
    void setLog(std::vector<CollisionRecord>* log) { log_ = log; }

    /// Events of each kind processed by the last step.
    struct EventStats {
        std::uint64_t pairs = 0, walls = 0, cells = 0, stale = 0;
        std::uint64_t sleeps = 0, wakes = 0;  ///< particles put to sleep / woken (gravity only)
        bool budgetExhausted = false;
    };
    [[nodiscard]] const EventStats& lastStepEvents() const { return stats_; }

  private:
    enum class Kind : std::uint8_t { None, Pair, Wall };

    // What an event and a neighbour's prediction read, in one 64-byte line.
    struct alignas(64) Body {
        double x, y;          // centre at time t, metres
        double vx, vy;        // m/s
        double t;             // time of the last velocity change (or rebuild), seconds
        double r;             // radius
        double nextColl;      // time of its scheduled collision event (see scanCells)
        std::uint32_t count;  // bumped at every velocity change
        std::uint32_t flags;  // kHeld, kJammed
    };
    static constexpr std::uint32_t kHeld = 1;    // kinematic: infinite mass
    static constexpr std::uint32_t kJammed = 2;  // passes through held particles (jam guard)
    static constexpr std::uint32_t kPlacedOverlapping = 4;  // in a pair of overlapContact_
    static constexpr std::uint32_t kAsleep = 8;             // at rest: no velocity, no acceleration
    static constexpr std::uint32_t kRestX = 16;  // no acceleration along x (on a wall, pinned)
    static constexpr std::uint32_t kRestY = 32;  // no acceleration along y
    // Where a particle is at a time, and how it moves there (gravity only).
    struct Motion {
        double x, y, vx, vy, ax, ay;
    };
    struct Event {
        double time;
        std::uint32_t partner;       // pair: the other particle
        std::uint32_t partnerCount;  // pair: its counter when predicted
        Kind kind;
        std::int8_t side;  // wall: 0..3 (left, right, top, bottom)
    };

    // What only the particle's own events read, in one line.
    struct alignas(64) Cold {
        Event coll;              // its next collision (pair or wall)
        double m;                // mass
        std::int64_t kx, ky;     // cell coordinates
        std::int8_t cellSide;    // the face its next cell event crosses: -x, +x, -y, +y
        bool pinX, pinY;         // does not fit between the walls along this axis
        std::uint32_t heldHits;  // collisions with held particles this step (jam guard)
        double w;                // inverse mass, 0 = held
    };

    [[nodiscard]] bool matches(const ParticleArrays& p, const WorldDef& def) const;
    void rebuild(ParticleArrays& p, const WorldDef& def);
    void setUpGrid();
    void sortByCell(bool midRun);
    [[nodiscard]] double bucketWidth() const;
    void advance(Body& b, double t) const;
    void accelerationOf(const Body& b, double& ax, double& ay) const;
    [[nodiscard]] Motion motionAt(const Body& b, double t) const;
    [[nodiscard]] static bool isStatic(const Body& b) {
        return (b.flags & kAsleep) || ((b.flags & kHeld) && b.vx == 0.0 && b.vy == 0.0);
    }
    [[nodiscard]] static double pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                                     const Motion& bm, double sigma,
                                                     double horizon);
    // Calls f(q) for every particle q in the 3 × 3 cells around i (i included).
    template <typename F>
    void forEachAround(std::uint32_t i, F&& f) const {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const std::uint32_t c = cells_.cell(cold_[i].kx + dx, cold_[i].ky + dy);
                if (c == CellList::kNone) continue;
                for (std::uint32_t q = cells_.head(c); q != CellList::kNone; q = cells_.next(q))
                    f(q);
            }
        }
    }
    [[nodiscard]] bool supported(std::uint32_t i) const;
    [[nodiscard]] bool mayRest(std::uint32_t i, double now) const {
        return now - wokeAt_[i] >= kContactDuration;
    }
    void fallAsleep(std::uint32_t i, double now);
    void wake(std::uint32_t i, double now);
    void liftPressedPair(std::uint32_t i, std::uint32_t j, Normal n);
    void settleAfterPair(std::uint32_t i, bool justWoken);
    void scanCells(std::uint32_t i, double now, double ax, double ay, const std::uint32_t* cells,
                   int cellCount, Event& best);
    void recordPlacedOverlaps();
    [[nodiscard]] static std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
        return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
    }
    void predictCollision(std::uint32_t i, double now);
    void predictWallsUnderGravity(std::uint32_t i, const Motion& m, double now, Event& best) const;
    void predictCell(std::uint32_t i, double now);
    void handlePair(std::uint32_t i, const Event& ev, StepCounters& counters);
    void handleWall(std::uint32_t i, const Event& ev, StepCounters& counters);
    void handleCell(std::uint32_t i, double now);
    [[nodiscard]] static bool collidedWithin(const Body& b, double now);
    [[nodiscard]] double effectiveRestitution(double impactSpeed, bool recent) const;
    void runEvents(double tEnd, StepCounters& counters, std::uint64_t budget);
    void sync(ParticleArrays& p, double t);

    WorldDef def_;
    bool stale_ = true;
    bool gravity_ = false;  // def_.gravity is not zero
    double gx_ = 0.0, gy_ = 0.0;
    double restSpeed_ = 0.0;  // see the design note
    double restGap_ = 0.0;
    std::vector<std::uint32_t> wakeStack_;
    // When each particle was last woken (gravity only): it does not fall asleep again within
    // kContactDuration, so a sleeper hit awake cannot be put back to sleep at the same instant
    // by the next event of the cascade that woke it.
    std::vector<double> wokeAt_;
    double clock_ = 0.0;  // seconds since the last rebuild
    // Particles are kept in cell order (rebuild sorts them) so that a 3 × 3 neighbourhood is
    // three short runs of memory; order_ maps this order back to the world's storage indices.
    std::vector<Body> bodies_;
    std::vector<Cold> cold_;
    std::vector<std::uint32_t> order_;
    std::vector<ParticleId> ids_;
    CellList cells_;
    double skinX_ = 0.0, skinY_ = 0.0;  // how far a centre may stray out of its cell
    EventQueue queue_;
    std::uint64_t eventsSinceSort_ = 0;
    double maxOverlap_ = 0.0;
    EventStats stats_;
    std::vector<CollisionRecord>* log_ = nullptr;
    // Pairs found overlapping at the last rebuild (placed so from outside), keyed by their
    // storage indices (order_), with the contact distance they keep until they are found apart.
    std::unordered_map<std::uint64_t, double> overlapContact_;

    // What the last step left in the world's arrays, to detect any change made between steps.
    ParticleArrays snapshot_;
};

}  // namespace psb::exact
