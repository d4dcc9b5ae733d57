// Rendering with SDL's software renderer into an offscreen surface: no window, no display.
// Camera: zoom 1 pixel per metre, offset 0, so world metres are surface pixels.

#include <gtest/gtest.h>

#include <memory>

#include <SDL.h>

#include "gui/control_panel.hpp"
#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"
#include "render/overlay_drawing.hpp"
#include "render/renderer.hpp"
#include "render/selection_outline.hpp"
#include "render/text.hpp"
#include "session/camera.hpp"
#include "view/hud.hpp"
#include "view/inspector_lines.hpp"
#include "view/mass_shade.hpp"
#include "view/overlays.hpp"
#include "view/periodic_box.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 400;
/// The frame length the worlds drawn here are stepped by (a scene file's default dt): what the
/// renderer's resting speed is measured against.
constexpr double kFrame = 0.01;

class RenderTest : public OffscreenTest {
  protected:
    explicit RenderTest(int size = kSize) : OffscreenTest(size) {}

    DrawStats draw(const World& w, ViewOptions o) {
        const DrawStats s = renderer_->draw(w, kFrame, camera_, o);
        SDL_RenderPresent(sdl_);
        return s;
    }

    /// Clears to black and draws the text panels of `o` where the app's layout puts them.
    void drawPanels(const Overlays& o) {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        LayoutRequest req;
        req.width = size_;
        req.height = size_;
        req.hud = textBoxSize(*font_, o.hud);
        if (o.showProfile) req.profile = textBoxSize(*font_, o.profile);
        req.inspector = textBoxSize(*font_, o.inspector);
        req.messages = textBoxSize(*font_, o.messages);
        layout_ = layoutPanels(req);
        drawOverlays(sdl_, *font_, o, layout_);
        SDL_RenderPresent(sdl_);
    }
    PanelLayout layout_;

    /// Pixels in [x0,x1)×[y0,y1) whose channels are all at least `min`.
    int brightPixels(int x0, int y0, int x1, int y1, int min = 200) const {
        int n = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const SDL_Color c = pixel(x, y);
                n += c.r >= min && c.g >= min && c.b >= min;
            }
        }
        return n;
    }

    static World worldWith(Vec2 pos, Vec2 vel, double radius, Color color) {
        WorldDef def;
        def.width = 1000.0;  // walls outside the surface
        def.height = 1000.0;
        World w(def);
        ParticleDef d;
        d.position = pos;
        d.velocity = vel;
        d.radius = radius;
        d.mass = 2.0;
        d.color = color;
        w.add(d);
        return w;
    }
};

bool isColor(SDL_Color c, Uint8 r, Uint8 g, Uint8 b, int tol = 8) {
    return std::abs(c.r - r) <= tol && std::abs(c.g - g) <= tol && std::abs(c.b - b) <= tol;
}

TEST_F(RenderTest, WhileAVideoRecordsTheMessagesAreDrawnAfterTheRestOfTheFrame) {
    // "Recording video ..." spoke to the teacher at the screen and was in the students' video:
    // the video takes the frame between drawOverlays and drawMessages.
    Overlays o;
    o.messages = {"Recording video (MP4, 60 fps) to a file"};
    drawPanels(o);
    const PixelRect m = layout_.messages;
    ASSERT_GT(m.w, 0);
    const int lit = brightPixels(m.x, m.y, m.x + m.w, m.y + m.h, 150);
    EXPECT_GT(lit, 20) << "the messages drawn with the rest when no video records";
    o.messagesAfterCapture = true;
    drawPanels(o);
    EXPECT_EQ(brightPixels(m.x, m.y, m.x + m.w, m.y + m.h, 150), 0)
        << "left out of the frame the video takes";
    drawMessages(sdl_, *font_, o, layout_);
    SDL_RenderPresent(sdl_);
    EXPECT_EQ(brightPixels(m.x, m.y, m.x + m.w, m.y + m.h, 150), lit) << "then drawn, the same";
}

TEST_F(RenderTest, WhileAVideoRecordsTheHudsKeyHintsAreDrawnAfterTheFrameIsTaken) {
    // "H: help" and "Space continues from here, Shift+Left/Right step" were in the students'
    // video: the frame the video takes holds the readings, the hints are drawn over it after.
    Overlays o;
    o.hud = {"Time 1.58 s | x1 | PAUSED", "Viewing 0.98 s back: Space continues from here",
             "H: help"};
    o.hudRecorded = {"Time 1.58 s | x1 | PAUSED", "Viewing 0.98 s back"};
    o.messagesAfterCapture = true;
    drawPanels(o);
    const PixelRect h = layout_.hud;
    const int lh = font_->lineHeight();
    ASSERT_GT(h.w, 0);
    const int hintX = h.x + font_->measure("Viewing 0.98 s back") + 8;
    const int readings = brightPixels(h.x, h.y, h.x + h.w, h.y + 2 * lh, 150);
    EXPECT_GT(readings, 20) << "the readings are in the video";
    EXPECT_EQ(brightPixels(hintX, h.y + lh, h.x + h.w, h.y + 2 * lh, 150), 0)
        << "the keys to step through the past are not";
    EXPECT_EQ(brightPixels(h.x, h.y + 2 * lh + 4, h.x + h.w, h.y + 3 * lh + 2, 150), 0)
        << "nor H: help";
    drawMessages(sdl_, *font_, o, layout_);
    SDL_RenderPresent(sdl_);
    EXPECT_GT(brightPixels(hintX, h.y + lh, h.x + h.w, h.y + 2 * lh, 150), 20)
        << "the one at the screen reads them";
    EXPECT_GT(brightPixels(h.x, h.y + 2 * lh + 4, h.x + h.w, h.y + 3 * lh + 2, 150), 10);
}

TEST_F(RenderTest, TheHelpCoversThePanelsUnderItWhole) {
    // The help's first lines had the HUD's text showing through them (drawn at 245 of 255):
    // under the help every pixel is the same whatever the HUD says.
    Overlays o;
    o.showHelp = true;
    o.helpAt = {0, 0};
    o.help = std::vector<std::string>(6, std::string(50, ' '));
    o.hud = {"WWWWWWWWWWWWWWWWWWWWWWWWW", "WWWWWWWWWWWWWWWWWWWWWWWWW"};
    const PixelPoint help = textBoxSize(*font_, o.help);
    const auto under = [&] {
        std::vector<Uint8> out;
        for (int y = 0; y < help.y; ++y) {
            for (int x = 0; x < help.x; ++x) {
                const SDL_Color c = pixel(x, y);
                out.insert(out.end(), {c.r, c.g, c.b});
            }
        }
        return out;
    };
    drawPanels(o);
    ASSERT_GT(layout_.hud.w, 0);
    ASSERT_LE(layout_.hud.x + layout_.hud.w, help.x) << "the help covers the HUD";
    ASSERT_LE(layout_.hud.y + layout_.hud.h, help.y);
    const std::vector<Uint8> withHud = under();
    o.hud.clear();
    drawPanels(o);
    EXPECT_TRUE(under() == withHud) << "the HUD shows through the help";
}

TEST_F(RenderTest, AParticleColoursThePixelsOfItsDisc) {
    const World w = worldWith({150, 200}, Vec2::Zero(), 20.0, {255, 0, 0});
    draw(w, {});
    EXPECT_TRUE(isColor(pixel(150, 200), 255, 0, 0));
    EXPECT_TRUE(isColor(pixel(150 + 15, 200), 255, 0, 0));  // inside the rim
    EXPECT_TRUE(isColor(pixel(150, 200 - 15), 255, 0, 0));
    EXPECT_TRUE(isColor(pixel(150 + 25, 200), 0, 0, 0));       // just outside
    EXPECT_TRUE(isColor(pixel(150 + 16, 200 + 16), 0, 0, 0));  // the disc's corner is empty
    EXPECT_TRUE(isColor(pixel(300, 300), 0, 0, 0));
}

TEST_F(RenderTest, TheCameraPlacesTheDisc) {
    const World w = worldWith({150, 200}, Vec2::Zero(), 20.0, {0, 255, 0});
    camera_.set(2.0, Vec2(100, 150));  // (150, 200) -> (100, 100), radius 40 px
    draw(w, {});
    EXPECT_TRUE(isColor(pixel(100, 100), 0, 255, 0));
    EXPECT_TRUE(isColor(pixel(135, 100), 0, 255, 0));
    EXPECT_TRUE(isColor(pixel(145, 100), 0, 0, 0));
}

TEST_F(RenderTest, ManyParticlesAreDrawn) {
    WorldDef def;
    def.width = 1000.0;
    def.height = 1000.0;
    World w(def);
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            ParticleDef d;
            d.position = {20.0 + 35.0 * i, 20.0 + 35.0 * j};
            d.radius = 5.0;
            d.color = {0, 0, 255};
            w.add(d);
        }
    }
    const DrawStats s = draw(w, {});
    EXPECT_EQ(s.drawn, 100u);
    for (int i = 0; i < 10; ++i) {
        EXPECT_TRUE(isColor(pixel(20 + 35 * i, 20 + 35 * (9 - i)), 0, 0, 255)) << i;
    }
}

TEST_F(RenderTest, ABallThreeTimesAsHeavyIsFilledInADarkerShadeOfTheSameColour) {
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        World w = worldWith({100, 200}, {0, 0}, 20.0, Color{150, 170, 190});
        ParticleDef heavy;
        heavy.position = {300, 200};
        heavy.radius = 20.0;
        heavy.mass = 6.0;  // the first's 2 kg, three times
        heavy.color = Color{150, 170, 190};
        w.add(heavy);
        ViewOptions o;
        o.theme = theme;
        draw(w, o);
        const Color drawn = theme == Theme::Light ? lightColour(heavy.color) : heavy.color;
        const MassShades shades = massShades(drawn, theme);
        const SDL_Color a = pixel(100, 200), b = pixel(300, 200);
        EXPECT_TRUE(isColor(a, shades.light.r, shades.light.g, shades.light.b, 2));
        EXPECT_TRUE(isColor(b, shades.heavy.r, shades.heavy.g, shades.heavy.b, 2));
        EXPECT_GE(contrastRatio(Rgba{a.r, a.g, a.b}, Rgba{b.r, b.g, b.b}), kMinContrast - 0.05);
        // The same two discs of one mass: the scene's colour itself, as before.
        w.setMass(w.ids()[1], 2.0);
        draw(w, o);
        EXPECT_TRUE(isColor(pixel(100, 200), drawn.r, drawn.g, drawn.b, 2));
        EXPECT_TRUE(isColor(pixel(300, 200), drawn.r, drawn.g, drawn.b, 2));
    }
}

TEST_F(RenderTest, AnArrowPointsAlongTheVelocity) {
    // 300 m/s for 1/3 s: the tip is 100 px from the centre.
    const World right = worldWith({200, 200}, {300, 0}, 10.0, {255, 255, 0});
    ViewOptions o;
    o.arrows = true;
    draw(right, o);
    EXPECT_TRUE(isColor(pixel(200 + 50, 200), 255, 255, 0));  // on the shaft
    EXPECT_TRUE(isColor(pixel(200 + 95, 200), 255, 255, 0));  // in the head
    EXPECT_TRUE(isColor(pixel(200 + 105, 200), 0, 0, 0));     // beyond the tip
    EXPECT_TRUE(isColor(pixel(200 - 50, 200), 0, 0, 0));      // not behind
    EXPECT_TRUE(isColor(pixel(200, 200 - 50), 0, 0, 0));

    const World up = worldWith({200, 200}, {0, -300}, 10.0, {255, 255, 0});
    draw(up, o);
    EXPECT_TRUE(isColor(pixel(200, 200 - 50), 255, 255, 0));
    EXPECT_TRUE(isColor(pixel(200 + 50, 200), 0, 0, 0));

    o.arrows = false;
    draw(up, o);
    EXPECT_TRUE(isColor(pixel(200, 200 - 50), 0, 0, 0));
}

TEST_F(RenderTest, AnArrowPastAWallEndsOnItInABarWithoutAHead) {
    // A box 300 m wide: 300 m/s for 1/3 s from x = 250 would reach x = 350, 50 px past the
    // right wall (lesson 1's ball ran 30 px past the left one). It stops at the wall, cut.
    WorldDef def;
    def.width = 300.0;
    def.height = 400.0;
    World w(def);
    w.add({.position = Vec2(250.0, 200.0),
           .velocity = Vec2(300.0, 0.0),
           .mass = 2.0,
           .radius = 10.0,
           .color = {255, 255, 255}});
    draw(w, {});
    EXPECT_TRUE(isColor(pixel(280, 200), 255, 255, 255)) << "the shaft up to the wall";
    EXPECT_FALSE(isColor(pixel(310, 200), 255, 255, 255)) << "past the wall";
    EXPECT_FALSE(isColor(pixel(330, 200), 255, 255, 255)) << "past the wall";
    // The bar across its end, wider than the shaft, and no head's flanks behind it.
    EXPECT_TRUE(isColor(pixel(298, 200 + 3), 255, 255, 255)) << "the bar";
    EXPECT_TRUE(isColor(pixel(298, 200 - 3), 255, 255, 255)) << "the bar";
    EXPECT_TRUE(isColor(pixel(292, 200 + 3), 0, 0, 0)) << "a head's flank";
}

TEST_F(RenderTest, AnArrowHeadIsFilledAndWiderThanTheShaft) {
    const World w = worldWith({100, 200}, {600, 0}, 10.0, {255, 255, 255});
    draw(w, {});
    // Tip at x = 300; the 12 px head with ±30° flanks is ±5.8 px wide 10 px behind the tip.
    EXPECT_TRUE(isColor(pixel(290, 200 + 4), 255, 255, 255));
    EXPECT_TRUE(isColor(pixel(290, 200 - 4), 255, 255, 255));
    EXPECT_TRUE(isColor(pixel(250, 200 + 5), 0, 0, 0));  // the shaft is thin
}

TEST_F(RenderTest, ASlowBigParticleStillShowsAnArrowBeyondItsRim) {
    // 30 m/s -> 10 px at 1/3 s, inside a 20 m disc: before, no arrow at all. Now it reaches
    // kMinArrowPixels past the rim.
    const World w = worldWith({200, 200}, {30, 0}, 20.0, {255, 0, 0});
    draw(w, {});
    int red = 0;
    for (int x = 222; x < 260; ++x)
        red += pixel(x, 200).r > 0;
    EXPECT_GE(red, static_cast<int>(kMinArrowPixels) - 3);
    EXPECT_EQ(pixel(200 + 20 + static_cast<int>(kMinArrowPixels) + 3, 200).r, 0);  // no longer
}

TEST_F(RenderTest, AParticleAtRestHasNoArrow) {
    const World w = worldWith({200, 200}, {0, 0}, 20.0, {255, 0, 0});
    draw(w, {});
    int red = 0;
    for (int x = 222; x < 260; ++x)
        red += pixel(x, 200).r > 0;
    EXPECT_EQ(red, 0);
}

TEST_F(RenderTest, AParticleRestingUnderGravityInTheDiscreteModeHasNoArrow) {
    // At rest on a floor it keeps the g dt of one step: no arrow (its minimum arrow pointed
    // through the floor). Ten times that is motion, and shows one. (A strong g, so that at one
    // pixel a metre g dt alone would draw the minimum arrow.)
    const double g = 3000.0;
    const auto redBelow = [&](double vy) {
        World w = worldWith({200, 200}, {0, vy}, 20.0, {255, 0, 0});
        w.setGravity(Vec2(0.0, g));
        draw(w, {});
        int red = 0;
        for (int y = 222; y < 260; ++y)
            red += pixel(200, y).r > 0;
        return red;
    };
    const double gdt = g * kFrame;
    EXPECT_EQ(redBelow(gdt), 0);
    EXPECT_GT(redBelow(10.0 * gdt), 5);
}

TEST_F(RenderTest, LabelsAppearOnlyWhenTheOverlayIsOn) {
    const World w = worldWith({200, 250}, {12, -3}, 20.0, {255, 0, 0});
    ViewOptions o;
    o.arrows = false;
    o.labels = false;
    draw(w, o);
    // The four lines stack above the disc (top of the disc at y = 230).
    EXPECT_EQ(brightPixels(100, 150, 300, 230), 0);
    o.labels = true;
    const DrawStats s = draw(w, o);
    EXPECT_EQ(s.labelled, 1u);
    EXPECT_GT(brightPixels(100, 150, 300, 230), 100);
    EXPECT_EQ(brightPixels(100, 280, 300, 400), 0);  // nothing below the disc
}

TEST_F(RenderTest, TextAtAFractionOfAPixelIsDrawnAsAtTheWholePixel) {
    // The "1800.00" drawn as "18CC.C0": glyph quads at x + 0.5 were resampled.
    const auto image = [&](float x, float y) {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        GeometryBatch b;
        font_->layout("Momentum: 1800.00", x, y, SDL_Color{255, 255, 255, 255}, b);
        font_->draw(b);
        SDL_RenderPresent(sdl_);
        std::vector<Uint8> v;
        for (int yy = 90; yy < 130; ++yy)
            for (int xx = 0; xx < 200; ++xx)
                v.push_back(pixel(xx, yy).r);
        return v;
    };
    const auto whole = image(20.0f, 100.0f);
    EXPECT_EQ(image(20.4f, 100.4f), whole);
    EXPECT_EQ(image(19.6f, 99.7f), whole);
}

TEST_F(RenderTest, LatinOneCharactersInUtf8AreTheirOwnGlyphsAndOthersAQuestionMark) {
    // "µJ", "m/s²", "½ m v²": each UTF-8 pair is one glyph of its own, not '?' and not two.
    const auto image = [&](std::string_view text) {
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        GeometryBatch b;
        font_->layout(text, 20.0f, 100.0f, SDL_Color{255, 255, 255, 255}, b);
        font_->draw(b);
        SDL_RenderPresent(sdl_);
        std::vector<Uint8> v;
        for (int yy = 90; yy < 130; ++yy)
            for (int xx = 0; xx < 120; ++xx)
                v.push_back(pixel(xx, yy).r);
        return v;
    };
    for (const char* c : {"\u00b5", "\u00b2", "\u00bd", "\u00b0"}) {
        EXPECT_NE(image(c), image("?")) << c;
        EXPECT_NE(image(c), image("u")) << c;
        EXPECT_EQ(font_->measure(std::string("5 ") + c + "J"),
                  font_->measure("5 ") + font_->measure(c) + font_->measure("J"));
    }
    // Beyond Latin-1 (€, three bytes), a stray continuation byte and a cut sequence: one '?'
    // each, never a crash or a read past the end.
    EXPECT_EQ(image("\u20ac"), image("?"));
    EXPECT_EQ(image("\x80"), image("?"));
    EXPECT_EQ(image("\xc2"), image("?"));
    EXPECT_EQ(font_->measure("a\u20acb"), font_->measure("a?b"));
}

TEST_F(RenderTest, LabelsOfNeighboursDoNotOverlapAndKeepClearOfThePanels) {
    WorldDef def;
    def.width = def.height = kSize;
    World w(def);
    for (const double x : {150.0, 185.0, 220.0}) {
        ParticleDef d;
        d.position = {x, 250};
        d.radius = 10.0;
        w.add(d);
    }
    ViewOptions o;
    o.arrows = false;
    o.labels = true;
    // Nothing may be drawn above y = 200 (a panel there).
    const LabelKeepOut avoid{{PixelRect{0, 0, kSize, 200}}, {}};
    const DrawStats s = renderer_->draw(w, kFrame, camera_, o, nullptr, kNullParticle, &avoid);
    SDL_RenderPresent(sdl_);
    EXPECT_EQ(brightPixels(0, 0, kSize, 200), 0);
    // Three 150 px wide labels cannot all sit side by side at 35 px spacing: those that fit are
    // drawn, the rest counted, and none is drawn over another.
    EXPECT_EQ(s.labelled + s.labelsCrowded, 3u);
    EXPECT_GE(s.labelled, 2u);
}

TEST_F(RenderTest, ALabelStaysOnOneSideOfTheWalls) {
    // A disc just under the top wall: above it the label would cross the wall, so it goes
    // below (inside the box), and nothing of it is drawn above the wall.
    WorldDef def;
    def.width = def.height = 300.0;
    World w(def);
    ParticleDef d;
    d.position = {150, 20};
    d.radius = 10.0;
    w.add(d);
    camera_.set(1.0, Vec2(-50, -50));  // the box from (50, 50) to (350, 350) on screen
    ViewOptions o;
    o.arrows = false;
    o.labels = true;
    const DrawStats s = renderer_->draw(w, kFrame, camera_, o, nullptr, kNullParticle, nullptr);
    SDL_RenderPresent(sdl_);
    EXPECT_EQ(s.labelled, 1u);
    EXPECT_EQ(brightPixels(0, 0, kSize, 47), 0);    // above the wall (2 px thick)
    EXPECT_GT(brightPixels(60, 82, 350, 160), 50);  // below the disc
}

TEST_F(RenderTest, ALabelThatWouldRunOffTheWindowGoesAlongItsEdgeInstead) {
    // A disc in the box's top-right corner, the box filling the window: above it and right of
    // it are off the window, left of it and centred below it run off the top and right edges.
    // Nothing else is there to overlap: the label goes beside it, shifted to fit a few pixels
    // clear of the walls (it used to be left out, counted as "where they would overlap").
    WorldDef def;
    def.width = def.height = kSize;
    World w(def);
    ParticleDef d;
    d.position = {kSize - 15.0, 15.0};
    d.radius = 10.0;
    w.add(d);
    ViewOptions o;
    o.arrows = false;
    o.labels = true;
    const DrawStats s = draw(w, o);
    EXPECT_EQ(s.labelled, 1u);
    EXPECT_EQ(s.labelsCrowded, 0u);
    EXPECT_EQ(s.labelsOffWindow, 0u);
    // Beside the disc, in the box, clear of the walls (left of it, below its corner: a label
    // below it would touch the right wall), not over the disc (x 375 to 395).
    EXPECT_GT(brightPixels(kSize / 2, 2, kSize - 26, 120), 100);
}

TEST_F(RenderTest, ALabelWithNoRoomInTheWindowIsCountedAsSuch) {
    // A disc nearly as big as the window: every side of it is off the window's edges. The
    // label is left out for want of room in the window, not "where labels would overlap".
    WorldDef def;
    def.width = def.height = 1000.0;
    World w(def);
    ParticleDef d;
    d.position = {500.0, 500.0};
    d.radius = 190.0;
    w.add(d);
    camera_.set(1.0, Vec2(300.0, 300.0));  // the disc's centre at (200, 200), 190 px across
    ViewOptions o;
    o.arrows = false;
    o.labels = true;
    const DrawStats s = draw(w, o);
    EXPECT_EQ(s.labelled, 0u);
    EXPECT_EQ(s.labelsCrowded, 0u);
    EXPECT_EQ(s.labelsOffWindow, 1u);
}

TEST_F(RenderTest, ALabelWithNoPlaceClearOfOtherDiscsIsLeftOutNotDrawnOverThem) {
    // A disc hemmed in by four big ones leaves its label no place clear of discs: it used to be
    // drawn over them (outlined, without its background); a label never covers a ball, so it
    // is left out and counted, and not one pixel of the big discs' green is changed.
    WorldDef def;
    def.width = def.height = kSize;
    World w(def);
    ParticleDef d;
    d.position = {200, 200};
    d.radius = 5.0;
    d.color = {0, 0, 255};
    w.add(d);
    for (const Vec2& at : {Vec2(200, 120), Vec2(200, 280), Vec2(100, 200), Vec2(300, 200)}) {
        d.position = at;
        d.radius = 74.0;
        d.color = {0, 200, 0};
        w.add(d);
    }
    const auto greens = [&](bool labels, DrawStats* stats) {
        ViewOptions o;
        o.arrows = false;
        o.labels = labels;
        *stats = renderer_->draw(w, kFrame, camera_, o, nullptr, kNullParticle, nullptr);
        SDL_RenderPresent(sdl_);
        std::vector<Uint32> out;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const SDL_Color c = pixel(x, y);
                out.push_back(static_cast<Uint32>(c.r) << 16 | static_cast<Uint32>(c.g) << 8 | c.b);
            }
        }
        return out;
    };
    DrawStats without, with;
    const std::vector<Uint32> bare = greens(false, &without);
    const std::vector<Uint32> labelled = greens(true, &with);
    // The small disc's label is among those left out (no place beside it is clear).
    EXPECT_GE(with.labelsCrowded, 1u);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < bare.size(); ++i) {
        const Uint32 c = bare[i];
        const bool green = (c >> 16) == 0 && (c & 0xff) == 0 && ((c >> 8) & 0xff) == 200;
        changed += green && labelled[i] != c;
    }
    EXPECT_EQ(changed, 0u) << "pixels of the big discs changed by a label";
}

TEST_F(RenderTest, LabelsKeepTheirPixelSizeAtAnyZoom) {
    const World w = worldWith({200, 250}, Vec2::Zero(), 20.0, {255, 0, 0});
    ViewOptions o;
    o.labels = true;
    camera_.set(0.05, Vec2(200 - 200 / 0.05, 250 - 250 / 0.05));  // the disc is 1 px wide
    draw(w, o);
    // Above the box, 50 pixels across from (190, 237): its white walls are not the label's.
    const int far = brightPixels(100, 150, 300, 235);
    camera_.set(1.0, Vec2::Zero());
    draw(w, o);
    const int near = brightPixels(100, 150, 300, 230);
    EXPECT_GT(far, 100);
    EXPECT_NEAR(far, near, near * 0.2);
}

TEST_F(RenderTest, WallsAreDrawnAroundTheBox) {
    WorldDef def;
    def.width = 300.0;
    def.height = 300.0;
    const World w(def);
    // Box from (50, 50) to (350, 350) on screen; walls 2 px thick (at least), outside.
    camera_.set(1.0, Vec2(-50, -50));
    draw(w, {});
    EXPECT_TRUE(isColor(pixel(200, 49), 255, 255, 255));
    EXPECT_TRUE(isColor(pixel(350, 200), 255, 255, 255));
    EXPECT_TRUE(isColor(pixel(200, 200), 0, 0, 0));
}

TEST_F(RenderTest, APeriodicBoxHasDashedEdgesAndADiscOverAnEdgeShowsAtTheOtherToo) {
    WorldDef def;
    def.width = 300.0;
    def.height = 300.0;
    def.walls = false;
    def.periodic = true;
    World w(def);
    w.add({.position = Vec2(10.0, 150.0), .radius = 20.0, .color = {255, 0, 0}});
    // Box from (50, 50) to (350, 350) on screen; the disc over its left edge at (60, 200).
    camera_.set(1.0, Vec2(-50, -50));
    const std::optional<PeriodicBoxView> box = periodicBoxView(w, camera_);
    ASSERT_TRUE(box.has_value());
    ASSERT_EQ(box->images.size(), 1u);
    renderer_->draw(w, kFrame, camera_, {}, nullptr, kNullParticle, nullptr, nullptr, &*box);
    SDL_RenderPresent(sdl_);
    EXPECT_TRUE(isColor(pixel(60, 200), 255, 0, 0));
    // Its image: the part over the left edge shows inside the right one, and beyond it.
    EXPECT_TRUE(isColor(pixel(345, 200), 255, 0, 0));
    EXPECT_TRUE(isColor(pixel(365, 200), 255, 0, 0));
    EXPECT_TRUE(isColor(pixel(300, 200), 0, 0, 0));
    // The top edge dashed: a dash from the corner, then a gap, along the edge's line.
    EXPECT_TRUE(isColor(pixel(55, 50), 255, 255, 255));
    EXPECT_TRUE(isColor(pixel(63, 50), 0, 0, 0));
    EXPECT_TRUE(isColor(pixel(70, 50), 255, 255, 255));
    int lit = 0;
    for (int x = 50; x < 350; ++x)
        lit += isColor(pixel(x, 50), 255, 255, 255);
    EXPECT_NEAR(lit, 300 * 10 / 16, 12) << "dashes, not a solid wall";
    // Drawn without the view's box (a caller that has none): a solid frame, as before.
    renderer_->draw(w, kFrame, camera_, {});
    SDL_RenderPresent(sdl_);
    EXPECT_FALSE(isColor(pixel(365, 200), 255, 0, 0));
}

/// A window wide enough for the side column beside the box (sideColumnFits).
class WideRenderTest : public RenderTest {
  protected:
    WideRenderTest() : RenderTest(700) {}
};

TEST_F(WideRenderTest, TheProfileOverlayDrawsTextOnlyWhenOn) {
    Overlays o;
    o.hud = {"FPS 60"};
    o.profile = {"Profile, last step (ms)", "find pairs               1.500",
                 "total                    3.000"};
    const auto drawOverlay = [&] { drawPanels(o); };
    const int w = size_;
    o.showProfile = false;
    drawOverlay();
    // The profile goes to the top-right corner; the short HUD line stays at the top-left.
    EXPECT_EQ(brightPixels(w / 2, 0, w, 80), 0);
    EXPECT_GT(brightPixels(0, 0, 100, 30), 10);
    o.showProfile = true;
    drawOverlay();
    EXPECT_GT(brightPixels(w / 2, 0, w, 80), 100);
    EXPECT_EQ(brightPixels(w / 2, 100, w, w), 0);  // nothing below its three lines
}

TEST_F(RenderTest, TheSelectionOutlineRingsTheDiscOutsideItsRim) {
    const World w = worldWith({200, 200}, Vec2::Zero(), 20.0, {0, 0, 255});
    ViewOptions o;
    o.arrows = false;
    renderer_->draw(w, kFrame, camera_, o);
    drawSelectionOutline(sdl_, camera_, w.get(w.ids()[0]));
    SDL_RenderPresent(sdl_);
    // Rings 3 and 4 px outside the 20 px rim, in the outline's yellow; the disc stays blue.
    for (const auto& [x, y] :
         {std::pair{223, 200}, std::pair{177, 200}, std::pair{200, 223}, std::pair{200, 177}}) {
        EXPECT_TRUE(isColor(pixel(x, y), 255, 230, 0, 40)) << x << "," << y;
    }
    EXPECT_TRUE(isColor(pixel(200, 200), 0, 0, 255));
    EXPECT_TRUE(isColor(pixel(212, 200), 0, 0, 255));
    EXPECT_TRUE(isColor(pixel(230, 200), 0, 0, 0));
}

TEST_F(RenderTest, TheInspectorPanelIsDrawnBottomRightOnlyWithASelection) {
    Overlays o;
    o.hud = {"FPS 60"};
    const auto drawOverlay = [&] { drawPanels(o); };
    drawOverlay();
    EXPECT_EQ(brightPixels(kSize / 2, kSize / 2, kSize, kSize), 0);
    Particle p;
    p.position = {1, 2};
    p.velocity = {3, 4};
    o.inspector = inspectorLines(p, EditPrompt{});
    drawOverlay();
    EXPECT_GT(brightPixels(kSize / 2, kSize / 2, kSize, kSize), 300);
    EXPECT_EQ(brightPixels(0, kSize / 2, kSize / 4, kSize), 0);  // not bottom-left
}

TEST(ArrowScale, IsTheOriginalsThirdOfASecondForAFewParticles) {
    World w;  // 700 m box
    ParticleDef d;
    d.velocity = {300.0, 0.0};
    d.position = {100.0, 100.0};
    w.add(d);
    EXPECT_DOUBLE_EQ(arrowSecondsFor(w), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(arrowSecondsFor(World{}), 1.0 / 3.0);  // nothing moves: nothing to scale
}

TEST(ArrowScale, ShortensSoADenseGasIsNotHiddenUnderItsArrows) {
    World w;  // 700 m box, 4900 particles: mean spacing 10 m
    for (int i = 0; i < 70; ++i) {
        for (int j = 0; j < 70; ++j) {
            ParticleDef d;
            d.position = {5.0 + 10.0 * i, 5.0 + 10.0 * j};
            d.velocity = {100.0, 0.0};
            w.add(d);
        }
    }
    // The root-mean-square arrow is three quarters of the spacing: 7.5 m at 100 m/s.
    EXPECT_NEAR(arrowSecondsFor(w), 0.075, 1e-12);
}

TEST_F(RenderTest, LongLinesWrapAtSpacesWithinTheWidthAndKeepEveryWord) {
    const std::string line =
        "Cannot open scene: /some/long/path/lesson.json: particles[2].mass: must be > 0 kg, got -3";
    const int width = font_->measure(line) / 2;
    const std::vector<std::string> wrapped = wrapLines(*font_, {line, "short"}, width);
    ASSERT_GE(wrapped.size(), 3u);
    EXPECT_EQ(wrapped.back(), "short");
    std::string joined = wrapped[0];
    EXPECT_LE(font_->measure(wrapped[0]), width - 8) << wrapped[0];
    for (std::size_t k = 1; k + 1 < wrapped.size(); ++k) {
        EXPECT_LE(font_->measure(wrapped[k]), width - 8) << wrapped[k];
        ASSERT_EQ(wrapped[k].rfind("  ", 0), 0u) << "continuations are indented";
        // A path goes on after a separator, without a space.
        if (joined.back() != '/') joined += " ";
        joined.append(wrapped[k], 2, std::string::npos);
    }
    EXPECT_EQ(joined, line);
}

TEST_F(RenderTest, HudLinesWrapBetweenTheirPartsAndKeepEveryReading) {
    const std::string line = "Kinetic energy 1.96 J | momentum (0.111, 0.461) kg m/s | H: help";
    const int width = font_->measure("Kinetic energy 1.96 J | momentum (0.111, 0.461) kg m/s") + 10;
    const std::vector<std::string> wrapped = wrapHudLines(*font_, {line, "short"}, width);
    ASSERT_EQ(wrapped.size(), 3u);
    EXPECT_EQ(wrapped[0], "Kinetic energy 1.96 J | momentum (0.111, 0.461) kg m/s");
    EXPECT_EQ(wrapped[1], "  H: help");
    EXPECT_EQ(wrapped[2], "short");
    for (const std::string& l : wrapped)
        EXPECT_LE(font_->measure(l), width - 8) << l;
    // Narrower than one part: that part breaks at spaces too; nothing is lost.
    const std::vector<std::string> narrow =
        wrapHudLines(*font_, {line}, font_->measure("Kinetic energy 1.96 J") + 8);
    std::string joined;
    for (const std::string& l : narrow)
        joined += l + "\n";
    for (const char* reading : {"1.96 J", "(0.111,", "0.461)", "help"})
        EXPECT_NE(joined.find(reading), std::string::npos) << joined;
    EXPECT_EQ(wrapHudLines(*font_, {line}, 10000), std::vector<std::string>{line});
}

TEST_F(RenderTest, TheHelpFitsA600By600WindowInPagesAndListsEveryControl) {
    // The HUD's font, as the app draws the help. In a 600 x 600 window (the control panel
    // folded) the help used to be one box, cut at the right edge, its last rows (K to Esc)
    // below the window.
    const Font hud(sdl_, findAsset("fonts/DejaVuSansMono.ttf"), 14);
    const PixelRect room = helpRoom(600, 600);
    EXPECT_GT(textBoxSize(hud, helpLines()).y, room.h) << "one box does not fit";
    const auto pages = helpPages(hud, helpLines(), {room.w, room.h});
    ASSERT_GE(pages.size(), 2u);
    std::string all;
    for (const auto& page : pages) {
        const PixelPoint size = textBoxSize(hud, page);
        EXPECT_LE(room.x + size.x, 600 - kPanelMargin);
        EXPECT_LE(room.y + size.y, 600 - kPanelMargin);
        for (const std::string& l : page)
            all += l + "\n";
    }
    EXPECT_NE(pages.front().front().find("page 1 of"), std::string::npos);
    EXPECT_NE(pages.back().front().find("H closes"), std::string::npos);
    // Every control, in order, the last ones included.
    std::size_t at = 0;
    for (const auto& [keys, what] : controls()) {
        const std::size_t found = all.find(keys, at);
        ASSERT_NE(found, std::string::npos) << keys;
        at = found + keys.size();
    }
    // In 420 px the keys' column leaves their words too little room beside it: each control's
    // words go on the lines under its keys, indented; none start beside the keys and go on
    // under them.
    for (const auto& page : helpPages(hud, helpLines(), {420, 720})) {
        for (std::size_t k = 2; k < page.size(); ++k) {
            if (!page[k].empty() && page[k][0] != ' ') {
                EXPECT_EQ(page[k].find("   "), std::string::npos) << page[k];
            }
        }
    }
    // A large window keeps it on one page.
    const PixelRect big = helpRoom(1600, 1000);
    EXPECT_EQ(helpPages(hud, helpLines(), {big.w, big.h}).size(), 1u);
}

}  // namespace
}  // namespace psb::app
