// Two balls meet head on in the exact (event-driven) mode: the textbook elastic collision.
// Prints the velocities before and after, the ones the conservation laws predict, and the
// total momentum and kinetic energy; exits 1 if the world disagrees with the formula.

#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/world.hpp>

int main() {
    psb::WorldDef box;
    box.width = 10.0;  // metres
    box.height = 2.0;
    psb::SolverSettings exact;
    exact.mode = psb::StepMode::Exact;
    psb::World world(box, exact);

    const double m1 = 1.0, m2 = 3.0;   // kilograms
    const double u1 = 2.0, u2 = -1.0;  // metres per second
    const auto a =
        world.add({.position = {3.0, 1.0}, .velocity = {u1, 0.0}, .mass = m1, .radius = 0.25});
    const auto b =
        world.add({.position = {6.0, 1.0}, .velocity = {u2, 0.0}, .mass = m2, .radius = 0.5});
    const double energyBefore = psb::kineticEnergy(world);
    const double momentumBefore = psb::momentum(world).x();

    world.step(1.0);  // they touch after (6 - 3 - 0.75) / 3 = 0.75 s, and walls are far

    // One-dimensional elastic collision: v1 = ((m1 - m2) u1 + 2 m2 u2) / (m1 + m2), and so on.
    const double v1 = ((m1 - m2) * u1 + 2.0 * m2 * u2) / (m1 + m2);
    const double v2 = ((m2 - m1) * u2 + 2.0 * m1 * u1) / (m1 + m2);
    const double w1 = world.get(a).velocity.x(), w2 = world.get(b).velocity.x();
    std::printf("before: %.3f m/s and %.3f m/s\n", u1, u2);
    std::printf("after:  %.3f m/s and %.3f m/s (predicted %.3f and %.3f)\n", w1, w2, v1, v2);
    std::printf("momentum %.6f -> %.6f kg m/s, kinetic energy %.6f -> %.6f J\n", momentumBefore,
                psb::momentum(world).x(), energyBefore, psb::kineticEnergy(world));
    const bool agrees = std::abs(w1 - v1) < 1e-9 && std::abs(w2 - v2) < 1e-9;
    return agrees ? 0 : 1;
}
