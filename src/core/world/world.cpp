#include <particle_sandbox/world.hpp>

#include <particle_sandbox/validation.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "broadphase/broad_phase_auto.hpp"
#include "discrete/discrete_step.hpp"
#include "exact/stepper.hpp"
#include "obstacles/obstacle_validate.hpp"
#include "support/periodic_box.hpp"
#include "world/dropper_stage.hpp"
#include "world/periodic_fit.hpp"
#include "world/stage_timer.hpp"
#include "world/step_context.hpp"
#include "world/validate.hpp"

namespace psb {

using detail::requireFinite;
using detail::requirePositive;

namespace {

/// Throws InvalidArgument for the first problem validate() finds, then for the first obstacle
/// that cannot be (validate() leaves each obstacle's geometry to World: its message names the
/// obstacle by index).
void require(const WorldDef& def, const SolverSettings& solver, const char* where) {
    const std::vector<SettingProblem> problems = validate(def, solver);
    if (!problems.empty()) {
        const std::string setting(problems.front().setting);
        detail::fail(where, setting.c_str(), problems.front().message);
    }
    detail::validateObstacles(def.obstacles, def.width, def.height, where);
}

void requireInertiaFactor(double k, const char* where) {
    if (!std::isfinite(k) || !(k >= kMinInertiaFactor) || k > 1.0)
        detail::fail(where, "inertia factor", "must be from 0.001 to 1 " + detail::got(k));
}

void validateParticle(const ParticleDef& d, const char* where) {
    requireFinite(d.position, where, "position");
    requireFinite(d.velocity, where, "velocity");
    detail::requireMass(d.mass, where, "mass");
    requirePositive(d.radius, where, "radius");
    requireFinite(d.angle, where, "angle");
    requireFinite(d.angularVelocity, where, "angular velocity");
    requireInertiaFactor(d.inertiaFactor, where);
    if (d.fixedRotation && d.angularVelocity != 0.0) {
        detail::fail(where, "angular velocity",
                     "must be 0 for a fixed-rotation particle " + detail::got(d.angularVelocity));
    }
}

bool defaultRotation(const ParticleDef& d) {
    return d.angle == 0.0 && d.angularVelocity == 0.0 && d.inertiaFactor == kDefaultInertiaFactor &&
           !d.fixedRotation;
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
    require(def, solver, "World");
    if (def_.periodic) {
        def_.walls = false;  // joined edges have no walls
        detail::requireObstaclesClearOfEdges(def_.obstacles, 0.0, def_.width, def_.height, "World");
        matchUnwrapArrays();
    }
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

World::World(const World& other)
    : def_(other.def_),
      solver_(other.solver_),
      droppers_(other.droppers_),
      p_(other.particles()),  // with what an exact step still owes it
      ids_(other.ids_),
      ctx_(std::make_unique<StepContext>()),  // scratch is not state
      // The exact mode's event state is state: a rebuild from the arrays alone would continue
      // from rounded positions, and the copy would drift from the original in the last bits.
      exact_(other.exact_ ? std::make_unique<exact::ExactStepper>(*other.exact_) : nullptr),
      threads_(other.threads_),
      stepsUntilReorder_(other.stepsUntilReorder_),
      broadPhaseUsed_(other.broadPhaseUsed_),
      time_(other.time_),
      eventBudget_(other.eventBudget_),
      measureVirial_(other.measureVirial_),
      profile_(other.profile_),
      counters_(other.counters_),
      counterResets_(other.counterResets_),
      collisionLog_(other.collisionLog_) {
    if (exact_) exact_->setLog(nullptr);  // the original's log stays the original's
}

World& World::operator=(const World& other) {
    if (this != &other) *this = World(other);
    return *this;
}

void World::setBox(double width, double height) {
    WorldDef d = def_;
    d.width = width;
    d.height = height;
    require(d, solver_, "World::setBox");
    detail::validateDroppers(droppers_, width, height, def_.walls, "World::setBox");
    if (def_.periodic) {
        const double r = largestRadius();
        detail::requireFitsPeriodic(r, width, height, "World::setBox", "largest radius");
        detail::requireObstaclesClearOfEdges(def_.obstacles, r, width, height, "World::setBox");
    }
    changed();
    def_ = d;
}

void World::setWalls(bool enabled) {
    if (enabled && def_.periodic) {
        detail::fail("World::setWalls", "walls",
                     "cannot be on in a periodic world: its edges are joined (setPeriodic(false) "
                     "first)");
    }
    detail::validateDroppers(droppers_, def_.width, def_.height, enabled, "World::setWalls");
    changed();
    def_.walls = enabled;
}

void World::setPeriodic(bool enabled) {
    if (enabled == def_.periodic) return;
    if (enabled) {
        const double r = largestRadius();
        detail::requireFitsPeriodic(r, def_.width, def_.height, "World::setPeriodic",
                                    "largest radius");
        detail::requireObstaclesClearOfEdges(def_.obstacles, r, def_.width, def_.height,
                                             "World::setPeriodic");
        detail::validateDroppers(droppers_, def_.width, def_.height, false, "World::setPeriodic");
    }
    changed();
    def_.periodic = enabled;
    if (enabled) def_.walls = false;
    matchUnwrapArrays();
}

void World::matchUnwrapArrays() {
    p_.periodic = def_.periodic;
    if (def_.periodic) {
        p_.unwrapX.assign(p_.size(), 0.0);
        p_.unwrapY.assign(p_.size(), 0.0);
    } else {
        p_.unwrapX = {};
        p_.unwrapY = {};
    }
}

double World::largestRadius() const {
    double r = 0.0;
    for (const double ri : p_.radius)
        r = std::max(r, ri);
    for (const Dropper& d : droppers_)
        r = std::max(r, d.radius);
    return r;
}

void World::setGravity(const Vec2& gravity) {
    WorldDef d = def_;
    d.gravity = gravity;
    require(d, solver_, "World::setGravity");
    changed();
    def_.gravity = gravity;
}

void World::setRestitution(double e) {
    WorldDef d = def_;
    d.restitution = e;
    require(d, solver_, "World::setRestitution");
    changed();
    def_.restitution = e;
}

void World::setFriction(double mu) {
    WorldDef d = def_;
    d.friction = mu;
    require(d, solver_, "World::setFriction");
    changed();
    def_.friction = mu;
}

void World::setTangentialRestitution(double beta) {
    WorldDef d = def_;
    d.tangentialRestitution = beta;
    require(d, solver_, "World::setTangentialRestitution");
    changed();
    def_.tangentialRestitution = beta;
}

void World::setSolver(const SolverSettings& solver) {
    require(def_, solver, "World::setSolver");
    changed();
    solver_ = solver;
}

void World::setObstacles(Obstacles obstacles) {
    detail::validateObstacles(obstacles, def_.width, def_.height, "World::setObstacles");
    if (def_.periodic) {
        detail::requireObstaclesClearOfEdges(obstacles, largestRadius(), def_.width, def_.height,
                                             "World::setObstacles");
    }
    changed();
    def_.obstacles = std::move(obstacles);
}

std::size_t World::addObstacle(const Obstacle& obstacle) {
    const std::size_t index = def_.obstacles.size();
    detail::validateObstacle(obstacle, index, def_.width, def_.height, "World::addObstacle");
    if (def_.periodic) {
        Obstacles one{obstacle};
        detail::requireObstaclesClearOfEdges(one, largestRadius(), def_.width, def_.height,
                                             "World::addObstacle");
    }
    changed();
    def_.obstacles.push_back(obstacle);
    return index;
}

void World::removeObstacle(std::size_t index) {
    if (index >= def_.obstacles.size()) {
        detail::fail("World::removeObstacle", "index",
                     "names no obstacle (got " + std::to_string(index) + ", the world has " +
                         std::to_string(def_.obstacles.size()) + ")");
    }
    changed();
    def_.obstacles.erase(def_.obstacles.begin() + static_cast<std::ptrdiff_t>(index));
}

void World::setDroppers(Droppers droppers) {
    detail::validateDroppers(droppers, def_.width, def_.height, def_.walls, "World::setDroppers");
    if (def_.periodic) {
        double r = 0.0;
        for (const Dropper& d : droppers) {
            detail::requireFitsPeriodic(d.radius, def_.width, def_.height, "World::setDroppers",
                                        "dropper radius");
            r = std::max(r, d.radius);
        }
        detail::requireObstaclesClearOfEdges(def_.obstacles, r, def_.width, def_.height,
                                             "World::setDroppers");
    }
    droppers_ = std::move(droppers);
}

ParticleId World::add(const ParticleDef& d) {
    validateParticle(d, "World::add");
    if (def_.periodic) {
        detail::requireFitsPeriodic(d.radius, def_.width, def_.height, "World::add", "radius");
        detail::requireObstaclesClearOfEdges(def_.obstacles, d.radius, def_.width, def_.height,
                                             "World::add");
    }
    if (p_.size() >= UINT32_MAX - 1)
        detail::fail("World::add", "particle count", "is at its limit");
    changed();
    // Rotation arrays are made for the particles there are before this one is added.
    if (!defaultRotation(d)) useRotation();
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
    if (p_.rotation) {
        p_.angle.push_back(d.angle);
        p_.omega.push_back(d.angularVelocity);
        p_.inertiaFactor.push_back(d.inertiaFactor);
        p_.fixedRotation.push_back(d.fixedRotation ? 1 : 0);
    }
    if (p_.periodic) {
        p_.unwrapX.push_back(0.0);
        p_.unwrapY.push_back(0.0);
    }
    return id;
}

void World::useRotation() {
    if (p_.rotation) return;
    // Every particle so far has the defaults.
    const std::size_t n = p_.size();
    p_.rotation = true;
    p_.angle.assign(n, 0.0);
    p_.omega.assign(n, 0.0);
    p_.inertiaFactor.assign(n, kDefaultInertiaFactor);
    p_.fixedRotation.assign(n, 0);
}

bool World::remove(ParticleId id) {
    const auto found = ids_.find(id);
    if (!found) return false;
    changed();
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
    if (p_.rotation) {
        swapRemove(p_.angle, i);
        swapRemove(p_.omega, i);
        swapRemove(p_.inertiaFactor, i);
        swapRemove(p_.fixedRotation, i);
    }
    if (p_.periodic) {
        swapRemove(p_.unwrapX, i);
        swapRemove(p_.unwrapY, i);
    }
    return true;
}

void World::clear() {
    changed();
    ids_.clear();
    p_ = ParticleArrays{};
    matchUnwrapArrays();
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
    settle();
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
    if (p_.rotation) {
        p_.angle.reserve(n);
        p_.omega.reserve(n);
        p_.inertiaFactor.reserve(n);
        p_.fixedRotation.reserve(n);
    }
    if (p_.periodic) {
        p_.unwrapX.reserve(n);
        p_.unwrapY.reserve(n);
    }
    ids_.reserve(n);
}

std::size_t World::memoryBytes() const {
    std::size_t bytes =
        sizeof(double) * (p_.x.capacity() + p_.y.capacity() + p_.vx.capacity() + p_.vy.capacity() +
                          p_.invMass.capacity() + p_.radius.capacity() + p_.mass.capacity());
    bytes += sizeof(Color) * p_.color.capacity() + sizeof(ParticleId) * p_.id.capacity();
    bytes +=
        sizeof(double) * (p_.angle.capacity() + p_.omega.capacity() + p_.inertiaFactor.capacity() +
                          p_.unwrapX.capacity() + p_.unwrapY.capacity()) +
        p_.fixedRotation.capacity();
    bytes += ids_.memoryBytes();
    if (ctx_) {
        const StepContext& c = *ctx_;
        bytes += sizeof(ContactPair) * c.pairs.capacity() + c.grid.memoryBytes() +
                 c.quadtree.memoryBytes() + sizeof(ParticleStats) * c.statsScratch.capacity() +
                 sizeof(double) * c.wallImpulseScratch.capacity() +
                 sizeof(std::uint64_t) * c.wallHitScratch.capacity();
        bytes +=
            c.obstacleGrid.memoryBytes() +
            sizeof(double) * (c.startX.capacity() + c.startY.capacity()) +
            sizeof(float) * (c.freeX.capacity() + c.freeY.capacity() + c.freeRadius.capacity()) +
            sizeof(std::uint64_t) * c.obstacleHitScratch.capacity();
        for (const auto& list : c.obstacleCandidates)
            bytes += sizeof(std::uint32_t) * list.capacity();
        for (const auto& list : c.obstacleNearby)
            bytes += sizeof(std::uint32_t) * list.capacity();
    }
    return bytes;
}

std::size_t World::stateBytes() const {
    std::size_t bytes =
        sizeof(double) * (p_.x.size() + p_.y.size() + p_.vx.size() + p_.vy.size() +
                          p_.invMass.size() + p_.radius.size() + p_.mass.size()) +
        sizeof(Color) * p_.color.size() + sizeof(ParticleId) * p_.id.size() +
        sizeof(double) * (p_.angle.size() + p_.omega.size() + p_.inertiaFactor.size() +
                          p_.unwrapX.size() + p_.unwrapY.size()) +
        p_.fixedRotation.size() + ids_.memoryBytes();
    if (exact_) bytes += exact_->memoryBytes();
    return bytes;
}

void World::dropEventState() {
    settle();
    exact_.reset();
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
    settle();
    Particle out{id,         Vec2(p_.x[i], p_.y[i]), Vec2(p_.vx[i], p_.vy[i]),
                 p_.mass[i], p_.radius[i],           p_.color[i]};
    if (p_.rotation) {
        out.angle = p_.angle[i];
        out.angularVelocity = p_.omega[i];
        out.inertiaFactor = p_.inertiaFactor[i];
        out.fixedRotation = p_.fixedRotation[i] != 0;
    }
    return out;
}

Vec2 World::unwrappedPosition(ParticleId id) const {
    const std::size_t i = indexOrThrow(id, "World::unwrappedPosition");
    settle();
    if (!p_.periodic) return {p_.x[i], p_.y[i]};
    return {p_.x[i] + p_.unwrapX[i], p_.y[i] + p_.unwrapY[i]};
}

void World::setPosition(ParticleId id, const Vec2& position) {
    requireFinite(position, "World::setPosition", "position");
    const std::size_t i = indexOrThrow(id, "World::setPosition");
    changed();
    p_.x[i] = position.x();
    p_.y[i] = position.y();
}

void World::setVelocity(ParticleId id, const Vec2& velocity) {
    requireFinite(velocity, "World::setVelocity", "velocity");
    const std::size_t i = indexOrThrow(id, "World::setVelocity");
    changed();
    p_.vx[i] = velocity.x();
    p_.vy[i] = velocity.y();
}

void World::setMass(ParticleId id, double mass) {
    detail::requireMass(mass, "World::setMass", "mass");
    const std::size_t i = indexOrThrow(id, "World::setMass");
    changed();
    const bool kinematic = p_.invMass[i] == 0.0;
    p_.mass[i] = mass;
    p_.invMass[i] = kinematic ? 0.0 : 1.0 / mass;
}

void World::setRadius(ParticleId id, double radius) {
    requirePositive(radius, "World::setRadius", "radius");
    const std::size_t i = indexOrThrow(id, "World::setRadius");
    if (def_.periodic) {
        detail::requireFitsPeriodic(radius, def_.width, def_.height, "World::setRadius", "radius");
        detail::requireObstaclesClearOfEdges(def_.obstacles, radius, def_.width, def_.height,
                                             "World::setRadius");
    }
    changed();
    p_.radius[i] = radius;
}

void World::setAngle(ParticleId id, double angle) {
    requireFinite(angle, "World::setAngle", "angle");
    const std::size_t i = indexOrThrow(id, "World::setAngle");
    if (!p_.rotation && angle == 0.0) return;
    changed();
    useRotation();
    p_.angle[i] = angle;
}

void World::setAngularVelocity(ParticleId id, double omega) {
    requireFinite(omega, "World::setAngularVelocity", "angular velocity");
    const std::size_t i = indexOrThrow(id, "World::setAngularVelocity");
    if (!p_.rotation && omega == 0.0) return;
    if (p_.rotation && p_.fixedRotation[i] && omega != 0.0) {
        detail::fail("World::setAngularVelocity", "angular velocity",
                     "must be 0 for a fixed-rotation particle " + detail::got(omega));
    }
    changed();
    useRotation();
    p_.omega[i] = omega;
}

void World::setInertiaFactor(ParticleId id, double k) {
    requireInertiaFactor(k, "World::setInertiaFactor");
    const std::size_t i = indexOrThrow(id, "World::setInertiaFactor");
    if (!p_.rotation && k == kDefaultInertiaFactor) return;
    changed();
    useRotation();
    p_.inertiaFactor[i] = k;
}

void World::setFixedRotation(ParticleId id, bool fixed) {
    const std::size_t i = indexOrThrow(id, "World::setFixedRotation");
    if (!p_.rotation && !fixed) return;
    changed();
    useRotation();
    p_.fixedRotation[i] = fixed ? 1 : 0;
    if (fixed) p_.omega[i] = 0.0;
}

void World::setColor(ParticleId id, Color color) {
    p_.color[indexOrThrow(id, "World::setColor")] = color;
}

void World::setKinematic(ParticleId id, bool kinematic) {
    const std::size_t i = indexOrThrow(id, "World::setKinematic");
    changed();
    p_.invMass[i] = kinematic ? 0.0 : 1.0 / p_.mass[i];
}

bool World::isKinematic(ParticleId id) const {
    return p_.isKinematic(indexOrThrow(id, "World::isKinematic"));
}

std::optional<ParticleId> World::pick(const Vec2& point) const {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) return std::nullopt;
    settle();
    // Storage order is drawing order, so the topmost particle is the last one that contains it.
    if (!def_.periodic) {
        for (std::size_t i = p_.size(); i-- > 0;) {
            const double dx = point.x() - p_.x[i], dy = point.y() - p_.y[i];
            if (dx * dx + dy * dy <= p_.radius[i] * p_.radius[i]) return p_.id[i];
        }
        return std::nullopt;
    }
    // A periodic box: the disc or the image of it that contains the point, where an image is
    // drawn (the disc crosses the edge it is drawn across), so that a click on any part of a
    // disc seen over an edge picks it.
    const periodic::Box box{def_.width, def_.height};
    for (std::size_t i = p_.size(); i-- > 0;) {
        const double sx = point.x() - p_.x[i], sy = point.y() - p_.y[i];
        const double dx = box.imageX(sx), dy = box.imageY(sy);
        const double r = p_.radius[i];
        if (dx * dx + dy * dy > r * r) continue;
        const double ox = sx - dx, oy = sy - dy;  // the image's offset, whole boxes
        const bool drawn =
            (ox == 0.0 || (ox > 0.0 ? p_.x[i] - r < 0.0 : p_.x[i] + r > def_.width)) &&
            (oy == 0.0 || (oy > 0.0 ? p_.y[i] - r < 0.0 : p_.y[i] + r > def_.height));
        if (drawn) return p_.id[i];
    }
    return std::nullopt;
}

double World::step(double dt) {
    requirePositive(dt, "World::step", "dt");
    profile_ = {};
    if (!ctx_) ctx_ = std::make_unique<StepContext>();  // a moved-from world is still usable
    if (!droppers_.empty()) releaseBalls(dt);
    ctx_->threads = threads_;
    ctx_->broadPhase = solver_.broadphase;
    ctx_->collisionLog = collisionLog_ ? &*collisionLog_ : nullptr;
    ctx_->measureVirial = measureVirial_;
    ctx_->stepStart = time_;
    // Friction turns discs: from the first step with friction on, the world keeps rotation.
    if (def_.friction > 0.0 && !p_.rotation) {
        changed();
        useRotation();
    }
    // A step in another mode works on the arrays: they must hold the state, and the exact
    // stepper must rebuild from what that step leaves. The exact mode keeps its own copy in
    // cell order, so it never reorders the world's storage.
    double simulated = dt;
    switch (solver_.mode) {
        case StepMode::Discrete:
        case StepMode::Substep:
            changed();
            stages::discreteSteps(p_, ids_, def_, dt,
                                  solver_.mode == StepMode::Substep ? solver_.substeps : 1, *ctx_,
                                  stepsUntilReorder_, profile_, counters_);
            break;
        case StepMode::Exact:
            simulated = stepExact(dt);
            break;
    }
    if (solver_.mode != StepMode::Exact) broadPhaseUsed_ = ctx_->broadPhaseUsed;
    profile_.total += profile_.ms("drop");
    time_ += simulated;
    return simulated;
}

void World::releaseBalls(double dt) {
    // Listed first, and only in a world with droppers: a scene without any pays nothing.
    double& stageMs = profile_.stage("drop");
    // The state an exact step owes is written first, under its own stage ("sync").
    const bool due = std::any_of(droppers_.begin(), droppers_.end(),
                                 [dt](const Dropper& d) { return detail::ballDue(d, dt); });
    if (due) settle();
    double ms = 0.0;
    {
        StageTimer t(ms);
        for (Dropper& d : droppers_) {
            bool released = false, waiting = false;
            if (detail::ballDue(d, dt)) {
                const ParticleDef ball = detail::nextBall(d);
                // A new particle is a change to the world: in the exact mode the next step
                // rebuilds its events, keeping asleep what sleeps away from the new ball.
                const periodic::Box box{def_.width, def_.height};
                released = detail::spotClear(p_, ball, def_.periodic ? &box : nullptr);
                waiting = !released;
                if (released) add(ball);
            }
            detail::advanceDropper(d, dt, released, waiting);
        }
    }
    stageMs += ms;
}

void World::settle() const {
    if (exact_ && exact_->owesSync()) {
        double ms = 0.0;
        {
            StageTimer t(ms);
            exact_->sync(p_);
        }
        profile_.stage("sync") += ms;
        profile_.total += ms;
    }
}

void World::changed() {
    settle();
    if (exact_) exact_->invalidate();
}

double World::stepExact(double dt) {
    // Every function that changes what the stepper read calls changed(), which makes it
    // rebuild at this step; otherwise it carries on from its own state.
    if (!exact_) exact_ = std::make_unique<exact::ExactStepper>();
    exact_->record(ctx_->collisionLog, time_);
    exact_->measureVirial(measureVirial_);
    return exact_->step(p_, def_, dt, eventBudget_, profile_, counters_);
}

void World::recordCollisions(CollisionLog log) {
    collisionLog_ = std::move(log);
}

std::vector<Collision> World::takeCollisions() {
    return collisionLog_ ? collisionLog_->take() : std::vector<Collision>{};
}

}  // namespace psb
