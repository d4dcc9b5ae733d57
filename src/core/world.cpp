#include <particle_sandbox/world.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <thread>

#include "broad_phase_auto.hpp"
#include "discrete_step.hpp"
#include "exact_stepper.hpp"
#include "obstacle_validate.hpp"
#include "particle_reorder.hpp"
#include "stage_timer.hpp"
#include "step_context.hpp"
#include "validate.hpp"

namespace psb {

using detail::requireFinite;
using detail::requireInRange;
using detail::requirePositive;

namespace {

void validateDef(const WorldDef& def, const char* where) {
    requirePositive(def.width, where, "width");
    requirePositive(def.height, where, "height");
    requireFinite(def.gravity, where, "gravity");
    requireInRange(def.restitution, 0.0, 1.0, where, "restitution");
    if (!std::isfinite(def.friction) || def.friction < 0.0) {
        detail::fail(where, "friction", "must be finite and >= 0 " + detail::got(def.friction));
    }
    detail::validateObstacles(def.obstacles, def.width, def.height, where);
}

void validateSolver(const SolverSettings& s, const char* where) {
    requirePositive(s.dt, where, "dt");
    if (s.substeps < 1 || s.substeps > kMaxSubsteps) {
        detail::fail(where, "substeps",
                     "must be in [1, " + std::to_string(kMaxSubsteps) + "] (got " +
                         std::to_string(s.substeps) + ")");
    }
    // An enumerator outside the lists (a cast from an integer) would make step() do nothing.
    if (toString(s.mode) == "?") detail::fail(where, "mode", "is not a known step mode");
    if (toString(s.broadphase) == "?") {
        detail::fail(where, "broadphase", "is not a known broadphase");
    }
}

// The exact mode flies particles in straight lines between events; under gravity they would fly
// parabolas, which it does not predict.
void validateModeWithGravity(const SolverSettings& s, const Vec2& gravity, const char* where) {
    if (s.mode == StepMode::Exact && (gravity.x() != 0.0 || gravity.y() != 0.0)) {
        std::ostringstream os;
        os.precision(17);
        os << "must be zero in 'exact' mode (got [" << gravity.x() << ", " << gravity.y()
           << "]): the event-driven step does not support gravity; use 'discrete' or "
              "'substep' for a world with gravity";
        detail::fail(where, "gravity", os.str());
    }
}

void validateParticle(const ParticleDef& d, const char* where) {
    requireFinite(d.position, where, "position");
    requireFinite(d.velocity, where, "velocity");
    detail::requireMass(d.mass, where, "mass");
    requirePositive(d.radius, where, "radius");
}

int hardwareThreads() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(std::min(n, 256u));
}

template <typename T>
void swapRemove(std::vector<T>& v, std::size_t i) {
    v[i] = v.back();
    v.pop_back();
}

}  // namespace

World::World(const WorldDef& def, const SolverSettings& solver)
    : def_(def),
      solver_(solver),
      ctx_(std::make_unique<StepContext>()),
      threads_(hardwareThreads()) {
    validateDef(def, "World");
    validateSolver(solver, "World");
    validateModeWithGravity(solver, def.gravity, "World");
    detail::validateModeWithObstacles(solver, def.obstacles, "World");
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

World::World(const World& other)
    : def_(other.def_),
      solver_(other.solver_),
      p_(other.p_),
      ids_(other.ids_),
      ctx_(std::make_unique<StepContext>()),  // scratch is not state
      threads_(other.threads_),
      stepsUntilReorder_(other.stepsUntilReorder_),
      broadPhaseUsed_(other.broadPhaseUsed_),
      time_(other.time_),
      profile_(other.profile_),
      counters_(other.counters_) {}

World& World::operator=(const World& other) {
    if (this != &other) *this = World(other);
    return *this;
}

void World::setBox(double width, double height) {
    WorldDef d = def_;
    d.width = width;
    d.height = height;
    validateDef(d, "World::setBox");
    def_ = d;
}

void World::setWalls(bool enabled) {
    def_.walls = enabled;
}

void World::setGravity(const Vec2& gravity) {
    requireFinite(gravity, "World::setGravity", "gravity");
    validateModeWithGravity(solver_, gravity, "World::setGravity");
    def_.gravity = gravity;
}

void World::setRestitution(double e) {
    requireInRange(e, 0.0, 1.0, "World::setRestitution", "restitution");
    def_.restitution = e;
}

void World::setFriction(double mu) {
    WorldDef d = def_;
    d.friction = mu;
    validateDef(d, "World::setFriction");
    def_.friction = mu;
}

void World::setSolver(const SolverSettings& solver) {
    validateSolver(solver, "World::setSolver");
    validateModeWithGravity(solver, def_.gravity, "World::setSolver");
    detail::validateModeWithObstacles(solver, def_.obstacles, "World::setSolver");
    solver_ = solver;
}

void World::setObstacles(Obstacles obstacles) {
    detail::validateObstacles(obstacles, def_.width, def_.height, "World::setObstacles");
    detail::validateModeWithObstacles(solver_, obstacles, "World::setObstacles");
    def_.obstacles = std::move(obstacles);
}

std::size_t World::addObstacle(const Obstacle& obstacle) {
    const std::size_t index = def_.obstacles.size();
    detail::validateObstacle(obstacle, index, def_.width, def_.height, "World::addObstacle");
    detail::validateModeWithObstacles(solver_, {obstacle}, "World::addObstacle");
    def_.obstacles.push_back(obstacle);
    return index;
}

void World::removeObstacle(std::size_t index) {
    if (index >= def_.obstacles.size()) {
        detail::fail("World::removeObstacle", "index",
                     "names no obstacle (got " + std::to_string(index) + ", the world has " +
                         std::to_string(def_.obstacles.size()) + ")");
    }
    def_.obstacles.erase(def_.obstacles.begin() + static_cast<std::ptrdiff_t>(index));
}

ParticleId World::add(const ParticleDef& d) {
    validateParticle(d, "World::add");
    if (p_.size() >= UINT32_MAX - 1)
        detail::fail("World::add", "particle count", "is at its limit");
    const auto index = static_cast<std::uint32_t>(p_.size());
    const ParticleId id = ids_.allocate(index);
    p_.x.push_back(d.position.x());
    p_.y.push_back(d.position.y());
    p_.vx.push_back(d.velocity.x());
    p_.vy.push_back(d.velocity.y());
    p_.invMass.push_back(1.0 / d.mass);
    p_.radius.push_back(d.radius);
    p_.mass.push_back(d.mass);
    p_.color.push_back(d.color);
    p_.id.push_back(id);
    return id;
}

bool World::remove(ParticleId id) {
    const auto found = ids_.find(id);
    if (!found) return false;
    const std::size_t i = *found;
    const std::size_t last = p_.size() - 1;
    if (i != last) ids_.relocate(p_.id[last], static_cast<std::uint32_t>(i));
    ids_.release(id);
    swapRemove(p_.x, i);
    swapRemove(p_.y, i);
    swapRemove(p_.vx, i);
    swapRemove(p_.vy, i);
    swapRemove(p_.invMass, i);
    swapRemove(p_.radius, i);
    swapRemove(p_.mass, i);
    swapRemove(p_.color, i);
    swapRemove(p_.id, i);
    return true;
}

void World::clear() {
    ids_.clear();
    p_ = ParticleArrays{};
    stepsUntilReorder_ = 0;
}

void World::setThreads(int n) {
    if (n < 0 || n > 256) {
        detail::fail("World::setThreads", "thread count",
                     "must be 0 (all hardware threads) or 1..256 (got " + std::to_string(n) + ")");
    }
    threads_ = n == 0 ? hardwareThreads() : n;
}

BroadPhaseKind World::broadPhaseInUse() const {
    if (broadPhaseUsed_) return *broadPhaseUsed_;
    std::vector<ParticleStats> scratch;
    return chooseBroadPhase(solver_.broadphase, p_, measureParticles(p_, 1, scratch));
}

void World::reserve(std::size_t n) {
    p_.x.reserve(n);
    p_.y.reserve(n);
    p_.vx.reserve(n);
    p_.vy.reserve(n);
    p_.invMass.reserve(n);
    p_.radius.reserve(n);
    p_.mass.reserve(n);
    p_.color.reserve(n);
    p_.id.reserve(n);
    ids_.reserve(n);
}

std::size_t World::memoryBytes() const {
    std::size_t bytes =
        sizeof(double) * (p_.x.capacity() + p_.y.capacity() + p_.vx.capacity() + p_.vy.capacity() +
                          p_.invMass.capacity() + p_.radius.capacity() + p_.mass.capacity());
    bytes += sizeof(Color) * p_.color.capacity() + sizeof(ParticleId) * p_.id.capacity();
    bytes += ids_.memoryBytes();
    if (ctx_) {
        const StepContext& c = *ctx_;
        bytes += sizeof(ContactPair) * c.pairs.capacity() + c.grid.memoryBytes() +
                 c.quadtree.memoryBytes() + sizeof(ParticleStats) * c.statsScratch.capacity() +
                 sizeof(double) * c.wallImpulseScratch.capacity() +
                 sizeof(std::uint64_t) * c.wallHitScratch.capacity();
        bytes += c.obstacleGrid.memoryBytes() +
                 sizeof(double) * (c.startX.capacity() + c.startY.capacity()) +
                 sizeof(std::uint64_t) * c.obstacleHitScratch.capacity();
        for (const auto& list : c.obstacleCandidates)
            bytes += sizeof(std::uint32_t) * list.capacity();
        for (const auto& list : c.obstacleNearby)
            bytes += sizeof(std::uint32_t) * list.capacity();
    }
    return bytes;
}

bool World::contains(ParticleId id) const {
    return ids_.find(id).has_value();
}

std::optional<std::size_t> World::indexOf(ParticleId id) const {
    const auto found = ids_.find(id);
    if (!found) return std::nullopt;
    return std::size_t{*found};
}

std::size_t World::indexOrThrow(ParticleId id, const char* what) const {
    const auto found = ids_.find(id);
    if (!found) {
        detail::fail(what, "id",
                     "names no live particle (slot " + std::to_string(id.slot) + ", generation " +
                         std::to_string(id.generation) + ")");
    }
    return *found;
}

Particle World::get(ParticleId id) const {
    const std::size_t i = indexOrThrow(id, "World::get");
    return Particle{id,         Vec2(p_.x[i], p_.y[i]), Vec2(p_.vx[i], p_.vy[i]),
                    p_.mass[i], p_.radius[i],           p_.color[i]};
}

void World::setPosition(ParticleId id, const Vec2& position) {
    requireFinite(position, "World::setPosition", "position");
    const std::size_t i = indexOrThrow(id, "World::setPosition");
    p_.x[i] = position.x();
    p_.y[i] = position.y();
}

void World::setVelocity(ParticleId id, const Vec2& velocity) {
    requireFinite(velocity, "World::setVelocity", "velocity");
    const std::size_t i = indexOrThrow(id, "World::setVelocity");
    p_.vx[i] = velocity.x();
    p_.vy[i] = velocity.y();
}

void World::setMass(ParticleId id, double mass) {
    detail::requireMass(mass, "World::setMass", "mass");
    const std::size_t i = indexOrThrow(id, "World::setMass");
    const bool kinematic = p_.invMass[i] == 0.0;
    p_.mass[i] = mass;
    p_.invMass[i] = kinematic ? 0.0 : 1.0 / mass;
}

void World::setRadius(ParticleId id, double radius) {
    requirePositive(radius, "World::setRadius", "radius");
    p_.radius[indexOrThrow(id, "World::setRadius")] = radius;
}

void World::setColor(ParticleId id, Color color) {
    p_.color[indexOrThrow(id, "World::setColor")] = color;
}

void World::setKinematic(ParticleId id, bool kinematic) {
    const std::size_t i = indexOrThrow(id, "World::setKinematic");
    p_.invMass[i] = kinematic ? 0.0 : 1.0 / p_.mass[i];
}

bool World::isKinematic(ParticleId id) const {
    return p_.isKinematic(indexOrThrow(id, "World::isKinematic"));
}

std::optional<ParticleId> World::pick(const Vec2& point) const {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) return std::nullopt;
    // Storage order is drawing order, so the topmost particle is the last one that contains it.
    for (std::size_t i = p_.size(); i-- > 0;) {
        const double dx = point.x() - p_.x[i], dy = point.y() - p_.y[i];
        if (dx * dx + dy * dy <= p_.radius[i] * p_.radius[i]) return p_.id[i];
    }
    return std::nullopt;
}

void World::step(double dt) {
    requirePositive(dt, "World::step", "dt");
    profile_ = {};
    if (!ctx_) ctx_ = std::make_unique<StepContext>();  // a moved-from world is still usable
    ctx_->threads = threads_;
    ctx_->broadPhase = solver_.broadphase;
    // The exact mode keeps its own copy in cell order; reordering the world's storage would only
    // make it rebuild.
    if (p_.size() >= kReorderMinParticles && solver_.mode != StepMode::Exact) {
        if (stepsUntilReorder_ == 0) {
            StageTimer t(profile_.reorder);
            reorderByCell(p_, ids_, *ctx_);
            stepsUntilReorder_ = kReorderInterval;
        }
        --stepsUntilReorder_;
    }
    switch (solver_.mode) {
        case StepMode::Discrete:
            stepDiscrete(dt);
            break;
        case StepMode::Substep: {
            const double h = dt / solver_.substeps;
            for (int k = 0; k < solver_.substeps; ++k)
                stepDiscrete(h);
            break;
        }
        case StepMode::Exact:
            stepExact(dt);
            break;
    }
    profile_.total += profile_.reorder;
    if (solver_.mode != StepMode::Exact) broadPhaseUsed_ = ctx_->broadPhaseUsed;
    time_ += dt;
}

void World::stepDiscrete(double dt) {
    stages::discreteStep(p_, def_, dt, *ctx_, profile_, counters_);
}

void World::stepExact(double dt) {
    // The stepper compares the world with what its last step left and rebuilds its event state
    // on any difference, so every mutator (and a step in another mode) is picked up without
    // each one having to remember to invalidate it.
    if (!exact_) exact_ = std::make_unique<exact::ExactStepper>();
    exact_->step(p_, def_, dt, profile_, counters_);
}

}  // namespace psb
