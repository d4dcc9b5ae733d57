// Between scenes and worlds: makeWorld and sceneFromWorld.

#include <particle_sandbox/scene.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

#include "broadphase/overlap_check.hpp"
#include "world/validate.hpp"

namespace psb {

World makeWorld(const Scene& scene) {
    // Not the world's to keep, but a scene that cannot be stepped is refused here, as the rest.
    detail::requirePositive(scene.dt, "makeWorld", "dt");
    World world(scene.world, scene.solver);
    for (const ParticleDef& d : scene.particles)
        world.add(d);
    world.setDroppers(scene.droppers);
    return world;
}

Scene sceneFromWorld(const World& world, double dt, std::string name, std::string description) {
    Scene s;
    s.name = std::move(name);
    s.description = std::move(description);
    s.world = world.def();
    s.solver = world.solver();
    s.dt = dt;
    s.droppers = world.droppers();
    const ParticleArrays& p = world.particles();
    // In number order (particleNumber), so that the scene opens with the particles numbered as
    // they were, the gaps left by removed ones closed.
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&p](std::size_t a, std::size_t b) { return p.id[a].slot < p.id[b].slot; });
    s.particles.reserve(p.size());
    for (const std::size_t i : order) {
        ParticleDef d;
        d.position = {p.x[i], p.y[i]};
        d.velocity = {p.vx[i], p.vy[i]};
        d.mass = p.mass[i];
        d.radius = p.radius[i];
        d.color = p.color[i];
        if (p.rotation) {
            d.angle = p.angle[i];
            d.angularVelocity = p.omega[i];
            d.inertiaFactor = p.inertiaFactor[i];
            d.fixedRotation = p.fixedRotation[i] != 0;
        }
        s.particles.push_back(d);
    }
    // A world may hold overlaps the loader refuses by default (particles placed overlapping, an
    // obstacle drawn over a particle, the discrete mode's resting contacts): the scene says so,
    // so that it loads again.
    const WorldDef& w = s.world;
    s.allowOverlaps = (w.periodic ? detail::findOverlapPeriodic(s.particles, w.width, w.height)
                                  : detail::findOverlap(s.particles))
                          .has_value() ||
                      detail::findObstacleOverlap(s.particles, s.world.obstacles).has_value();
    return s;
}

}  // namespace psb
