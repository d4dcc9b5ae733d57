#include "discrete_step.hpp"

#include "broad_phase_all_pairs.hpp"
#include "stage_timer.hpp"

namespace psb::stages {

void applyGravity(ParticleArrays& p, const Vec2& gravity, double dt) {
    const double gx = gravity.x() * dt, gy = gravity.y() * dt;
    const std::size_t n = p.size();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    const double* w = p.invMass.data();
    for (std::size_t i = 0; i < n; ++i) {
        // Kinematic particles (w == 0) are moved by their owner, not by forces.
        const double k = w[i] > 0.0 ? 1.0 : 0.0;
        vx[i] += k * gx;
        vy[i] += k * gy;
    }
}

void move(ParticleArrays& p, double dt) {
    const std::size_t n = p.size();
    double* x = p.x.data();
    double* y = p.y.data();
    const double* vx = p.vx.data();
    const double* vy = p.vy.data();
    for (std::size_t i = 0; i < n; ++i) {
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
    }
}

void findPairs(const ParticleArrays& p, StepContext& ctx) {
    ctx.pairs.clear();
    findPairsAllPairs(p, ctx.pairs);
}

void discreteStep(ParticleArrays& p, const WorldDef& def, double dt, StepContext& ctx,
                  StepProfile& profile, StepCounters& counters) {
    StageTimer total(profile.total);
    if (def.gravity.x() != 0.0 || def.gravity.y() != 0.0) {
        StageTimer t(profile.gravity);
        applyGravity(p, def.gravity, dt);
    }
    {
        StageTimer t(profile.move);
        move(p, dt);
    }
    {
        StageTimer t(profile.findPairs);
        findPairs(p, ctx);
    }
    {
        StageTimer t(profile.resolve);
        resolve(p, def, ctx, counters);
    }
    {
        StageTimer t(profile.separate);
        separate(p, ctx);
    }
    if (def.walls) {
        StageTimer t(profile.walls);
        walls(p, def, counters);
    }
    ++counters.steps;
}

}  // namespace psb::stages
