#include <particle_sandbox/data_tables.hpp>

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

#include <particle_sandbox/world.hpp>

namespace psb {

using csv::Separator;
using csv::Table;

std::string valuesTable(const World& world, Separator separator) {
    Table t(separator, {"particle", "x_m", "y_m", "vx_m_per_s", "vy_m_per_s", "px_kg_m_per_s",
                        "py_kg_m_per_s", "kinetic_energy_J", "mass_kg", "radius_m"});
    std::vector<ParticleId> ids = world.ids();
    std::sort(ids.begin(), ids.end(), [](ParticleId a, ParticleId b) { return a.slot < b.slot; });
    for (const ParticleId id : ids) {
        const Particle p = world.get(id);
        const Vec2 momentum = p.mass * p.velocity;
        t.count(particleNumber(id))
            .number(p.position.x())
            .number(p.position.y())
            .number(p.velocity.x())
            .number(p.velocity.y())
            .number(momentum.x())
            .number(momentum.y())
            .number(0.5 * p.mass * p.velocity.squaredNorm())
            .number(p.mass)
            .number(p.radius);
        t.endRow();
    }
    return t.str();
}

std::string timeSeriesTable(const std::vector<ObservablesSample>& samples, bool gravity,
                            Separator separator, bool rotation) {
    std::vector<std::string_view> columns = {
        "time_s",  "kinetic_energy_J", "momentum_x_kg_m_per_s", "momentum_y_kg_m_per_s", "com_x_m",
        "com_y_m", "collisions",       "collision_rate_per_s"};
    if (gravity) {
        columns.push_back("potential_energy_J");
        columns.push_back("mechanical_energy_J");
    }
    if (rotation) {
        columns.push_back("rotational_energy_J");
        columns.push_back("angular_momentum_kg_m2_per_s");
    }
    Table t(separator, std::span<const std::string_view>(columns));
    for (const ObservablesSample& s : samples) {
        t.time(s.time)
            .number(s.kineticEnergy)
            .number(s.momentum.x())
            .number(s.momentum.y())
            .number(s.centreOfMass.x())
            .number(s.centreOfMass.y())
            .count(s.collisions)
            .number(s.collisionRate);
        if (gravity) {
            t.number(s.potentialEnergy)
                .number(s.kineticEnergy + s.rotationalEnergy + s.potentialEnergy);
        }
        if (rotation) t.number(s.rotationalEnergy).number(s.angularMomentum);
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

std::string trajectoryTable(const Trajectory& trajectory, Separator separator) {
    Table t(separator, {"time_s", "particle", "x_m", "y_m", "vx_m_per_s", "vy_m_per_s"});
    for (const TrajectoryPoint& s : trajectory.samples()) {
        t.time(s.time)
            .count(particleNumber(s.id))
            .number(s.position.x())
            .number(s.position.y())
            .number(s.velocity.x())
            .number(s.velocity.y());
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

std::string collisionTable(const std::vector<Collision>& collisions, Separator separator) {
    Table t(separator,
            {"time_s", "particle", "with", "other", "vx_before_m_per_s", "vy_before_m_per_s",
             "vx_after_m_per_s", "vy_after_m_per_s", "other_vx_before_m_per_s",
             "other_vy_before_m_per_s", "other_vx_after_m_per_s", "other_vy_after_m_per_s",
             "impulse_x_N_s", "impulse_y_N_s"});
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
        t.number(c.aBefore.x()).number(c.aBefore.y()).number(c.aAfter.x()).number(c.aAfter.y());
        if (c.with == Collision::With::Particle) {
            t.number(c.bBefore.x()).number(c.bBefore.y()).number(c.bAfter.x()).number(c.bAfter.y());
        } else {
            t.none().none().none().none();
        }
        t.number(c.impulse.x()).number(c.impulse.y());
        t.endRow();
    }
    return t.str();
}

}  // namespace psb
