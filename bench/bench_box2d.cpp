// The gas benchmark scene in Box2D 2.4 (Debian's libbox2d-dev), for a side-by-side figure:
// dynamic circles of radius 1 m and mass 1 kg with fixed rotation, restitution 1, restitution
// threshold 0, friction 0, no gravity, four static edge walls, dt = 0.01 s with Box2D's
// default 8 velocity and 3 position iterations. Box2D is single-threaded. It solves contacts
// differently (soft iterative impulses), so this compares cost, not results.
//
// Name: box2d/n:<N>; items_per_second = particle-steps per second.

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <memory>
#include <string>

#include "gas_scene.hpp"
#include "run_benchmarks.hpp"

namespace psb::bench {
namespace {

void box2dGas(benchmark::State& state, std::size_t n) {
    const GasState g = makeGas(n);
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
    const float side = static_cast<float>(g.side);

    b2BodyDef wallDef;
    b2Body* walls = world->CreateBody(&wallDef);
    const b2Vec2 corners[4] = {{0.0f, 0.0f}, {side, 0.0f}, {side, side}, {0.0f, side}};
    for (int k = 0; k < 4; ++k) {
        b2EdgeShape edge;
        edge.SetTwoSided(corners[k], corners[(k + 1) % 4]);
        b2FixtureDef fd;
        fd.shape = &edge;
        fd.friction = 0.0f;
        fd.restitution = 1.0f;
        fd.restitutionThreshold = 0.0f;
        walls->CreateFixture(&fd);
    }

    b2CircleShape circle;
    circle.m_radius = static_cast<float>(kRadius);
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = static_cast<float>(kMass / (3.141592653589793 * kRadius * kRadius));
    fd.friction = 0.0f;
    fd.restitution = 1.0f;
    fd.restitutionThreshold = 0.0f;
    for (std::size_t k = 0; k < n; ++k) {
        b2BodyDef bd;
        bd.type = b2_dynamicBody;
        bd.fixedRotation = true;
        bd.position.Set(static_cast<float>(g.x[k]), static_cast<float>(g.y[k]));
        bd.linearVelocity.Set(static_cast<float>(g.vx[k]), static_cast<float>(g.vy[k]));
        world->CreateBody(&bd)->CreateFixture(&fd);
    }
    for (int k = 0; k < 3; ++k)
        world->Step(static_cast<float>(kDt), 8, 3);
    for (auto _ : state)
        world->Step(static_cast<float>(kDt), 8, 3);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void registerAll() {
    for (const std::size_t n : {1000, 3000, 10000, 30000, 100000}) {
        const std::string name = "box2d/n:" + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(), box2dGas, n)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace
}  // namespace psb::bench

int main(int argc, char** argv) {
    psb::bench::registerAll();
    return psb::bench::runBenchmarks(argc, argv);
}
