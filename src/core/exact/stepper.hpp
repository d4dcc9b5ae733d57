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
// What it is made of (src/core/exact/). Each concept is a type that owns its state:
//   EventQueue         event_queue.*         the event calendar: two keys per particle
//   Grid               grid.*, cell_list.*   the cells: fine cells with a skin, size levels,
//                                            the walks over them, the order of a re-sort
//   ObstacleCells      obstacle_cells.*      the fixed obstacles each fine cell may reach
//   PlacedContacts     placed_contacts.*     pairs placed overlapping, at their placed distance
//   Resting            resting.*             the resting contacts under gravity: what holds a
//                                            particle, sleep, provisional sleep, waking,
//                                            rattling, sleepers kept across a rebuild
//   Slides             slides.*              the sliding contact on a segment's face
//   Rolls              rolls.*               each disc's rotation; slipping, then rolling, on
//                                            a face or a wall
//   JamGuard           jam_guard.*           particles with no room: held squeezes, jams
//   CollisionRecorder  collision_recorder.hpp  where resolved collisions go
// They share the per-particle records (body.hpp: Body, Cold, and the Slide and Turn the
// slides and rolls keep; all in the stepper's cell order) and lean on free functions: motion
// (motion.hpp: lazy advance, on a parabola under gravity), the collision rules
// (collision_rules.hpp) and the times of impact (time_of_impact.hpp for straight lines,
// parabolic_impact.hpp under gravity, obstacle_impact.hpp for obstacles).
//
// The stepper owns the particle records and composes the parts. What is left to it is the
// orchestration: which part is asked what, in which order, and every prediction that follows:
//   stepper.cpp             the loop: step(), runEvents(), sync(); the re-sort into cell order
//   stepper_rebuild.cpp     the state rebuilt from the world's arrays
//   stepper_prediction.cpp  a particle's next collision and next cell move; the cell move
//   stepper_collisions.cpp  pair and wall events
//   stepper_obstacles.cpp   events with fixed pegs and segments
//   stepper_surfaces.cpp    slides and rolls started, and their own events
//   stepper_resting.cpp     sleep and wake carried out (Resting decides), predicted again
//
// Ties. Events at the same instant are handled in key order (particle index, collision before
// cell move); equal candidate times in a prediction go to the lower partner index. Indices are
// the cell order of the last sort, which depends only on the state, so the same state always
// gives the same sequence.
//
// Walls off: no wall events, particles fly free; the cell grid folds onto itself
// (cell_list.hpp) so space is unbounded.
//
// Periodic boxes (WorldDef::periodic). The cells tile the box as with walls, but its edges are
// faces like any other: a particle leaving the last column is a cell move into the first one,
// at which its centre moves by a box width (an exact shift of its line of flight but for one
// rounding) and what moved it is added to its unwrapped offset. The box's own faces have no
// skin, so every centre stays in the box but for rounding. Searches read the cells around a
// particle as images: a range of cell coordinates past an edge is the other side's cells,
// their members seen a box width away (scanBlock), so a pair is predicted across an edge and a
// corner exactly as inside the box, with the two-events argument unchanged; where the box is
// one or two cells across the same cell comes back as several images, each searched. Events
// of a pair measure it between nearest images (the only ones that can touch: World keeps each
// diameter at most half the box). No wall events. The world's arrays receive centres wrapped
// into [0, width) × [0, height) and the offsets (sync).
//
// The event budget (World::setExactEventBudget; none unless the caller sets one, as the
// interactive app does for its frames) ends a step that would process more events at the
// first event left: the state is the exact one at that instant (never a pair through each
// other, never a particle past a wall), step() returns the time it reached, and the rest of
// the step is not simulated. Without a budget a step always reaches its end.

#include <cstdint>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

#include "contact/contact.hpp"
#include "exact/body.hpp"
#include "exact/cell_list.hpp"
#include "exact/collision_recorder.hpp"
#include "exact/collision_rules.hpp"
#include "exact/event_queue.hpp"
#include "exact/grid.hpp"
#include "exact/jam_guard.hpp"
#include "exact/motion.hpp"
#include "exact/obstacle_cells.hpp"
#include "exact/placed_contacts.hpp"
#include "exact/resting.hpp"
#include "exact/rolls.hpp"
#include "exact/slides.hpp"

namespace psb::exact {

/// Of the box's extent: how far past a wall its event may leave a particle's centre before
/// handleWall puts it back on the wall (rounding of the event's time at extreme speeds; found by
/// the world mutation fuzzer with 10¹³ m/s).
inline constexpr double kWallSlack = 1e-12;

/// Of the box's larger extent: the room across an axis (extent − 2r) below which a particle is
/// held on the centre line like one wider than the box (Cold::pinX, pinY). Found by the world
/// mutation fuzzer: a disc of 10⁻³⁰¹ m in a box 10⁻³⁰⁰ m wide and 2.7 m high bounced between
/// the side walls every 10⁻³⁰¹ s.
inline constexpr double kNoRoom = 1e-12;

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

    /// Whether the next steps add each pair collision's r_ij·J_ij to StepCounters::pairVirial.
    void measureVirial(bool on) { virial_ = on; }

    /// Bytes held by the event state (per-particle records, every level's cells, the queue,
    /// placed overlaps): what a copy of a world in this mode carries besides its own arrays.
    /// Small bookkeeping vectors are left out.
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    // --- the loop (stepper.cpp) ---------------------------------------------------------------
    // Handles the events up to tEnd; returns the time the state is exact at: tEnd, or, when
    // the budget (0: none) ran out, the time of the first event left.
    double runEvents(double tEnd, StepCounters& counters, std::uint64_t budget);
    // Re-sorts the particles into cell order (Grid::cellOrder), every part's per-particle
    // state with them; `midRun`: the scheduled events and the cell lists follow.
    void sortByCell(bool midRun);

    // --- rebuild (stepper_rebuild.cpp) --------------------------------------------------------
    void rebuild(ParticleArrays& p, const WorldDef& def);
    [[nodiscard]] double bucketWidth() const;

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

    // --- prediction (stepper_prediction.cpp) --------------------------------------------------
    void predictCollision(std::uint32_t i, double now);
    void predictWallsUnderGravity(std::uint32_t i, const Motion& m, double now, Event& best) const;
    void predictCell(std::uint32_t i, double now);
    void scanNeighbours(std::uint32_t i, double now, double ax, double ay, Event& best);
    void scanBlock(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                   std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1, Event& best);
    // (sx, sy): where the cells' members are seen, metres from where they are (their images
    // across the edges of a periodic box; 0 otherwise).
    void scanCells(std::uint32_t i, double now, double ax, double ay, const CellList& list,
                   const std::uint32_t* cells, int cellCount, Event& best, double sx = 0.0,
                   double sy = 0.0);
    // scanBlock in a periodic box: the range cut at the box's edges, each piece searched as
    // the image it is.
    void scanBlockPeriodic(std::uint32_t i, double now, double ax, double ay, std::uint8_t level,
                           std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1,
                           Event& best);
    [[nodiscard]] static double pairTimeUnderGravity(const Body& a, const Motion& am, const Body& b,
                                                     const Motion& bm, double sigma,
                                                     double horizon);
    void handleCell(std::uint32_t i, double now);

    // --- pair and wall events (stepper_collisions.cpp) ----------------------------------------
    void handlePair(std::uint32_t i, const Event& ev, StepCounters& counters);
    void handleWall(std::uint32_t i, const Event& ev, StepCounters& counters);
    // Before a collision of i at time t: true while i is jammed (jam_guard.hpp), its velocity
    // absorbed.
    bool jamsAt(std::uint32_t i, double t);

    // --- resting, gravity only (resting.hpp; stepper_resting.cpp) ----------------------------
    // What resting reads around a particle: the stepper's parts.
    [[nodiscard]] Surroundings around() {
        return {bodies_, cold_, grid_, obstacles_, slides_, rolls_, gravity_, def_};
    }
    // At a rebuild under unchanged laws: what slept and has not moved sleeps on; what the
    // changes touch wakes.
    void keepSleepers(Resting::Snapshot& before);
    // After an event of i: asleep if slow and held, or caught rattling; after a pair (or an
    // event that ends like one), off the wall it rested on if pushed off, settled, and its roll
    // set again.
    void settle(std::uint32_t i, double now, bool slow);
    void settleAfterPair(std::uint32_t i, bool justWoken);
    // Particle i asleep at `now`, brought there; awake at `now`, and with it every sleeper it
    // held up (each predicted again as it wakes).
    void fallAsleep(std::uint32_t i, double now, std::uint32_t depth, bool provisional);
    void wake(std::uint32_t i, double now);
    void handleRecheck(std::uint32_t i, const Event& ev);
    void sleepNeighboursAtRest(std::uint32_t i, double now);

    // --- fixed obstacles (stepper_obstacles.cpp) ----------------------------------------------
    // i's earliest impact with an obstacle of its cell's list, if earlier than best; the
    // rebound.
    void predictObstacles(std::uint32_t i, const Motion& m, double now, Event& best);
    void handleObstacle(std::uint32_t i, const Event& ev, StepCounters& counters);
    // The rebound off obstacle k at i's current state (a lift or a slide where gravity presses
    // i into it), without the event's bookkeeping.
    void reboundOffObstacle(std::uint32_t i, std::uint32_t k, bool recent, StepCounters& counters,
                            bool maySlide = true);

    // --- sliding on a segment's face (slides.hpp; stepper_surfaces.cpp) -----------------------
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

    // --- slipping and rolling on a face or a wall (rolls.hpp; stepper_surfaces.cpp) ----------
    // The phase i's contact calls for at bodies_[i].t (Rolls::set); the slip-to-roll event.
    void setRoll(std::uint32_t i) {
        rolls_.set(i, bodies_[i], cold_[i], slides_, obstacles_, gravity_, def_.friction);
    }
    void handleRoll(std::uint32_t i, const Event& ev);

    // --- what it is made of ---------------------------------------------------------------
    WorldDef def_;
    Gravity gravity_;  // def_.gravity
    // The particles, in cell order (a rebuild sorts them, and the loop every kResortEvery·N
    // events) so that a 3 × 3 neighbourhood is three short runs of memory; order_ maps this
    // order back to the world's storage indices, ids_ to their ids.
    std::vector<Body> bodies_;
    std::vector<Cold> cold_;
    std::vector<std::uint32_t> order_;
    std::vector<ParticleId> ids_;
    EventQueue queue_;         // the event calendar
    Grid grid_;                // the cells and size levels
    ObstacleCells obstacles_;  // the fixed obstacles each fine cell may reach
    PlacedContacts placed_;    // pairs placed overlapping at the last rebuild
    Resting rest_;             // the resting contacts (gravity only)
    Slides slides_;            // sliding contacts (gravity with obstacles or rough contacts)
    Rolls rolls_;              // rotations (a world that keeps rotation); rough contacts
    JamGuard jams_;
    bool virial_ = false;         // measureVirial's: not state, the world sets it before each step
    CollisionRecorder recorder_;  // where resolved collisions go (setLog, record)

    // --- the loop's bookkeeping ----------------------------------------------------------------
    bool stale_ = true;      // a rebuild is due (invalidate)
    double clock_ = 0.0;     // seconds since the last rebuild
    bool syncOwed_ = false;  // the world's arrays do not hold the state at clock_ yet
    std::uint64_t eventsSinceSort_ = 0;
    // Events handled in this step (pairs, stale pairs, walls, obstacles, slides, cell moves):
    // what step() adds to StepCounters::events; and the deepest overlap met in it.
    std::uint64_t events_ = 0;
    double maxOverlap_ = 0.0;
    std::vector<std::uint32_t> wakeStack_;  // the wake cascade's particles to look around
    // Periodic boxes: what the wraps have taken off each particle's centre (in cell order), as
    // ParticleArrays::unwrapX, unwrapY keep it; empty otherwise.
    std::vector<double> unwrapX_, unwrapY_;
};

}  // namespace psb::exact
