// The exact stepper's state rebuilt from the world's arrays, after any change to the world:
// the particles copied and clamped into the box, the grid and its levels set up, the particles
// sorted into cell order, the pairs placed overlapping recorded (placed_contacts.hpp), and every
// particle's two events predicted. What slept and still may sleeps on (keepSleepers, resting.hpp).

#include <algorithm>
#include <cmath>

#include "exact/grid.hpp"
#include "exact/motion.hpp"
#include "exact/stepper.hpp"
#include "exact/time_of_impact.hpp"
#include "support/periodic_box.hpp"

namespace psb::exact {

void ExactStepper::rebuild(ParticleArrays& p, const WorldDef& def) {
    // What was asleep before, where it was (gravity only; see resting.hpp).
    Resting::Snapshot before;
    const bool sameLaws = gravity_.on && def.gravity == def_.gravity && def.width == def_.width &&
                          def.height == def_.height && def.walls == def_.walls &&
                          def.periodic == def_.periodic && def.restitution == def_.restitution &&
                          def.friction == def_.friction;
    if (sameLaws) rest_.remember(bodies_, ids_, gravity_, slides_, clock_, before);
    def_ = def;
    clock_ = 0.0;
    gravity_.x = def.gravity.x();
    gravity_.y = def.gravity.y();
    gravity_.on = gravity_.x != 0.0 || gravity_.y != 0.0;
    const auto n = static_cast<std::uint32_t>(p.size());
    bodies_.resize(n);
    cold_.resize(n);
    order_.resize(n);

    ids_ = p.id;
    jams_.reset();
    rest_.reset(def_, gravity_, p, n);
    rolls_.reset(p, def.friction);
    // Slides on faces, and rolls on faces and walls (rolls.hpp).
    slides_.reset(gravity_.on && (!def_.obstacles.empty() || rolls_.rough()) ? n : 0);
    // A periodic box: centres wrapped into it, what that took off added to the offsets.
    unwrapX_.clear();
    unwrapY_.clear();
    if (def_.periodic) {
        unwrapX_.assign(p.unwrapX.begin(), p.unwrapX.end());
        unwrapY_.assign(p.unwrapY.begin(), p.unwrapY.end());
        unwrapX_.resize(n, 0.0);
        unwrapY_.resize(n, 0.0);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        Body& b = bodies_[i];
        Cold& c = cold_[i];
        b = Body{p.x[i],  p.y[i], p.vx[i],
                 p.vy[i], 0.0,    p.radius[i],
                 kNever,  0,      p.invMass[i] == 0.0 ? kHeld : 0u};
        c = Cold{Event{kNever, 0, 0, Kind::None, 0},
                 p.mass[i],
                 0,
                 0,
                 0,
                 false,
                 false,
                 0,
                 0,
                 p.invMass[i]};
        order_[i] = i;
        if (def_.periodic) {
            periodic::wrapInto(b.x, unwrapX_[i], def_.width);
            periodic::wrapInto(b.y, unwrapY_[i], def_.height);
        }
        if (def_.walls) {
            // Into the box, as the discrete mode's wall stage would; a particle too wide for
            // an axis sits on the centre line with no velocity across it. So does one with no
            // room at the scene's scale (kNoRoom): bouncing across it would take ~10¹² events
            // per second for each metre per second of its speed across the box.
            const double noRoom = kNoRoom * std::max(def_.width, def_.height);
            const auto place = [noRoom](double& x, double& v, double r, double extent) {
                if (r >= extent - r || extent - 2.0 * r < noRoom) {
                    x = 0.5 * extent;
                    v = 0.0;
                    return true;
                }
                x = std::clamp(x, r, extent - r);
                return false;
            };
            c.pinX = place(b.x, b.vx, b.r, def_.width);
            c.pinY = place(b.y, b.vy, b.r, def_.height);
            // A pinned axis has no room to fall along: gravity across it is held by the walls.
            if (gravity_.on && c.pinX) b.flags |= kRestX;
            if (gravity_.on && c.pinY) b.flags |= kRestY;
            if (c.pinX && c.pinY) b.flags |= kPinned;
        }
    }
    grid_.setUp(def_, bodies_, cold_);
    obstacles_.build(def_.obstacles, grid_.fine(), grid_.skinX(), grid_.skinY(),
                     grid_.largestRadius());
    sortByCell(false);
    eventsSinceSort_ = 0;
    for (std::uint32_t i = 0; i < n; ++i)
        grid_.insert(i, cold_[i]);
    placed_.record(bodies_, cold_, order_, grid_, {def_.width, def_.height});
    queue_.reset(2 * n, bucketWidth());
    if (!before.empty()) keepSleepers(before);
    for (std::uint32_t i = 0; i < n; ++i) {
        predictCollision(i, 0.0);
        predictCell(i, 0.0);
    }
    stale_ = false;
}

double ExactStepper::bucketWidth() const {
    // About 1/64 of the time a typical particle takes to cross a cell: the current bucket then
    // holds a few percent of the 2N events, and the 256-bucket calendar spans ~4 crossings.
    double v2 = 0.0;
    for (const Body& b : bodies_)
        v2 += b.vx * b.vx + b.vy * b.vy;
    const CellList& cells = grid_.fine();
    const double side = std::min(cells.faceX(1) - cells.faceX(0), cells.faceY(1) - cells.faceY(0));
    // Under gravity speeds grow to about √(g·side) within a cell crossing.
    if (gravity_.on)
        v2 += static_cast<double>(bodies_.size()) * std::hypot(gravity_.x, gravity_.y) * side;
    if (!(v2 > 0.0)) return 1.0;
    const double vrms = std::sqrt(v2 / static_cast<double>(bodies_.size()));
    return side / vrms / 64.0;
}

}  // namespace psb::exact
