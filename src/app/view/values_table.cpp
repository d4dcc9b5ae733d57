#include "view/values_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "session/units.hpp"

namespace psb::app {

const std::array<ValuesColumn, kValuesColumns>& valuesColumns() {
    static const std::array<ValuesColumn, kValuesColumns> columns = {{
        {"x", "m", ParticleField::X},
        {"y", "m", ParticleField::Y},
        {"vx", "m/s", ParticleField::Vx},
        {"vy", "m/s", ParticleField::Vy},
        {"px", "kg m/s", std::nullopt},
        {"py", "kg m/s", std::nullopt},
        {"KE", "J", std::nullopt},
        {"mass", "kg", ParticleField::Mass},
    }};
    return columns;
}

namespace {

std::array<double, kValuesColumns> valuesOf(const Particle& p) {
    return {p.position.x(),
            p.position.y(),
            p.velocity.x(),
            p.velocity.y(),
            p.mass * p.velocity.x(),
            p.mass * p.velocity.y(),
            0.5 * p.mass * p.velocity.squaredNorm(),
            p.mass};
}

}  // namespace

ValuesTable valuesTable(const World& world, std::optional<ParticleId> selected) {
    ValuesTable t;
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    t.totals = {kNaN, kNaN, kNaN, kNaN, 0.0, 0.0, 0.0, 0.0};
    std::vector<ParticleId> ids = world.ids();
    t.particles = ids.size();
    std::sort(ids.begin(), ids.end(),
              [](ParticleId a, ParticleId b) { return particleNumber(a) < particleNumber(b); });
    const bool all = ids.size() <= kValuesMaxRows;
    for (const ParticleId id : ids) {
        const Particle p = world.get(id);
        const auto v = valuesOf(p);
        for (std::size_t k = 4; k < kValuesColumns; ++k)
            t.totals[k] += v[k];
        if (all || (selected && *selected == id)) t.rows.push_back({id, particleNumber(id), v});
    }
    if (!all) {
        t.note = std::to_string(ids.size());
        t.note += " particles: the totals of all, and the selected particle's row";
        if (t.rows.empty()) t.note += " (click one)";
    }
    return t;
}

std::string valuesCell(double value) {
    if (std::isnan(value)) return "";
    return quantity(value, "", false);
}

std::vector<std::string> valuesLines(const ValuesTable& table) {
    std::string header = "#";
    for (const ValuesColumn& c : valuesColumns()) {
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
    return lines;
}

}  // namespace psb::app
