#include "broadphase/particle_reorder.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace psb {

void reorderByCell(ParticleArrays& p, detail::IdTable& ids, StepContext& ctx) {
    const std::size_t n = p.size();
    // The top bit of a permutation entry marks a slot already filled.
    if (n < 2 || n >= (std::size_t{1} << 31)) return;
    const ParticleStats stats = measureParticles(p, ctx.threads, ctx.statsScratch);
    // The grid that will find the pairs, so that its cells come in the order it reads them.
    GridBroadPhase& grid = p.periodic ? ctx.periodicGrid.boxGrid() : ctx.grid;
    grid.build(p, stats, ctx.threads);
    const std::span<std::uint32_t> perm = grid.order();  // slot k receives old particle perm[k]
    constexpr std::uint32_t kDone = 0x80000000u;

    // The obstacles stage's free discs (step_context.hpp) move with their particles.
    float* fx = ctx.freeX.data();
    float* fy = ctx.freeY.data();
    float* fr = ctx.freeRadius.data();
    const bool withDiscs = ctx.freeRadius.size() == n;
    auto copy = [&](std::size_t dst, std::size_t src) {
        if (withDiscs) {
            fx[dst] = fx[src];
            fy[dst] = fy[src];
            fr[dst] = fr[src];
        }
        p.x[dst] = p.x[src];
        p.y[dst] = p.y[src];
        p.vx[dst] = p.vx[src];
        p.vy[dst] = p.vy[src];
        p.invMass[dst] = p.invMass[src];
        p.radius[dst] = p.radius[src];
        p.mass[dst] = p.mass[src];
        p.color[dst] = p.color[src];
        p.id[dst] = p.id[src];
        if (p.rotation) {
            p.angle[dst] = p.angle[src];
            p.omega[dst] = p.omega[src];
            p.inertiaFactor[dst] = p.inertiaFactor[src];
            p.fixedRotation[dst] = p.fixedRotation[src];
        }
        if (p.periodic) {
            p.unwrapX[dst] = p.unwrapX[src];
            p.unwrapY[dst] = p.unwrapY[src];
        }
    };
    for (std::size_t s = 0; s < n; ++s) {
        if (perm[s] & kDone) continue;
        if (perm[s] == s) {
            perm[s] |= kDone;
            continue;
        }
        // Follow the cycle s ← perm[s] ← perm[perm[s]] ... back to s.
        const double x = p.x[s], y = p.y[s], vx = p.vx[s], vy = p.vy[s];
        const double invMass = p.invMass[s], radius = p.radius[s], mass = p.mass[s];
        const Color color = p.color[s];
        const ParticleId id = p.id[s];
        const float discX = withDiscs ? fx[s] : 0.0f, discY = withDiscs ? fy[s] : 0.0f;
        const float discRadius = withDiscs ? fr[s] : 0.0f;
        const bool turns = p.rotation;
        const double angle = turns ? p.angle[s] : 0.0, omega = turns ? p.omega[s] : 0.0;
        const double inertia = turns ? p.inertiaFactor[s] : 0.0;
        const std::uint8_t fixed = turns ? p.fixedRotation[s] : 0;
        const bool wraps = p.periodic;
        const double unwrapX = wraps ? p.unwrapX[s] : 0.0, unwrapY = wraps ? p.unwrapY[s] : 0.0;
        std::size_t k = s;
        for (;;) {
            const std::size_t src = perm[k];
            perm[k] |= kDone;
            if (src == s) {
                p.x[k] = x;
                p.y[k] = y;
                p.vx[k] = vx;
                p.vy[k] = vy;
                p.invMass[k] = invMass;
                p.radius[k] = radius;
                p.mass[k] = mass;
                p.color[k] = color;
                p.id[k] = id;
                if (turns) {
                    p.angle[k] = angle;
                    p.omega[k] = omega;
                    p.inertiaFactor[k] = inertia;
                    p.fixedRotation[k] = fixed;
                }
                if (wraps) {
                    p.unwrapX[k] = unwrapX;
                    p.unwrapY[k] = unwrapY;
                }
                if (withDiscs) {
                    fx[k] = discX;
                    fy[k] = discY;
                    fr[k] = discRadius;
                }
                ids.relocate(id, static_cast<std::uint32_t>(k));
                break;
            }
            copy(k, src);
            ids.relocate(p.id[k], static_cast<std::uint32_t>(k));
            k = src;
        }
    }
}

}  // namespace psb
