#include <particle_sandbox/data_tables.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include <particle_sandbox/world.hpp>

namespace psb {

using csv::Separator;
using csv::Table;

namespace {

/// A header of column names, some built (the y ones name their direction).
class Header {
  public:
    Header& add(std::string name) {
        names_.push_back(std::move(name));
        return *this;
    }
    /// "vy_m_per_s", or with y up "vy_up_m_per_s": `stem` then "_up" then `_unit`.
    Header& y(const Axes& axes, std::string_view stem, std::string_view unit) {
        return named(stem, axes.yUp ? "_up" : "", unit);
    }
    /// The angular velocity or momentum column: positive clockwise on screen with y down,
    /// counterclockwise with y up (Axes::spin), which "_ccw" says.
    Header& turning(const Axes& axes, std::string_view stem, std::string_view unit) {
        return named(stem, axes.yUp ? "_ccw" : "", unit);
    }
    [[nodiscard]] Table table(Separator separator) const {
        std::vector<std::string_view> views(names_.begin(), names_.end());
        return Table(separator, std::span<const std::string_view>(views));
    }

  private:
    Header& named(std::string_view stem, std::string_view mark, std::string_view unit) {
        std::string name(stem);
        name += mark;
        name += '_';
        name += unit;
        return add(std::move(name));
    }
    std::vector<std::string> names_;
};

}  // namespace

std::string valuesTable(const World& world, Separator separator, const Axes& axes) {
    const bool rotation = world.rotationInUse();
    Header h;
    h.add("particle").add("x_m").y(axes, "y", "m").add("vx_m_per_s").y(axes, "vy", "m_per_s");
    if (rotation) h.turning(axes, "omega", "rad_per_s");
    h.add("px_kg_m_per_s").y(axes, "py", "kg_m_per_s").add("kinetic_energy_J");
    if (rotation) h.add("rotational_energy_J");
    h.add("mass_kg").add("radius_m");
    Table t = h.table(separator);
    std::vector<ParticleId> ids = world.ids();
    std::sort(ids.begin(), ids.end(), [](ParticleId a, ParticleId b) { return a.slot < b.slot; });
    for (const ParticleId id : ids) {
        const Particle p = world.get(id);
        const Vec2 position = axes.point(p.position), velocity = axes.vector(p.velocity);
        t.count(particleNumber(id))
            .number(position.x())
            .number(position.y())
            .number(velocity.x())
            .number(velocity.y());
        if (rotation) t.number(axes.spin(p.angularVelocity));
        t.number(p.mass * velocity.x())
            .number(p.mass * velocity.y())
            .number(0.5 * p.mass * p.velocity.squaredNorm());
        if (rotation) {
            t.number(0.5 * p.inertiaFactor * p.mass * p.radius * p.radius * p.angularVelocity *
                     p.angularVelocity);
        }
        t.number(p.mass).number(p.radius);
        t.endRow();
    }
    return t.str();
}

std::string timeSeriesTable(const std::vector<ObservablesSample>& samples, bool gravity,
                            Separator separator, bool rotation, const Axes& axes,
                            double rateWindowSeconds) {
    Header h;
    h.add("time_s").add("kinetic_energy_J").add("momentum_x_kg_m_per_s");
    h.y(axes, "momentum_y", "kg_m_per_s").add("com_x_m").y(axes, "com_y", "m");
    // A rate over a window says which: its column is read without the docs at hand.
    h.add("collisions")
        .add(rateWindowSeconds > 0.0
                 ? "collision_rate_per_s_last_" + csv::number(rateWindowSeconds) + "_s"
                 : std::string("collision_rate_per_s"));
    if (gravity) h.add("potential_energy_J").add("mechanical_energy_J");
    if (rotation) h.add("rotational_energy_J").turning(axes, "angular_momentum", "kg_m2_per_s");
    Table t = h.table(separator);
    for (const ObservablesSample& s : samples) {
        t.time(s.time)
            .number(s.kineticEnergy)
            .number(s.momentum.x())
            .number(axes.up(s.momentum.y()))
            .number(s.centreOfMass.x())
            .number(axes.y(s.centreOfMass.y()))
            .count(s.collisions);
        // No rate before the series reaches a whole window back: an empty cell, which a
        // spreadsheet reads as missing, not "nan" text or a 0 that was never measured.
        // A count over a window of added steps, to the 12 digits its time has: 2 collisions in
        // 1 s read 2, not 2.000000000000007.
        if (std::isnan(s.collisionRate)) {
            t.text("");
        } else {
            t.text(csv::time(s.collisionRate));
        }
        if (gravity) {
            t.number(s.potentialEnergy)
                .number(s.kineticEnergy + s.rotationalEnergy + s.potentialEnergy);
        }
        if (rotation) {
            t.number(s.rotationalEnergy)
                .number(axes.angularMomentum(s.angularMomentum, s.momentum.x()));
        }
        t.endRow();
    }
    return t.str();
}

std::vector<ObservablesSample> samplesOf(const TimeSeries& series) {
    std::vector<ObservablesSample> out;
    out.reserve(series.size());
    for (std::size_t k = 0; k < series.size(); ++k)
        out.push_back(series[k]);
    return out;
}

std::string trajectoryTable(const Trajectory& trajectory, Separator separator, bool rotation,
                            const Axes& axes) {
    Header h;
    h.add("time_s").add("particle").add("x_m").y(axes, "y", "m").add("vx_m_per_s");
    h.y(axes, "vy", "m_per_s");
    if (rotation) h.turning(axes, "omega", "rad_per_s");
    Table t = h.table(separator);
    for (const TrajectoryPoint& s : trajectory.samples()) {
        t.time(s.time)
            .count(particleNumber(s.id))
            .number(s.position.x())
            .number(axes.y(s.position.y()))
            .number(s.velocity.x())
            .number(axes.up(s.velocity.y()));
        if (rotation) t.number(axes.spin(s.angularVelocity));
        t.endRow();
    }
    return t.str();
}

const char* wallName(WallSide side) {
    switch (side) {
        case WallSide::Left:
            return "left";
        case WallSide::Right:
            return "right";
        case WallSide::Top:
            return "top";
        case WallSide::Bottom:
            break;
    }
    return "bottom";
}

std::string collisionTable(const std::vector<Collision>& collisions, Separator separator,
                           const Axes& axes) {
    Header h;
    h.add("time_s").add("particle").add("with").add("other");
    for (const char* who : {"", "other_"}) {
        for (const char* when : {"before", "after"}) {
            h.add(std::string(who) + "vx_" + when + "_m_per_s");
            h.y(axes, std::string(who) + "vy", std::string(when) + "_m_per_s");
        }
    }
    h.add("impulse_x_N_s").y(axes, "impulse_y", "N_s");
    Table t = h.table(separator);
    for (const Collision& c : collisions) {
        t.time(c.time).count(particleNumber(c.a));
        switch (c.with) {
            case Collision::With::Particle:
                t.text("particle").count(particleNumber(c.b));
                break;
            case Collision::With::Wall:
                t.text("wall").text(wallName(c.wall()));
                break;
            case Collision::With::Obstacle:
                t.text("obstacle").count(c.where);
                break;
        }
        const auto velocity = [&](const Vec2& v) { t.number(v.x()).number(axes.up(v.y())); };
        velocity(c.aBefore);
        velocity(c.aAfter);
        if (c.with == Collision::With::Particle) {
            velocity(c.bBefore);
            velocity(c.bAfter);
        } else {
            t.none().none().none().none();
        }
        velocity(c.impulse);
        t.endRow();
    }
    return t.str();
}

}  // namespace psb
