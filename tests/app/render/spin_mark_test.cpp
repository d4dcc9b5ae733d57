// The spin mark (render/spin_mark.hpp): a contrasting quarter of each turning disc, turned with
// it, drawn by the app's Renderer with SDL's software renderer into an offscreen surface.

#include <gtest/gtest.h>

#include <numbers>

#include "render/offscreen_test.hpp"
#include "render/spin_mark.hpp"

namespace psb::app {
namespace {

constexpr Color kDisc{90, 160, 230};  // light: its mark is dark

class SpinMarkTest : public OffscreenTest {
  protected:
    SpinMarkTest() : OffscreenTest(200) {}

    /// A world of one disc of radius 40 m (40 px) at (100, 100), turned `angle`, its rotation
    /// fixed when `fixed` (the other disc, far away, turns: the world keeps rotation).
    static World oneDisc(double angle, bool fixed) {
        WorldDef def;
        def.width = def.height = 1000.0;
        World w(def);
        const ParticleId id =
            w.add({.position = Vec2(100.0, 100.0), .mass = 1.0, .radius = 40.0, .color = kDisc});
        w.add({.position = Vec2(900.0, 900.0), .mass = 1.0, .radius = 10.0});
        w.setAngularVelocity(w.ids().back(), 1.0);
        w.setAngle(id, angle);
        if (fixed) w.setFixedRotation(id, true);
        return w;
    }

    void draw(const World& w, bool spin = true) {
        ViewOptions o;
        o.arrows = false;
        o.spin = spin;
        renderer_->draw(w, 0.01, camera_, o);
        SDL_RenderPresent(sdl_);
    }

    [[nodiscard]] bool isMark(int x, int y) const {
        const SDL_Color c = pixel(x, y);
        const SDL_Color m = spinMarkColor(kDisc);
        return std::abs(c.r - m.r) <= 4 && std::abs(c.g - m.g) <= 4 && std::abs(c.b - m.b) <= 4;
    }
    [[nodiscard]] bool isDisc(int x, int y) const {
        const SDL_Color c = pixel(x, y);
        return std::abs(c.r - kDisc.r) <= 4 && std::abs(c.g - kDisc.g) <= 4 &&
               std::abs(c.b - kDisc.b) <= 4;
    }
};

TEST_F(SpinMarkTest, TheMarkContrastsWithTheDisc) {
    const SDL_Color dark = spinMarkColor({230, 220, 200});
    EXPECT_LT(dark.r + dark.g + dark.b, 3 * 100) << "a light disc gets a dark mark";
    const SDL_Color light = spinMarkColor({30, 40, 120});
    EXPECT_GT(light.r + light.g + light.b, 3 * 150) << "a dark disc gets a light mark";
}

TEST_F(SpinMarkTest, ATurningDiscShowsAQuarterThatTurnsWithIt) {
    draw(oneDisc(0.0, false));
    // Angle 0: the quarter right of the centre and below it (+x, +y on screen).
    EXPECT_TRUE(isMark(115, 115));
    EXPECT_TRUE(isDisc(85, 115));
    EXPECT_TRUE(isDisc(85, 85));
    EXPECT_TRUE(isDisc(115, 85));
    // A quarter turn clockwise on screen (positive): the quarter below and left of the centre.
    draw(oneDisc(0.5 * std::numbers::pi, false));
    EXPECT_TRUE(isMark(85, 115));
    EXPECT_TRUE(isDisc(115, 115));
    EXPECT_TRUE(isDisc(115, 85));
    // The mark keeps inside the rim: outside the disc the background stays black.
    const SDL_Color out = pixel(100 - 38, 100 + 38);
    EXPECT_EQ(out.r + out.g + out.b, 0);
}

TEST_F(SpinMarkTest, AFixedRotationDiscHasNoMark) {
    draw(oneDisc(0.0, true));
    for (const auto& [x, y] : {std::pair{115, 115}, {85, 115}, {85, 85}, {115, 85}})
        EXPECT_TRUE(isDisc(x, y)) << x << ", " << y;
}

TEST_F(SpinMarkTest, TheSpinOptionHidesTheMarks) {
    draw(oneDisc(0.0, false), false);
    EXPECT_TRUE(isDisc(115, 115));
}

TEST_F(SpinMarkTest, AWorldWithoutRotationDrawsNoMark) {
    WorldDef def;
    def.width = def.height = 1000.0;
    World w(def);
    w.add({.position = Vec2(100.0, 100.0), .mass = 1.0, .radius = 40.0, .color = kDisc});
    ASSERT_FALSE(w.rotationInUse());
    draw(w);
    EXPECT_TRUE(isDisc(115, 115));
}

}  // namespace
}  // namespace psb::app
