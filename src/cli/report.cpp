#include "report.hpp"

#include <nlohmann/json.hpp>

namespace psb::cli {

std::string reportJson(const RunReport& r) {
    // nlohmann::ordered_json keeps the fields in the order a reader expects them.
    nlohmann::ordered_json j;
    j["mode"] = std::string(toString(r.solver.mode));
    j["dt"] = r.dt;
    j["substeps"] = r.solver.substeps;
    j["broadphase"] = std::string(toString(r.broadphaseUsed));
    j["broadphase_requested"] = std::string(toString(r.solver.broadphase));
    j["threads"] = r.threads;
    j["particles"] = r.particles;
    j["steps"] = r.steps;
    j["sim_time"] = r.simTime;
    j["wall_seconds"] = r.wallSeconds;
    j["collisions"] = r.collisions;
    j["wall_collisions"] = r.wallCollisions;
    j["obstacles"] = r.obstacles;
    j["obstacle_collisions"] = r.obstacleCollisions;
    j["kinetic_energy"] = {{"initial", r.kineticEnergyInitial}, {"final", r.kineticEnergyFinal}};
    // Friction turns discs: translational kinetic energy flows into rotation and back.
    j["rotational_energy"] = {{"initial", r.rotationalEnergyInitial},
                              {"final", r.rotationalEnergyFinal}};
    if (r.gravity) {
        // Under gravity kinetic energy alone is not conserved; kinetic + potential is.
        j["potential_energy"] = {{"initial", r.potentialEnergyInitial},
                                 {"final", r.potentialEnergyFinal}};
        j["mechanical_energy"] = {
            {"initial",
             r.kineticEnergyInitial + r.rotationalEnergyInitial + r.potentialEnergyInitial},
            {"final", r.kineticEnergyFinal + r.rotationalEnergyFinal + r.potentialEnergyFinal}};
    }
    j["momentum"] = {
        {"initial", {r.momentumInitial.x(), r.momentumInitial.y()}},
        {"final", {r.momentumFinal.x(), r.momentumFinal.y()}},
    };
    // Orbital plus spin, about the box's top-left corner (the origin): kept by every pair
    // contact; walls, obstacles and gravity change it.
    j["angular_momentum"] = {{"initial", r.angularMomentumInitial},
                             {"final", r.angularMomentumFinal}};
    j["wall_impulse"] = r.wallImpulse;
    j["max_overlap"] = r.maxOverlap;
    j["cut_short"] = r.cutShort;
    j["escaped"] = r.escaped;
    if (r.bins) {
        const BinsMeasurement& b = *r.bins;
        nlohmann::ordered_json bins;
        bins["counts"] = b.counts.counts;
        bins["counted"] = b.counts.counted();
        bins["outside"] = b.counts.outside;
        bins["above"] = b.counts.above;
        if (!b.expected.empty()) bins["expected"] = b.expected;
        if (const auto& t = b.test; t && t->valid()) {
            nlohmann::ordered_json chi;
            chi["statistic"] = t->statistic;
            chi["dof"] = t->dof;
            chi["alpha"] = t->alpha;
            chi["critical"] = t->critical;
            chi["p_value"] = t->pValue;
            chi["passes"] = t->passes();
            chi["observed_merged"] = t->observed;
            chi["expected_merged"] = t->expected;
            bins["chi_square"] = chi;
        }
        j["bins"] = bins;
    }
    if (!r.droppers.empty()) {
        nlohmann::ordered_json droppers = nlohmann::ordered_json::array();
        for (const RunReport::DropperCount& d : r.droppers)
            droppers.push_back({{"released", d.released}, {"left", d.left}});
        j["droppers"] = droppers;
    }
    return j.dump(2) + "\n";
}

}  // namespace psb::cli
