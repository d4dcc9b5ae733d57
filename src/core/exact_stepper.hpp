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
// Lazy advance (Lubachevsky 1991). Each particle keeps the position it had at its last
// velocity change; an event touches only its one or two particles, so an event costs a search
// of the cells around a particle and an O(1)–O(log N) queue update, not O(N). Positions for
// the outside world are computed when it reads them (sync) and never fed back, so how dt is
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
// Cells with a skin. Cells are at least one largest diameter (of level 0, below) plus twice a
// skin wide, and a particle moves to the next cell only once its centre is a skin's width past
// the face (not at the face). Two touching discs of level 0 are then still in neighbouring
// cells, and a particle that just moved is a skin inside its new cell, so it does not flicker
// across a face: about half as many cell moves as with plain cells at the same search cost.
//
// Size levels. Cells sized by the largest disc would make a gas with one big disc search
// cells hundreds of small discs wide. Instead radii fall into levels: level 0 holds every disc
// up to 1.25 mean spacings across (the cells are about a spacing wide anyway) or twice the
// smallest radius, whichever is larger, and levels above it double (empty ones dropped). The fine
// grid is sized by level 0 alone, and every particle, whatever its level, has a fine cell and
// makes fine cell moves. Particles of levels a and b are neighbours when their fine cells are
// at most reach(a, b) apart along each axis, the distance at which two such discs can still
// touch (1 for two of level 0: the 3 × 3 search). The relation is symmetric and changes only
// at a cell move of one of the two, which searches the strip of cells that just came within
// reach, at every level: that is all the argument above needs. Level 0 is listed in the fine
// cells; level l > 0 in cells of block × block fine cells (block = 2 reach(0, l) + 1), so that
// a small disc looks at a few cells of each upper level, and a big disc's search is the
// (2 reach + 1)² fine cells around it, mostly inside the disc itself and so empty. A scene of
// one size has one level and runs the code it ran before levels existed, bit for bit.
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
// Obstacles (fixed pegs and segments; exact_obstacle_events.cpp). A third kind of collision
// event, kept in a particle's collision key like a wall's and replaced like it at every change
// of course. Each fine cell lists the obstacles a particle in it may reach before its next cell
// move (exact_obstacle_cells.hpp); a prediction tests its cell's list, a cell move the new
// cell's. Times of impact: exact_obstacle_impact.hpp (quadratics; under gravity the quartic
// for pegs and caps, a quadratic across a flat side). Rebound: the walls' law along the normal
// from the nearest core point. Under gravity obstacles are supports for resting (below), a
// single one only within the friction angle, so a ball slides down a slope steeper than that.
// Sliding (gravity only): a rebound off a segment's face that gravity presses the particle into
// and that leaves it slower than the lift (restSpeed_ / 2) starts a sliding contact instead of a
// hop: the particle stays at contact distance and moves along the face with a constant
// acceleration, gravity's share along it less the kinetic friction mu·|g_n| against the motion
// (none while static friction holds a particle at rest). Its path is still a parabola, with
// another acceleration: pair times of impact take the relative-acceleration quartic, walls and
// cell faces their quadratics, as for any acceleration. The contact has events of its own, in
// the collision key (Kind::Slide): the end of the face (either end; it leaves from a hair past
// it in free flight, and hops round the cap only if too slow to fly clear of it), and, where
// friction decelerates it, the instant it stops (asleep there if the friction angle holds it,
// else sliding back down). Any other event of the particle (a pair, a wall, another obstacle)
// ends the slide; a slider a pair hit that is still on its face gets the face's answer at once
// (keepOnFace: a rebound, and a slide again if slow), after a wall or another obstacle it is
// found touching at its next prediction and slides again at that same instant.
// Pegs and caps keep the hop: round a circle the normal force is not constant, and the path
// is not a parabola.
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
//     acceleration, no cell events) if the supports within restGap_ hold it (hold()): gravity
//     lies in the cone of their contact normals (along one, or strictly between two less than
//     a half turn apart), or the one face gravity slides it down (the loaded support no other
//     blocks) is tilted less than the friction angle atan(mu). Not each normal's cone widened
//     by that angle: that counts a neighbour the slide only grazes (one above the particle) as
//     pushing with any force, and grains above a neck locked into arches nothing held up.
//     Supports are walls, obstacles, held particles at rest and sleepers. Each sleeper has a
//     depth: 1 on a wall, an obstacle or a held particle, else 1 + the least depth of the
//     sleepers it rests on; it must keep a support of lower depth, so every sleeper rests on a
//     chain down to something fixed and no cluster holds itself up;
//   - provisional sleep (e < 1): a particle that only slow free neighbours (slower than
//     restSpeed_, not woken in the last kRecheckAfter, not in the first kSettleTime after a
//     rebuild) help hold, with something static among its supports, sleeps until a recheck
//     kRecheckAfter later (Kind::Recheck, in its collision key): held then by what is static,
//     it sleeps for good; still held only with free neighbours' help, it waits again (and a
//     free neighbour at rest with no acceleration, which has no event of its own to fall
//     asleep at, falls asleep then if what is static holds it); else it wakes. Without it an arch
//     of discs leaning on each other waits for the others to sleep first, and none does; with it a
//     grain that slept on a moving one does not hang in the air when that one has gone. A particle
//     woken less than kContactDuration ago does not fall asleep again;
//   - a sleeping particle hit at a normal speed above 2·restSpeed_ (or by a held particle, or,
//     as a backstop, by a particle that already hit sleepers kWakeAfterHits times in this step)
//     wakes; then every sleeper within restGap_ of a woken one is judged again (hold() at its
//     depth) and wakes if no longer held, and so on (a support that moves lets what it held
//     fall, whether it held it from below or from the side; one still held with slow free
//     neighbours' help turns provisional instead); slower hits bounce off it as off
//     an infinitely heavy disc, with the restitution e itself (no TC rule: a sleeper does not
//     move, so there is no collapse to prevent, and the elastic rule only kept a disc wedged
//     between sleepers rattling at full speed) and with none if the rebound would be slower
//     than restSpeed_ (it stops, as on a wall it rests on);
//   - a pair that gravity presses together (one falls and the other does not: it is asleep,
//     held or resting on a wall) and that leaves a collision slower than restSpeed_ / 2 leaves
//     at restSpeed_ / 2 (an impulse shared as the collision shares it): a particle on the side
//     of its support hops down it instead of making ever faster tiny bounces on it, and no
//     pair is ever predicted to touch again at the same instant (a slider the pair event took
//     off its face counts as moving with its slide's acceleration: it is still on the face).
// Rattling (e < 1). Where the weight of a frictionless pile has to be carried by collisions
// alone, the hard-disc model carries it by ever more frequent ones (a disc squeezed between
// two others on a floor it slides on, a cluster collapsing, McNamara & Young 1994): the rules
// above do not bound them. So a particle that collides more than kRattleLimit times within
// kRattleWindow of simulated time falls asleep where it is (it is caught among its neighbours
// at that instant): for good if what is static holds it, else provisionally (rechecked as
// above: a ball squeezed against a neighbour on a slope slides on when the neighbour has
// left). The count is in simulated time, so it does not depend on how steps chop it;
// particles a rebuild sets free are left alone by it for kSettleTime (they are falling).
// restSpeed_ is kRestSpeed for e < 1, or the speed of a hop of kRestHop smallest radii if that
// is higher (large discs under strong gravity); with e = 1 it is the speed of a fall through
// rounding (kRestRoundingGap of the box), so that only particles placed at rest on a support rest,
// and nothing moving ever sleeps (the free-neighbour and rattle rules are off). restGap_ is the
// height of a hop at restSpeed_, restSpeed_²/(2g): waking a sleeper lets it fall at most that
// far, which reaches only restSpeed_ and does not wake what is under it.
// A rebuild (any change to the world) keeps what sleeps where it slept, at its depth (a
// provisional sleeper is rechecked kRecheckAfter after it), if the laws (gravity, box, walls,
// restitution, friction) are unchanged: a particle removed, added, moved or set in motion
// wakes the sleepers within restGap_ of it (and so what they held up); more than
// kMaxDisturbances such changes, or changed laws, wake everything. A drag through a settled
// pile therefore wakes only what the dragged particle touches.
// The event budget under gravity ends the step at the first event left (see
// kMaxEventsPerParticlePerStep): never a particle through the floor. Without gravity the rest
// of the step is flown freely, and a particle that flight takes past a wall is put back on it
// and turned inward by the walls' law (as the discrete mode's wall stage would).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

#include "cell_list.hpp"
#include "contact.hpp"
#include "event_queue.hpp"
#include "exact_collision_rate.hpp"
#include "exact_obstacle_cells.hpp"

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

/// Events one step may process per particle (plus a fixed allowance) before the step ends
/// early: a last-resort guard that keeps the app responsive. The state is then the exact one
/// at the first event left (nothing overlaps, nothing is past a wall), and the rest of the
/// step's time is not simulated; the next step goes on from there. No scene or test that
/// settles reaches it.
inline constexpr std::uint64_t kMaxEventsPerParticlePerStep = 10000;

/// Under gravity: hits on sleeping particles in one step after which a particle wakes the
/// sleepers it hits (see the design note): a backstop for a particle wedged between sleepers,
/// below the step's event budget. No scene or test reaches it.
inline constexpr std::uint32_t kWakeAfterHits = 100000;

/// Under gravity with e < 1, the rattle guard (see the design note): a particle that collides
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
/// imposed, is checked again this long after (seconds; see the design note). Ten milliseconds:
/// four times the 2.6 ms in which a neighbour at the rest speed moves out of the rest gap.
inline constexpr double kRecheckAfter = 0.01;

/// Under gravity with e < 1: speed (m/s) below which a particle comes to rest (see the design
/// note). The guards' kElasticBelowSpeed: bounces above it follow the closed form h·e^(2n).
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

class ExactStepper {
  public:
    /// Advances the event state by dt seconds. Rebuilds it from `p` and `def` first if
    /// invalidate() was called since the last step (or there was none). Does not write `p`:
    /// the state at the end of the step is owed to it until sync(). Updates the counters
    /// (collisions, wallCollisions, wallImpulse, maxOverlap, steps, events).
    void step(ParticleArrays& p, const WorldDef& def, double dt, StepProfile& profile,
              StepCounters& counters);

    /// Whether `p` has not yet received the state of the last step.
    [[nodiscard]] bool owesSync() const { return syncOwed_; }
    /// Writes every particle's position and velocity at the end of the last step into `p`
    /// (the arrays the last rebuild read): one pass over the particles.
    void sync(ParticleArrays& p);

    /// Forces a rebuild at the next step: the world calls it whenever it changes anything the
    /// stepper read (particles, box, walls, material laws), after taking the owed sync.
    void invalidate() { stale_ = true; }

    /// Appends every resolved collision to `log` (nullptr to stop). Indices are storage
    /// indices of `p`; times restart from 0 at each rebuild.
    void setLog(std::vector<CollisionRecord>* log) { log_ = log; }

    /// Bytes held by the event state (per-particle records, every level's cells, the queue,
    /// placed overlaps): what a copy of a world in this mode carries besides its own arrays.
    /// Small bookkeeping vectors are left out.
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    enum class Kind : std::uint8_t { None, Pair, Wall, Obstacle, Slide, Recheck };

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
    static constexpr std::uint32_t kRestX = 16;    // no acceleration along x (on a wall, pinned)
    static constexpr std::uint32_t kRestY = 32;    // no acceleration along y
    static constexpr std::uint32_t kSliding = 64;  // on a segment's face: slide_ holds how
    static constexpr std::uint32_t kProvisional = 128;  // asleep until recheckAt_ (see Resting)
    // A particle sliding on a segment's face (kSliding; exact_obstacle_events.cpp): which
    // segment, and its constant acceleration along the face (gravity's share along it less the
    // kinetic friction, or none where static friction holds it).
    struct Slide {
        std::uint32_t obstacle = 0;
        double ax = 0.0, ay = 0.0;
    };
    // Where a particle is at a time, and how it moves there (gravity only).
    struct Motion {
        double x, y, vx, vy, ax, ay;
    };
    struct Event {
        double time;
        std::uint32_t partner;       // pair: the other particle; obstacle: its index
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
        std::uint8_t level;      // its size class (see Size levels)
        std::uint32_t heldHits;  // collisions with held particles this step (jam guard)
        double w;                // inverse mass, 0 = held
    };
    static_assert(sizeof(Cold) == 64);

    // A size class above level 0: its members are listed in cells of block × block fine cells
    // (cells_ is level 0's list and the fine grid everyone's cell moves follow).
    struct Level {
        CellList cells;
        std::int64_t block = 1;
    };

    void rebuild(ParticleArrays& p, const WorldDef& def);
    // At a rebuild under unchanged laws: what slept and has not moved sleeps on; what the
    // changes touch wakes (see the design note).
    struct Kept {
        Body body;
        std::uint32_t depth;
    };
    void keepSleepers(std::unordered_map<ParticleId, Kept>& before);
    // Changed particles beyond which a rebuild wakes everything (an O(N) search per change).
    static constexpr std::size_t kMaxDisturbances = 64;
    void setUpGrid();
    void sortByCell(bool midRun);
    [[nodiscard]] double bucketWidth() const;
    void advance(std::uint32_t i, double t);
    void scanCells(std::uint32_t i, double now, double ax, double ay, const CellList& list,
                   const std::uint32_t* cells, int cellCount, Event& best);
    void assignLevels(double spacing, double& fineDiameter);
    void setUpLevels();
    [[nodiscard]] bool populous(std::uint8_t level) const;
    [[nodiscard]] bool populousUpperLevel() const;
    [[nodiscard]] std::int64_t reach(std::uint8_t a, std::uint8_t b) const {
        return reach_[a * levelCount_ + b];
    }
    [[nodiscard]] const CellList& listOf(std::uint8_t level) const {
        return level == 0 ? cells_ : upper_[level - 1].cells;
    }
    [[nodiscard]] std::uint32_t memberCell(std::uint32_t i) const;
    void insertMember(std::uint32_t i);
    template <typename F>
    void forCells(std::uint8_t level, std::int64_t x0, std::int64_t x1, std::int64_t y0,
                  std::int64_t y1, F&& f) const;
    void scanBlock(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                   std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1, Event& best);
    void scanNeighbours(std::uint32_t i, double now, double ax, double ay, Event& best);
    // i names the particle (its slide, if any, is slide_[i]); b is its record or a copy of it.
    void accelerationOf(std::uint32_t i, const Body& b, double& ax, double& ay) const;
    [[nodiscard]] Motion motionAt(std::uint32_t i, const Body& b, double t) const;
    [[nodiscard]] static bool isStatic(const Body& b) {
        return (b.flags & kAsleep) || ((b.flags & kHeld) && b.vx == 0.0 && b.vy == 0.0);
    }
    [[nodiscard]] static double pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                                     const Motion& bm, double sigma,
                                                     double horizon);
    // Calls f(q) for every particle q near enough to touch i (i included): the cells of every
    // level within its reach of i's level.
    template <typename F>
    void forEachAround(std::uint32_t i, F&& f) const;
    // What holds i up at time `now` (i is at its position then; see the design note, Resting):
    // `firm` if the static supports do, with one of depth below `below` among them (depth: the
    // sleeper's `depth`, 1 + the least of theirs); `withFree` if they do only with the slow
    // free neighbours added.
    struct Hold {
        bool firm = false, withFree = false;
        std::uint32_t depth = kUngrounded;
    };
    static constexpr std::uint32_t kUngrounded = UINT32_MAX / 2;
    [[nodiscard]] Hold hold(std::uint32_t i, std::uint32_t below, double now) const;
    [[nodiscard]] bool holdsAgainstGravity(const double* nx, const double* ny, int count) const;
    // After an event of i: asleep if slow and held, or caught rattling (see the design note).
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
    // Fixed obstacles (exact_obstacle_events.cpp): i's earliest impact with an obstacle of its
    // cell's list, if earlier than best; the rebound; the supports obstacles give a resting
    // particle (normals appended to nx, ny up to max, returns the new count).
    void predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best);
    void handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters);
    // The rebound off obstacle k at i's current state (a lift or a slide where gravity presses
    // i into it), without the event's bookkeeping; and the same for a slider hit by a pair that
    // is still on its face.
    void reboundOffObstacle(std::uint32_t i, std::uint32_t k, bool recent, StepCounters& counters,
                            bool maySlide = true);
    void keepOnFace(std::uint32_t i, StepCounters& counters, bool maySlide);
    // The sliding contact: entering it at a rebound off a face (false if the face's end is too
    // near), the acceleration along the face, the end-of-face and stop events, leaving it.
    bool startSliding(std::uint32_t i, std::uint32_t k, double nx, double ny);
    void setSlideAcceleration(std::uint32_t i);
    void predictSlide(std::uint32_t i, const Motion& m, double now, Event& best) const;
    void handleSlide(std::uint32_t i, const Event& ev);
    void stopSliding(Body& b) const { b.flags &= ~kSliding; }
    int obstacleSupports(std::uint32_t i, double* nx, double* ny, int count, int max) const;
    [[nodiscard]] static bool collidedWithin(const Body& b, double now);
    [[nodiscard]] double effectiveRestitution(double impactSpeed, bool recent) const;
    // Handles the events up to tEnd; returns the time the state is exact at: tEnd, or, when
    // the budget ran out, the time of the first event left.
    double runEvents(double tEnd, StepCounters& counters, std::uint64_t budget);
    // Counts a hit of i on a held particle or a sleeper this step (heldHits, reset per step);
    // returns the count.
    std::uint32_t countHit(std::uint32_t i);
    void countHeldHit(std::uint32_t i);

    WorldDef def_;
    bool stale_ = true;
    bool gravity_ = false;  // def_.gravity is not zero
    double gx_ = 0.0, gy_ = 0.0;
    double restSpeed_ = 0.0;  // see the design note
    double restGap_ = 0.0;
    std::vector<std::uint32_t> wakeStack_;
    // Per particle, in bodies_' order, with gravity and obstacles only: its sliding contact,
    // read where kSliding is set.
    std::vector<Slide> slide_;
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
    CellList cells_;                    // level 0's members; the fine grid of every cell move
    double skinX_ = 0.0, skinY_ = 0.0;  // how far a centre may stray out of its cell
    std::vector<Level> upper_;          // levels 1, 2, ...
    ObstacleCells obstacles_;           // the fixed obstacles each fine cell may reach
    std::uint8_t levelCount_ = 1;
    // reach_[a · levelCount_ + b]: how many fine cells apart (per axis) a particle of level a
    // and one of level b may be and still touch; 1 for two of level 0.
    std::vector<std::int64_t> reach_;
    std::vector<double> levelRadius_;          // largest radius of each level
    std::vector<std::uint32_t> levelMembers_;  // particles of each level
    EventQueue queue_;
    std::uint64_t eventsSinceSort_ = 0;
    double maxOverlap_ = 0.0;
    // Events handled in this step (pairs, stale pairs, walls, obstacles, slides, cell moves):
    // what step() adds to StepCounters::events.
    std::uint64_t events_ = 0;
    std::vector<CollisionRecord>* log_ = nullptr;
    // Pairs found overlapping at the last rebuild (placed so from outside), keyed by their
    // storage indices (order_), with the contact distance they keep until they are found apart.
    std::unordered_map<std::uint64_t, double> overlapContact_;
    double placedOverlap_ = 0.0;  // the deepest of those overlaps, metres
    bool syncOwed_ = false;       // the world's arrays do not hold the state at clock_ yet
    // The budget ran out without gravity: the rest of the step was flown freely, so sync()
    // turns back into the box what the flight took past a wall (the next step rebuilds).
    bool flewFreely_ = false;
    // Particles with heldHits > 0 this step (the jam guard's counts are reset per step).
    std::vector<std::uint32_t> heldHit_;
};

}  // namespace psb::exact
