#include "view/values_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "session/units.hpp"

namespace psb::app {

std::vector<ValuesColumn> valuesColumns(bool rotation) {
    std::vector<ValuesColumn> c = {
        {"x", "m", ParticleField::X},     {"y", "m", ParticleField::Y},
        {"vx", "m/s", ParticleField::Vx}, {"vy", "m/s", ParticleField::Vy},
        {"px", "kg m/s", std::nullopt},   {"py", "kg m/s", std::nullopt},
        {"KE", "J", std::nullopt},        {"mass", "kg", ParticleField::Mass},
    };
    if (rotation) {
        c.insert(c.begin() + 4, {"\u03c9", "rad/s", ParticleField::Omega});
        c.insert(c.begin() + 8, {"KE rot", "J", std::nullopt});
    }
    return c;
}

namespace {

std::vector<double> valuesOf(const Particle& p, bool rotation, const Axes& axes) {
    const Vec2 position = axes.point(p.position), velocity = axes.vector(p.velocity);
    std::vector<double> v = {position.x(),
                             position.y(),
                             velocity.x(),
                             velocity.y(),
                             p.mass * velocity.x(),
                             p.mass * velocity.y(),
                             0.5 * p.mass * p.velocity.squaredNorm(),
                             p.mass};
    if (rotation) {
        v.insert(v.begin() + 4, axes.spin(p.angularVelocity));
        v.insert(v.begin() + 8, 0.5 * p.inertiaFactor * p.mass * p.radius * p.radius *
                                    p.angularVelocity * p.angularVelocity);
    }
    return v;
}

}  // namespace

ValuesTable valuesTable(const World& world, std::optional<ParticleId> selected, const Axes& axes) {
    ValuesTable t;
    const bool rotation = world.rotationInUse();
    t.columns = valuesColumns(rotation);
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    // Positions and velocities have no meaningful sum; the rest (after the velocities) do.
    const std::size_t firstSum = rotation ? 5 : 4;
    t.totals.assign(t.columns.size(), 0.0);
    for (std::size_t k = 0; k < firstSum; ++k)
        t.totals[k] = kNaN;
    // The totals straight from the arrays: a table of 10^4 particles shows one row, and a
    // Particle and a row of values built for each every frame cost a tenth of the frame.
    const ParticleArrays& a = world.particles();
    t.particles = a.size();
    double px = 0.0, py = 0.0, ke = 0.0, keRot = 0.0, mass = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        px += a.mass[i] * a.vx[i];
        py += a.mass[i] * a.vy[i];
        ke += 0.5 * a.mass[i] * (a.vx[i] * a.vx[i] + a.vy[i] * a.vy[i]);
        if (rotation) {
            keRot += 0.5 * a.inertiaFactor[i] * a.mass[i] * a.radius[i] * a.radius[i] * a.omega[i] *
                     a.omega[i];
        }
        mass += a.mass[i];
    }
    std::size_t k = firstSum;
    for (const double total : {px, axes.up(py), ke})
        t.totals[k++] = total;
    if (rotation) t.totals[k++] = keRot;
    t.totals[k] = mass;
    const bool all = a.size() <= kValuesMaxRows;
    if (all) {
        std::vector<ParticleId> ids = world.ids();
        std::sort(ids.begin(), ids.end(),
                  [](ParticleId x, ParticleId y) { return particleNumber(x) < particleNumber(y); });
        for (const ParticleId id : ids)
            t.rows.push_back({id, particleNumber(id), valuesOf(world.get(id), rotation, axes)});
    } else if (selected && world.contains(*selected)) {
        t.rows.push_back(
            {*selected, particleNumber(*selected), valuesOf(world.get(*selected), rotation, axes)});
    }
    t.axes = axesNote(axes, rotation);
    if (!all) {
        t.note = std::to_string(a.size());
        t.note += " particles: the totals of all, and the selected particle's row";
        if (t.rows.empty()) t.note += " (click one)";
    }
    return t;
}

std::string axesNote(const Axes& axes, bool rotation) {
    std::string s =
        axes.yUp ? "y up from the floor; vy, py up" : "y down from the top edge; vy, py down";
    if (rotation) s += axes.yUp ? "; \u03c9 counterclockwise" : "; \u03c9 clockwise";
    s += axes.yUp ? " (Show: y up)" : " (Show: y up is off)";
    return s;
}

std::string valuesCell(double value) {
    if (std::isnan(value)) return "";
    return quantity(value, "", false);
}

std::vector<std::string> valuesLines(const ValuesTable& table) {
    std::string header = "#";
    for (const ValuesColumn& c : table.columns) {
        header += '\t';
        header += c.name;
        header += " (";
        header += c.unit;
        header += ')';
    }
    std::vector<std::string> lines{header};
    for (const ValuesRow& r : table.rows) {
        std::string line = std::to_string(r.number);
        for (const double v : r.values) {
            line += '\t';
            line += valuesCell(v);
        }
        lines.push_back(line);
    }
    std::string totals = "total";
    for (const double v : table.totals) {
        totals += '\t';
        totals += valuesCell(v);
    }
    lines.push_back(totals);
    if (!table.note.empty()) lines.push_back(table.note);
    if (!table.axes.empty()) lines.push_back(table.axes);
    return lines;
}

}  // namespace psb::app
