#include "report.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace psb::cli {
namespace {

/// The report's `observables` object: each measured value as {value, error} (error only where
/// the window gave one), what theory predicts beside them, and the window's notes.
nlohmann::ordered_json observablesJson(const ObservablesResult& o) {
    nlohmann::ordered_json j;
    const auto put = [&j](const char* name, const Measured& m) {
        if (!m.valid()) return;
        nlohmann::ordered_json v;
        v["value"] = m.value;
        if (m.hasError()) v["error"] = m.error;
        j[name] = v;
    };
    put("temperature", o.temperature);
    put("rotational_temperature", o.rotationalTemperature);
    put("pressure_virial", o.pressureVirial);
    put("pressure_walls", o.pressureWalls);
    put("compressibility_factor", o.compressibilityFactor);
    put("contact_value", o.contactValue);
    put("collision_rate", o.collisionRate);
    put("wall_collision_rate", o.wallCollisionRate);
    put("mean_free_path", o.meanFreePath);
    put("diffusion_msd", o.diffusionMsd);
    put("diffusion_vacf", o.diffusionVacf);
    j["packing_fraction"] = o.packingFraction;
    j["area"] = o.area;
    j["perimeter"] = o.perimeter;
    j["blocks"] = o.blocks;
    j["block_seconds"] = o.blockDuration;
    nlohmann::ordered_json theory;
    const auto theoryPut = [&theory](const char* name, double v) {
        if (std::isfinite(v)) theory[name] = v;
    };
    theoryPut("henderson_compressibility_factor", o.hendersonZ);
    theoryPut("henderson_contact_value", o.hendersonContact);
    theoryPut("liu_compressibility_factor", o.liuZ);
    theoryPut("enskog_collision_rate", o.enskogCollisionRate);
    theoryPut("enskog_mean_free_path", o.enskogMeanFreePath);
    theoryPut("enskog_diffusion", o.enskogDiffusion);
    if (!theory.empty()) j["theory"] = theory;
    j["notes"] = o.notes;
    return j;
}

}  // namespace

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
    if (r.warmup > 0.0) j["warmup"] = r.warmup;
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
    if (r.observables) j["observables"] = observablesJson(*r.observables);
    return j.dump(2) + "\n";
}

}  // namespace psb::cli
