#pragma once
/// \file
/// The particle world: a box, its material laws, its particles, and the step.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/detail/id_table.hpp>
#include <particle_sandbox/dropper.hpp>
#include <particle_sandbox/math.hpp>
#include <particle_sandbox/obstacle.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/particle_arrays.hpp>
#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/step_profile.hpp>
#include <particle_sandbox/world_def.hpp>

namespace psb {

/// Worlds of at least this many particles sort their storage by grid cell (for memory
/// locality) in the discrete and substep modes, once every kReorderInterval steps, starting
/// with their first step; storage indices change then, ids stay valid.
inline constexpr std::size_t kReorderMinParticles = 4096;
inline constexpr unsigned kReorderInterval = 32;

struct StepContext;
namespace exact {
class ExactStepper;
}

/// Owns the particles and advances them in time.
///
/// Every public function validates its arguments and throws psb::InvalidArgument, leaving the
/// world unchanged, when one is out of range. Particles are reached through stable ids; the
/// const ParticleArrays view is for fast read-only iteration (rendering, diagnostics).
///
/// In Exact mode a step leaves the particles' new state inside the event-driven stepper and
/// the first read after it (particles(), get(), pick(), a copy, any mutation) writes it into
/// the arrays, once; steps nobody reads in between cost no work per particle. Reading is
/// therefore not safe from several threads at once right after an exact step.
class World {
  public:
    explicit World(const WorldDef& def = {}, const SolverSettings& solver = {});
    ~World();
    /// A copy is the same world: stepped alike, it stays bit-identical to the original (the
    /// exact mode's event state is copied too, so the copy does not rebuild it).
    World(const World& other);
    World& operator=(const World& other);
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;

    // --- parameters ----------------------------------------------------------------------
    [[nodiscard]] const WorldDef& def() const { return def_; }
    [[nodiscard]] const SolverSettings& solver() const { return solver_; }
    /// Resizes the box (metres, finite and > 0). Particles it no longer contains are allowed:
    /// with walls on, the next step's wall stage brings each centre back into [r, extent - r]
    /// (a particle wider than the box sits at its centre).
    void setBox(double width, double height);
    /// Throws InvalidArgument for walls on in a periodic world (setPeriodic(false) first).
    void setWalls(bool enabled);
    /// Joins the box's opposite edges (WorldDef::periodic) or parts them again. Joined, the walls
    /// go (def().walls becomes false; parted, they stay off until setWalls(true)), particles
    /// wrap into [0, width) × [0, height) at each step, and the world keeps each particle's
    /// unwrapped position (unwrappedPosition). Throws InvalidArgument, changing nothing, when
    /// a particle (or a dropper's ball) is wider than half the box's width or height, or an
    /// obstacle comes within the largest particle's diameter of an edge; while periodic,
    /// setBox, add, setRadius, setObstacles, addObstacle and setDroppers refuse what would break
    /// either rule.
    void setPeriodic(bool enabled);
    /// m/s², y down; any finite vector, in every step mode. Throws InvalidArgument otherwise.
    void setGravity(const Vec2& gravity);
    void setRestitution(double e);
    void setFriction(double mu);
    /// Tangential restitution β of sticking contacts, in [−1, 1] (WorldDef::tangentialRestitution).
    void setTangentialRestitution(double beta);
    /// Throws InvalidArgument for substeps outside [1, kMaxSubsteps], or a mode or broadphase
    /// this build does not have. Every mode takes gravity and obstacles.
    void setSolver(const SolverSettings& solver);

    // --- obstacles ---------------------------------------------------------------------------
    /// The fixed pegs and segments, in index order (def().obstacles).
    [[nodiscard]] const Obstacles& obstacles() const { return def_.obstacles; }
    /// Replaces every obstacle. Throws InvalidArgument, changing nothing, for an obstacle with a
    /// non-finite coordinate, a radius or thickness not finite and > 0, a segment of zero length,
    /// or a centre or end outside the box [0, width] × [0, height]. Every step mode handles
    /// obstacles. setBox refuses a box that would leave an obstacle outside. clear() removes
    /// particles, not obstacles.
    void setObstacles(Obstacles obstacles);
    /// Appends one obstacle (validated as by setObstacles) and returns its index.
    std::size_t addObstacle(const Obstacle& obstacle);
    /// Removes the obstacle at `index`; those after it move down one index. Throws
    /// InvalidArgument for an index past the end.
    void removeObstacle(std::size_t index);

    // --- droppers ----------------------------------------------------------------------------
    /// The ball droppers, in index order, with how far each has got (dropper.hpp).
    [[nodiscard]] const Droppers& droppers() const { return droppers_; }
    /// Replaces every dropper. Throws InvalidArgument, changing nothing, for a dropper with a
    /// value not finite, an interval, radius or mass not > 0, a negative spread, more than
    /// kMaxDropperBalls balls, or a ball that does not fit in the box at its release points;
    /// setBox and setWalls refuse a change that would leave a dropper's balls outside. A world
    /// without droppers skips the drop stage. clear() removes particles, not droppers.
    void setDroppers(Droppers droppers);

    // --- particles -------------------------------------------------------------------------
    /// Adds a particle; its position is taken as given (overlaps are allowed and separated by
    /// the next step). Throws InvalidArgument on a non-finite value, a radius <= 0 or a mass
    /// below the smallest normal double (its inverse would be infinite).
    ParticleId add(const ParticleDef& def);
    /// Removes a particle; returns false if the id names no live particle.
    bool remove(ParticleId id);
    void clear();
    [[nodiscard]] bool contains(ParticleId id) const;
    [[nodiscard]] std::size_t size() const { return p_.size(); }
    /// A copy of the particle's state; throws InvalidArgument for a dead id.
    [[nodiscard]] Particle get(ParticleId id) const;
    /// All live ids, in storage order.
    [[nodiscard]] std::vector<ParticleId> ids() const { return p_.id; }
    /// Storage index of a live particle (valid until the next add, remove or step: large worlds
    /// reorder their storage during steps), or nullopt.
    [[nodiscard]] std::optional<std::size_t> indexOf(ParticleId id) const;

    void setPosition(ParticleId id, const Vec2& position);
    void setVelocity(ParticleId id, const Vec2& velocity);
    void setMass(ParticleId id, double mass);
    void setRadius(ParticleId id, double radius);
    void setColor(ParticleId id, Color color);

    // Rotation. Positive angles and angular velocities turn +x toward +y: clockwise on a screen
    // whose y points down. Contacts change a particle's spin only where there is friction; a
    // world whose particles all have the defaults stores and computes no rotation until then.
    /// Radians, finite (any value: not wrapped).
    void setAngle(ParticleId id, double angle);
    /// Radians per second, finite; a fixed-rotation particle takes only 0.
    void setAngularVelocity(ParticleId id, double omega);
    /// k in the moment of inertia I = k m r², from kMinInertiaFactor (0.001) to 1: 1/2 a
    /// uniform disc, 2/5 a ball seen from the side, 1 a ring.
    void setInertiaFactor(ParticleId id, double k);
    /// A fixed-rotation particle never turns (a puck or block sliding as before rotation
    /// existed): its angular velocity becomes 0 and contacts give it no spin.
    void setFixedRotation(ParticleId id, bool fixed);
    /// Whether the world keeps rotation state (ParticleArrays::rotation): a particle was given
    /// an angle, spin, inertia factor or fixed rotation other than the defaults, or a step ran
    /// with friction. Until then every step is the one of a world without rotation.
    [[nodiscard]] bool rotationInUse() const { return p_.rotation; }

    /// A kinematic particle (one the user holds) is moved by its owner, not by collisions: it
    /// pushes others as if its mass were infinite and is never pushed. It still stays in the box.
    void setKinematic(ParticleId id, bool kinematic);
    [[nodiscard]] bool isKinematic(ParticleId id) const;

    /// The topmost particle (the one drawn last: highest storage index) whose disc contains
    /// `point`. Until a world reaches 4096 particles storage order is insertion order. In a
    /// periodic box, also a disc whose image across an edge contains it, where the disc crosses
    /// that edge (where the app draws the image).
    [[nodiscard]] std::optional<ParticleId> pick(const Vec2& point) const;

    /// The particle's centre as if the box's edges had never wrapped it: its position plus
    /// what the wraps took off it (ParticleArrays::unwrapX, unwrapY), metres. The difference of
    /// two readings is the particle's displacement between them, however often it crossed the
    /// edges (for a mean-squared displacement). In a world that is not periodic, get()'s
    /// position. setPosition moves it by as much as the position. Throws InvalidArgument for a
    /// dead id.
    [[nodiscard]] Vec2 unwrappedPosition(ParticleId id) const;

    [[nodiscard]] const ParticleArrays& particles() const {
        settle();
        return p_;
    }

    // --- collisions ------------------------------------------------------------------------
    /// Starts recording the collisions of the next steps into `log` (collision_log.hpp: every
    /// collision, or only those of chosen particles), replacing any log kept so far, in every
    /// step mode. Until then, and after stopRecordingCollisions(), steps record nothing and
    /// cost nothing more; recording or not, a step's results are bit-identical.
    void recordCollisions(CollisionLog log = {});
    void stopRecordingCollisions() { collisionLog_.reset(); }
    [[nodiscard]] bool recordingCollisions() const { return collisionLog_.has_value(); }
    /// The log being recorded (nullptr when not recording): the records since recording started
    /// or the last takeCollisions(). A copy of the world carries it, and goes on recording.
    [[nodiscard]] const CollisionLog* collisionLog() const {
        return collisionLog_ ? &*collisionLog_ : nullptr;
    }
    /// The records so far, in the order the steps resolved them, leaving the log empty (still
    /// recording); empty when not recording.
    [[nodiscard]] std::vector<Collision> takeCollisions();

    // --- time ------------------------------------------------------------------------------
    /// Advances the world by `dt` seconds (finite, > 0) with the solver's mode. In Exact mode
    /// every particle ends at its exact state at time() + dt, however many events that takes
    /// (unless an event budget is set: setExactEventBudget); any change made to the world
    /// between steps (particles, setters, box) is picked up by the next step.
    ///
    /// The argument is the one source of truth for how far a step goes: the world keeps no step
    /// length of its own. The frame length belongs to the scene (Scene::dt, the file's
    /// `solver.dt`); its driver passes it here: particle-sim the scene's (or --dt), the app's
    /// session the one it keeps in its SceneMeta (src/app/session/document.hpp).
    /// Returns the seconds simulated: dt itself, or less when the exact mode's event budget ran
    /// out (setExactEventBudget).
    double step(double dt);
    /// Simulated seconds since the world was made: the instant the particles' state is at.
    [[nodiscard]] double time() const { return time_; }
    /// Exact mode: the most events one step may process, per particle (the step may process
    /// that many times the particle count plus one), or 0 for no limit (the default, and what a
    /// measurement wants). A step that would process more ends at the first event left: the
    /// state is the exact one at that instant (no pair overlaps, no particle is past a wall),
    /// time() advances only to it, and StepCounters::cutShort counts the step. For a program
    /// whose frames must end (the interactive app), at the price of running behind. Kept by
    /// copies, like the solver settings.
    void setExactEventBudget(std::uint64_t eventsPerParticle) { eventBudget_ = eventsPerParticle; }
    [[nodiscard]] std::uint64_t exactEventBudget() const { return eventBudget_; }

    /// Threads the step may use: n >= 1, or 0 for one per hardware thread (the default).
    /// Results are bit-identical for every thread count.
    void setThreads(int n);
    [[nodiscard]] int threads() const { return threads_; }
    /// The broadphase the last step used (`auto` resolved); before the first step, the one the
    /// next step would use.
    [[nodiscard]] BroadPhaseKind broadPhaseInUse() const;
    /// Reserves storage for `n` particles, so that adding up to `n` allocates nothing.
    void reserve(std::size_t n);
    /// Bytes held by the particle arrays, the id table and the step's scratch (capacities).
    [[nodiscard]] std::size_t memoryBytes() const;
    /// Bytes a copy of this world holds (a copy carries state, not scratch): the particle
    /// arrays, the id table and, once the exact mode has stepped, its event state.
    [[nodiscard]] std::size_t stateBytes() const;
    /// Forgets the exact mode's event state, keeping the particles as they are: a copy kept
    /// for later (an undo history) then holds only what stateBytes() counts without it. The
    /// next exact step rebuilds the events from the arrays, as after any edit.
    void dropEventState();

    /// Whether steps add each pair collision's r_ij·J_ij to StepCounters::pairVirial (the
    /// observables window turns it on while open, observables.hpp). Off by default: then a step
    /// does exactly what it did before the counter existed. On or off, the motion is the same.
    /// Kept by copies.
    void setMeasureVirial(bool on) { measureVirial_ = on; }
    [[nodiscard]] bool measuringVirial() const { return measureVirial_; }

    [[nodiscard]] const StepProfile& profile() const { return profile_; }
    [[nodiscard]] const StepCounters& counters() const { return counters_; }
    void resetCounters() {
        counters_ = {};
        ++counterResets_;
    }
    /// How many times resetCounters() was called (kept by copies): a reader of the counters
    /// between resets (an observables window sampling after frames whose counters the caller
    /// clears) tells a reset from counts that merely did not grow.
    [[nodiscard]] std::uint64_t counterResets() const { return counterResets_; }

  private:
    [[nodiscard]] std::size_t indexOrThrow(ParticleId id, const char* what) const;
    /// Writes the state an exact step left in its stepper into p_, if it owes one.
    void settle() const;
    /// Called by every function that changes what a step reads (particles, box, laws): settles
    /// first, then tells the exact stepper to rebuild at its next step.
    void changed();
    /// Returns the seconds simulated: dt, or less when the event budget ran out.
    double stepExact(double dt);
    /// Makes the rotation arrays (every particle with the defaults) if there are none yet.
    void useRotation();
    /// Makes the unwrap arrays (every offset 0) or drops them, as def_.periodic says.
    void matchUnwrapArrays();
    /// The largest particle radius, dropper balls included (0 for none).
    [[nodiscard]] double largestRadius() const;
    /// The drop stage: each dropper whose ball is due releases it (World::add) if its spot is
    /// clear.
    void releaseBalls(double dt);

    WorldDef def_;
    SolverSettings solver_;
    Droppers droppers_;  ///< state, not parameters: their counts and clocks change as they drop
    mutable ParticleArrays p_;  ///< mutable: settle() fills in what an exact step left owed
    detail::IdTable ids_;
    std::unique_ptr<StepContext> ctx_;
    std::unique_ptr<exact::ExactStepper> exact_;  // event state of the Exact mode, made on use
    int threads_ = 1;
    unsigned stepsUntilReorder_ = 0;  ///< state, not scratch: it decides future storage order
    std::optional<BroadPhaseKind> broadPhaseUsed_;
    double time_ = 0.0;
    std::uint64_t eventBudget_ = 0;  ///< setExactEventBudget's; 0: none
    bool measureVirial_ = false;     ///< setMeasureVirial's
    mutable StepProfile profile_;    ///< mutable: settle() adds the time of the owed sync
    StepCounters counters_;
    std::uint64_t counterResets_ = 0;           ///< resetCounters() calls
    std::optional<CollisionLog> collisionLog_;  ///< recording when set
};

}  // namespace psb
