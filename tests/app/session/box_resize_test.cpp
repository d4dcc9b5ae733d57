// The box resized with its particles (box_resize.hpp): expanded, every centre scales with the
// box; squeezed, the gas preset's 4000 discs are pushed apart until none overlaps; a squeeze the
// discs cannot fit into is refused with the reason.

#include "session/box_resize.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/test_assets.hpp"

namespace psb::app {
namespace {

World gasPreset() {
    return makeWorld(loadScene(testAsset("scenes/04-gas-in-a-box.json")));
}

TEST(BoxResize, ExpandedEveryCentreScalesWithTheBoxAndKeepsItsVelocity) {
    const World w = gasPreset();
    const auto out = resizedBox(w, 14.0, 7.0);
    ASSERT_TRUE(std::holds_alternative<World>(out)) << std::get<std::string>(out);
    const World& r = std::get<World>(out);
    EXPECT_EQ(r.def().width, 14.0);
    for (const ParticleId id : w.ids()) {
        EXPECT_NEAR(r.get(id).position.x(), 2.0 * w.get(id).position.x(), 1e-12);
        EXPECT_EQ(r.get(id).position.y(), w.get(id).position.y());
        EXPECT_EQ(r.get(id).velocity, w.get(id).velocity);
    }
}

TEST(BoxResize, SqueezedTheGasPresetsDiscsArePushedApartNotLeftOverlapping) {
    const World w = gasPreset();
    const double side = std::sqrt(0.8);
    const auto out = resizedBox(w, 7.0 * side, 7.0 * side);
    ASSERT_TRUE(std::holds_alternative<World>(out)) << std::get<std::string>(out);
    const World& r = std::get<World>(out);
    EXPECT_LE(maxOverlapBruteForce(r), maxOverlapBruteForce(w) + 1e-8);
    const ParticleArrays& p = r.particles();
    double moved = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_GE(p.x[i], p.radius[i]);
        EXPECT_LE(p.x[i], r.def().width - p.radius[i]);
        const Particle before = w.get(p.id[i]);
        EXPECT_EQ(Vec2(p.vx[i], p.vy[i]), before.velocity);
        moved = std::max(moved, (Vec2(p.x[i], p.y[i]) - side * before.position).norm());
    }
    // Pushing apart moves a disc by a fraction of its size, not across the box.
    EXPECT_LT(moved, 2.0 * 0.025);
}

TEST(BoxResize, AFullBoxCannotBeSqueezedAndADiscWiderThanTheBoxIsNamed) {
    const World w = gasPreset();                  // the discs cover 16 % of the box
    const auto tooFar = resizedBox(w, 2.0, 2.0);  // they would cover 196 %
    ASSERT_TRUE(std::holds_alternative<std::string>(tooFar));
    EXPECT_NE(std::get<std::string>(tooFar).find("would overlap by up to"), std::string::npos);
    const auto narrow = resizedBox(w, 0.04, 7.0);
    ASSERT_TRUE(std::holds_alternative<std::string>(narrow));
    EXPECT_NE(std::get<std::string>(narrow).find("particle 1 (50.0 mm across) would not fit"),
              std::string::npos)
        << std::get<std::string>(narrow);
}

TEST(BoxResize, TinyDiscsInAHugeBoxNeedNoHugeGrid) {
    // Two micrometre discs a kilometre apart in a 10^6 m box, squeezed to a tenth: a grid of
    // cells as wide as a disc would have 10^23 cells.
    WorldDef def;
    def.width = def.height = 1e6;
    World w(def);
    w.add({.position = Vec2(1000.0, 1000.0), .radius = 1e-6});
    w.add({.position = Vec2(2000.0, 1000.0), .radius = 1e-6});
    const auto out = resizedBox(w, 1e5, 1e5);
    ASSERT_TRUE(std::holds_alternative<World>(out)) << std::get<std::string>(out);
    EXPECT_NEAR(std::get<World>(out).get(w.ids()[1]).position.x(), 200.0, 1e-9);
}

}  // namespace
}  // namespace psb::app
