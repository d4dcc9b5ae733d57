// The analysis overlays: their arithmetic (trail rings, plot ranges, the Rayleigh density, the
// speed histogram) and their drawing, with SDL's software renderer on an offscreen surface.
// Camera: 1 pixel per metre, offset 0, so world metres are surface pixels.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include <SDL.h>

#include "platform/assets.hpp"
#include "render/analysis_overlays.hpp"
#include "render/offscreen_test.hpp"
#include "render/renderer.hpp"
#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "render/trails.hpp"
#include "session/camera.hpp"
#include "view/speed_histogram.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 800;
/// The frame length the worlds drawn here are stepped by (a scene file's default dt).
constexpr double kFrame = 0.01;

World bigBox() {
    WorldDef def;
    def.width = 2000.0;  // walls outside the surface
    def.height = 2000.0;
    return World(def);
}

ParticleDef disc(Vec2 pos, Vec2 vel, double mass = 1.0, Color color = {200, 40, 200}) {
    ParticleDef d;
    d.position = pos;
    d.velocity = vel;
    d.mass = mass;
    d.radius = 5.0;
    d.color = color;
    return d;
}

// --- trails ---------------------------------------------------------------------------------

TEST(Trails, RingKeepsTheNewestPositionsOldestFirst) {
    World w = bigBox();
    const ParticleId id = w.add(disc({100.0, 100.0}, {0.0, 0.0}));
    Trails t;
    for (int k = 0; k < Trails::kLength + 9; ++k) {
        w.setPosition(id, {100.0 + k, 100.0});
        t.sample(w);
    }
    ASSERT_EQ(t.length(id), static_cast<std::size_t>(Trails::kLength));
    EXPECT_EQ(t.point(id, 0), Vec2(109.0, 100.0));  // the first 9 were overwritten
    EXPECT_EQ(t.point(id, Trails::kLength - 1), Vec2(100.0 + Trails::kLength + 8, 100.0));
}

TEST(Trails, ADeletedParticlesSlotStartsAnEmptyTrailForItsSuccessor) {
    World w = bigBox();
    const ParticleId a = w.add(disc({100.0, 100.0}, {0.0, 0.0}));
    Trails t;
    for (int k = 0; k < 5; ++k)
        t.sample(w);
    ASSERT_EQ(t.length(a), 5u);
    ASSERT_TRUE(w.remove(a));
    EXPECT_EQ(t.length(a), 5u);  // kept until the slot is reused, but never drawn (dead id)
    const ParticleId b = w.add(disc({300.0, 300.0}, {0.0, 0.0}));
    ASSERT_EQ(b.slot, a.slot);  // the id table reuses the slot with a new generation
    EXPECT_EQ(t.length(b), 0u);
    t.sample(w);
    EXPECT_EQ(t.length(b), 1u);
    EXPECT_EQ(t.point(b, 0), Vec2(300.0, 300.0));
    EXPECT_EQ(t.length(a), 0u);
}

TEST(Trails, ResetForgetsEveryTrailAndAPausedWorldAddsNothing) {
    World w = bigBox();
    const ParticleId id = w.add(disc({100.0, 100.0}, {10.0, 0.0}));
    Trails t;
    for (int k = 0; k < 2 * Trails::kSampleFrames * 4; ++k) {
        w.step(0.01);
        t.update(w);  // one sample every kSampleFrames frames
    }
    EXPECT_EQ(t.length(id), 8u);
    for (int k = 0; k < 10; ++k)
        t.update(w);  // time does not move: no samples
    EXPECT_EQ(t.length(id), 8u);
    t.reset();
    EXPECT_EQ(t.length(id), 0u);
}

TEST(Trails, TheFollowedParticleKeepsALongTrailThatStartsOverForAnother) {
    World w = bigBox();
    const ParticleId a = w.add(disc({100.0, 100.0}, {0.0, 0.0}));
    const ParticleId b = w.add(disc({300.0, 300.0}, {0.0, 0.0}));
    Trails t;
    t.follow(a);
    for (int k = 0; k < 10 * Trails::kLength; ++k)
        t.sample(w);
    EXPECT_EQ(t.followedLength(), static_cast<std::size_t>(10 * Trails::kLength));
    EXPECT_EQ(t.length(a), static_cast<std::size_t>(Trails::kLength));  // the short ring
    for (int k = 0; k < Trails::kFollowedLength; ++k)
        t.sample(w);
    EXPECT_EQ(t.followedLength(), static_cast<std::size_t>(Trails::kFollowedLength));
    t.follow(a);  // the same one: kept
    EXPECT_EQ(t.followedLength(), static_cast<std::size_t>(Trails::kFollowedLength));
    t.follow(b);
    EXPECT_EQ(t.followedLength(), 0u);
    t.sample(w);
    EXPECT_EQ(t.followedLength(), 1u);
    t.reset();
    EXPECT_EQ(t.followedLength(), 0u);
}

TEST(Trails, InAPeriodicBoxAWrapThroughAnEdgeIsNoLineAcrossTheBox) {
    WorldDef def;
    def.width = 200.0;
    def.height = 200.0;
    def.walls = false;
    def.periodic = true;
    World w(def);
    const ParticleId id = w.add(disc({180.0, 100.0}, {0.0, 0.0}));
    Trails t;
    // Right across the right edge and on from the left: 180, 186, ..., 198, then 4, 10, 16.
    for (const double x : {180.0, 186.0, 192.0, 198.0, 4.0, 10.0, 16.0}) {
        w.setPosition(id, {x, 100.0});
        t.sample(w);
    }
    Camera c;
    c.setViewport(200, 200);
    c.set(1.0, Vec2::Zero());
    const TrailImage& image = t.rasterise(w, c, TrailMode::All, kNullParticle);
    EXPECT_NE(image.at(190, 100), 0u);  // the steps before the edge
    EXPECT_NE(image.at(8, 100), 0u);    // and after it
    for (int x = 30; x < 170; x += 10)
        EXPECT_EQ(image.at(x, 100), 0u) << "a line across the box at x = " << x;
    // In a box with walls the same jump is a step (a teleport) and is drawn.
    def.periodic = false;
    def.walls = true;
    World walled(def);
    const ParticleId b = walled.add(disc({180.0, 100.0}, {0.0, 0.0}));
    Trails u;
    for (const double x : {180.0, 186.0, 4.0, 10.0}) {
        walled.setPosition(b, {x, 100.0});
        u.sample(walled);
    }
    EXPECT_NE(u.rasterise(walled, c, TrailMode::All, kNullParticle).at(100, 100), 0u);
}

TEST(Trails, ImageLinesAreClippedAndOnlyTheirRectangleIsCleared) {
    TrailImage img;
    img.resize(100, 50);
    // From far off screen on the left to (20, 10): clipped, drawn from x = 0 to 20 on row 10.
    img.line(-1e6f, 10.2f, 20.2f, 10.2f, 0xff102030u);
    const SDL_Rect r = img.dirty();
    EXPECT_EQ(r.x, 0);
    EXPECT_EQ(r.y, 10);
    EXPECT_EQ(r.w, 21);
    EXPECT_EQ(r.h, 1);
    for (int x = 0; x <= 20; ++x)
        EXPECT_EQ(img.at(x, 10), 0xff102030u) << "x = " << x;
    EXPECT_EQ(img.at(21, 10), 0u);
    // Where lines cross, the more opaque colour stays, whichever comes last.
    img.line(5.5f, 5.5f, 5.5f, 15.5f, 0x40ffffffu);
    EXPECT_EQ(img.at(5, 10), 0xff102030u);
    EXPECT_EQ(img.at(5, 14), 0x40ffffffu);
    // Entirely outside: nothing.
    img.line(200.0f, 10.0f, 300.0f, 40.0f, 0xffffffffu);
    EXPECT_EQ(img.dirty().w, 21);  // x 0..20, y 5..15: the two lines above
    EXPECT_EQ(img.dirty().h, 11);
    img.clear();
    EXPECT_EQ(img.dirty().w, 0);
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 100; ++x)
            ASSERT_EQ(img.at(x, y), 0u);
}

TEST(Trails, ModesCycleOffSelectedAll) {
    EXPECT_EQ(nextTrailMode(TrailMode::Off), TrailMode::Selected);
    EXPECT_EQ(nextTrailMode(TrailMode::Selected), TrailMode::All);
    EXPECT_EQ(nextTrailMode(TrailMode::All), TrailMode::Off);
}

// --- plot ranges ----------------------------------------------------------------------------

TEST(PlotRange, ConservedValueWithRoundingNoiseGetsTheFloorSpanAroundIt) {
    const double e = 4.038789e6;
    const PlotRange r = plotRange(e * (1 - 1e-15), e * (1 + 1e-15), 0.01 * e);
    EXPECT_GE(r.hi - r.lo, 0.01 * e);
    EXPECT_LE(r.hi - r.lo, 0.03 * e);  // rounded out to ticks, not blown up
    // The line sits in the middle fifth, not at an edge.
    const double at = (e - r.lo) / (r.hi - r.lo);
    EXPECT_GT(at, 0.3);
    EXPECT_LT(at, 0.7);
}

TEST(PlotRange, WideDataKeepsItsOwnRange) {
    const PlotRange r = plotRange(120.0, 980.0, 10.0);
    EXPECT_LE(r.lo, 120.0);
    EXPECT_GE(r.hi, 980.0);
    EXPECT_GE(r.lo, 0.0);
    EXPECT_LE(r.hi, 1000.0);
}

TEST(PlotRange, TicksAreOneTwoFiveMultiples) {
    const std::vector<double> ticks = niceTicks(0.0, 1.0, 6);
    ASSERT_EQ(ticks.size(), 6u);
    for (std::size_t k = 0; k < ticks.size(); ++k)
        EXPECT_NEAR(ticks[k], 0.2 * static_cast<double>(k), 1e-12);
    EXPECT_DOUBLE_EQ(niceStep(0.0, 100.0, 4), 50.0);
    EXPECT_EQ(tickLabel(4.04e6, 2e4), "4.04M");
    EXPECT_EQ(tickLabel(4.0e6, 2e4), "4.00M");
    EXPECT_EQ(tickLabel(2e-5, 1e-5), "20\u00b5");
    EXPECT_EQ(tickLabel(0.0, 5e5), "0");
    EXPECT_EQ(tickLabel(0.5, 0.1), "0.5");
    EXPECT_EQ(tickLabel(-1000.0, 500.0), "-1000");
}

// --- speed distribution ---------------------------------------------------------------------

TEST(SpeedHistogram, RayleighDensityIntegratesToOneAndPeaksAtTheThermalSpeed) {
    for (const double m : {0.5, 1.0, 7.0}) {
        const double kT = 1000.0, sigma = std::sqrt(kT / m);
        double integral = 0.0;
        const double dv = sigma / 1000.0;
        for (double v = 0.0; v < 12.0 * sigma; v += dv)
            integral += 0.5 * dv * (rayleighDensity(v, kT, m) + rayleighDensity(v + dv, kT, m));
        EXPECT_NEAR(integral, 1.0, 1e-6) << "m = " << m;
        EXPECT_GT(rayleighDensity(sigma, kT, m), rayleighDensity(0.9 * sigma, kT, m));
        EXPECT_GT(rayleighDensity(sigma, kT, m), rayleighDensity(1.1 * sigma, kT, m));
    }
    EXPECT_EQ(rayleighDensity(-1.0, 1.0, 1.0), 0.0);
    EXPECT_EQ(rayleighDensity(1.0, 0.0, 1.0), 0.0);
}

/// `n` particles of masses 1 and 4 with Maxwellian velocities at kT (each component normal with
/// variance kT / m).
World thermalGas(std::size_t n, double kT) {
    World w = bigBox();
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g(0.0, 1.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double m = k % 2 == 0 ? 1.0 : 4.0, s = std::sqrt(kT / m);
        w.add(disc({10.0 + static_cast<double>(k % 100) * 11.0,
                    10.0 + static_cast<double>(k / 100) * 11.0},
                   {s * g(rng), s * g(rng)}, m));
    }
    return w;
}

TEST(SpeedHistogram, BinsCountEveryParticleAndFollowTheMixtureDensity) {
    World w = thermalGas(20000, 500.0);
    const SpeedHistogram h = speedHistogram(w.particles(), 32);
    std::size_t sum = h.overflow;
    for (const std::size_t c : h.counts)
        sum += c;
    EXPECT_EQ(sum, 20000u);
    EXPECT_NEAR(h.kT, 500.0, 0.02 * 500.0);  // the sample's mean KE per particle
    ASSERT_EQ(h.masses.size(), 2u);
    EXPECT_EQ(h.masses[0], (std::pair<double, std::size_t>{1.0, 10000}));
    // The mixture density integrates to 1 and matches the bins within counting noise.
    double integral = 0.0;
    for (int k = 0; k < 4000; ++k) {
        const double v = (k + 0.5) * 10.0 * std::sqrt(h.kT) / 4000.0;
        integral += h.expectedDensity(v) * 10.0 * std::sqrt(h.kT) / 4000.0;
    }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    const double width = h.binWidth();
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        const double expected = 20000.0 * width * h.expectedDensity((b + 0.5) * width);
        EXPECT_NEAR(static_cast<double>(h.counts[b]), expected, 5.0 * std::sqrt(expected) + 8.0)
            << "bin " << b;
    }
}

TEST(SpeedHistogram, OneBulletDoesNotSquashTheGas) {
    World w = thermalGas(1000, 100.0);
    w.add(disc({1500.0, 1500.0}, {1e5, 0.0}));
    const SpeedHistogram h = speedHistogram(w.particles(), 32);
    EXPECT_EQ(h.overflow, 1u);
    EXPECT_LT(h.vmax, 100.0);  // the gas's thermal speeds are ~10 m/s
}

TEST(SpeedHistogram, EmptyWorldHasNoCounts) {
    World w = bigBox();
    const SpeedHistogram h = speedHistogram(w.particles(), 8);
    EXPECT_EQ(h.particles, 0u);
    EXPECT_EQ(h.counts.size(), 8u);
    EXPECT_EQ(h.expectedDensity(1.0), 0.0);
}

// --- drawing --------------------------------------------------------------------------------

class OverlayRenderTest : public OffscreenTest {
  protected:
    OverlayRenderTest() : OffscreenTest(kSize) {}
    void SetUp() override {
        OffscreenTest::SetUp();
        view_.arrows = false;
        view_.arrowSeconds = 1.0 / 3.0;
    }

    void draw(const World& w, const TimeSeries& series, Trails* trails = nullptr,
              ParticleId selected = kNullParticle) {
        renderer_->draw(w, kFrame, camera_, view_, trails, selected);
        overlays_.draw(sdl_, *font_, w, sampleObservables(w), camera_, series, 0.5, view_,
                       layout());
        SDL_RenderPresent(sdl_);
    }

    /// The panels' boxes for the current view, with no HUD.
    PanelLayout layout() const {
        LayoutRequest r;
        r.width = kSize;
        r.height = kSize;
        r.plots = view_.plots;
        r.speeds = view_.speeds;
        if (view_.momentum) r.legend = {300, 50};
        return layoutPanels(r);
    }

    static bool near(SDL_Color a, SDL_Color b, int tol = 12) {
        return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol &&
               std::abs(a.b - b.b) <= tol;
    }
    /// Pixels of colour `c` in [x0,x1)×[y0,y1).
    int count(SDL_Color c, int x0, int y0, int x1, int y1, int tol = 12) const {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                n += near(pixel(x, y), c, tol);
        return n;
    }
    /// Distinct rows in [y0,y1) holding a pixel of colour `c` within columns [x0,x1).
    int rows(SDL_Color c, int x0, int y0, int x1, int y1) const {
        int n = 0;
        for (int y = y0; y < y1; ++y) {
            bool any = false;
            for (int x = x0; x < x1 && !any; ++x)
                any = near(pixel(x, y), c);
            n += any;
        }
        return n;
    }

    AnalysisOverlays overlays_;
    ViewOptions view_;
};

TEST_F(OverlayRenderTest, MomentumViewDrawsParticleArrowsTheTotalAndTheCentreOfMass) {
    // Two 1 kg particles moving up at 150 m/s: each arrow is (1/3 s)·150 = 50 px long; the total
    // (0, −300) kg m/s on the same scale is 100 px, from the centre of mass at (200, 500).
    World w = bigBox();
    w.add(disc({100.0, 500.0}, {0.0, -150.0}, 1.0, {60, 60, 60}));
    w.add(disc({300.0, 500.0}, {0.0, -150.0}, 1.0, {60, 60, 60}));
    TimeSeries series(16);
    series.record(w);
    view_.momentum = true;
    draw(w, series);
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).momentumArrow), 96, 455, 105, 490),
              10);  // above the left disc
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).momentumArrow), 296, 455, 305, 490), 10);
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).totalMomentum), 195, 410, 206, 480),
              40);  // 100 px up from the CoM
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).centreOfMass), 192, 497, 209, 504),
              10);  // the cross
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).totalMomentum), 0, 520, layout().legend.x, kSize),
              0);  // nothing below
    // The legend, top-right: the total's value in its colour.
    const PixelRect legend = layout().legend;
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).totalMomentum), legend.x, legend.y,
                    legend.x + legend.w, legend.y + legend.h),
              20);

    view_.momentum = false;
    draw(w, series);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).momentumArrow), 0, 0, kSize, kSize), 0);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).totalMomentum), 0, 0, kSize, kSize), 0);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).centreOfMass), 0, 0, kSize, kSize), 0);
}

TEST_F(OverlayRenderTest, TrailsFollowThePathAndOnlyWhenOn) {
    World w = bigBox();
    const Color red{250, 20, 20};
    const ParticleId a = w.add(disc({100.0, 300.0}, {0.0, 0.0}, 1.0, red));
    const ParticleId b = w.add(disc({100.0, 600.0}, {0.0, 0.0}, 1.0, red));
    Trails trails;
    for (int k = 0; k <= 20; ++k) {  // both move 200 px to the right
        w.setPosition(a, {100.0 + 10.0 * k, 300.0});
        w.setPosition(b, {100.0 + 10.0 * k, 600.0});
        trails.sample(w);
    }
    TimeSeries series(4);
    const auto trailPixels = [&](int y) {
        int n = 0;  // any shade of the particle's red left of its disc
        for (int x = 95; x < 290; ++x) {
            const SDL_Color c = pixel(x, y);
            n += c.r > 20 && c.g <= 20 && c.b <= 20;  // the tail is 15 % of 250
        }
        return n;
    };
    view_.trails = TrailMode::All;
    draw(w, series, &trails);
    EXPECT_GT(trailPixels(300), 180);
    EXPECT_GT(trailPixels(600), 180);
    // Fading: the tail is dimmer than the head.
    EXPECT_LT(pixel(105, 300).r, pixel(280, 300).r);

    view_.trails = TrailMode::Selected;
    draw(w, series, &trails, b);
    EXPECT_EQ(trailPixels(300), 0);
    EXPECT_GT(trailPixels(600), 180);
    draw(w, series, &trails, kNullParticle);  // nothing selected
    EXPECT_EQ(trailPixels(600), 0);

    view_.trails = TrailMode::Off;
    draw(w, series, &trails, b);
    EXPECT_EQ(trailPixels(300), 0);
    EXPECT_EQ(trailPixels(600), 0);
}

TEST_F(OverlayRenderTest, PlotsShowAConservedEnergyFlatAndALosingOneFalling) {
    // The panel's energy plot is the top one: its area is the panel's top ~100 px.
    World w = bigBox();
    w.add(disc({100.0, 100.0}, {0.0, 0.0}));
    view_.plots = true;
    const PixelRect box = layout().plots;
    ASSERT_EQ(layout().plotRows, 4);
    ASSERT_EQ(layout().plotRowHeight, 100);
    const int x0 = box.x, y0 = box.y, x1 = box.x + box.w;
    TimeSeries flat(300);
    for (int k = 0; k < 300; ++k) {
        ObservablesSample s;
        s.time = 0.01 * k;
        s.kineticEnergy = 4.0e6 * (1.0 + 1e-13 * std::sin(k));  // rounding-size noise
        s.collisions = 100u * static_cast<unsigned>(k);
        flat.record(s);
    }
    draw(w, flat);
    EXPECT_LE(rows(sdlColor(palette(Theme::Dark).energyPlot), x0 + 80, y0 + 20, x1, y0 + 100), 2);
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).energyPlot), x0 + 80, y0 + 20, x1, y0 + 100),
              200);
    // The rate plot: 100 collisions per 0.01 s.
    EXPECT_GT(count(sdlColor(palette(Theme::Dark).ratePlot), x0 + 80, y0 + 300, x1, y0 + 400), 200);

    TimeSeries falling(300);
    for (int k = 0; k < 300; ++k) {
        ObservablesSample s;
        s.time = 0.01 * k;
        s.kineticEnergy = 4.0e6 * std::exp(-0.3 * s.time);
        falling.record(s);
    }
    draw(w, falling);
    EXPECT_GT(rows(sdlColor(palette(Theme::Dark).energyPlot), x0 + 80, y0 + 20, x1, y0 + 100), 30);

    view_.plots = false;
    draw(w, falling);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).energyPlot), 0, 0, kSize, kSize), 0);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).ratePlot), 0, 0, kSize, kSize), 0);
}

TEST_F(OverlayRenderTest, SpeedHistogramDrawsBarsAndTheCurveOnlyWhenOn) {
    World w = thermalGas(2000, 500.0);
    TimeSeries series(4);
    view_.speeds = true;
    draw(w, series);
    const int x0 = layout().speeds.x, y0 = layout().speeds.y;
    ASSERT_EQ(layout().speeds.h, 210);
    EXPECT_GT(
        count(sdlColor(palette(Theme::Dark).histogramBar), x0 + 60, y0 + 30, kSize, kSize - 30),
        2000);
    // White: the curve (the font is grey or coloured).
    EXPECT_GT(
        count(sdlColor(palette(Theme::Dark).theoryCurve), x0 + 60, y0 + 30, kSize, kSize - 40, 0),
        60);

    view_.speeds = false;
    draw(w, series);
    EXPECT_EQ(count(sdlColor(palette(Theme::Dark).histogramBar), 0, 0, kSize, kSize), 0);
}

}  // namespace
}  // namespace psb::app

namespace psb::app {
namespace {

TEST(TrailImage, ADiscCoversThePixelsWithinHalfAPixelOfItsRimAndTheOneUnderItsCentre) {
    // Small discs (the renderer's pixel path) and larger ones, at many sub-pixel offsets.
    for (const float r : {0.75f, 0.9f, 1.3f, 2.2f}) {
        for (float cx = 5.0f; cx < 6.0f; cx += 0.23f) {
            for (float cy = 5.0f; cy < 6.0f; cy += 0.31f) {
                TrailImage img;
                img.resize(12, 12);
                img.disc(cx, cy, r, 0xFF102030u);
                for (int y = 0; y < 12; ++y) {
                    for (int x = 0; x < 12; ++x) {
                        const float dx = static_cast<float>(x) + 0.5f - cx;
                        const float dy = static_cast<float>(y) + 0.5f - cy;
                        const bool in = dx * dx + dy * dy <= (r + 0.5f) * (r + 0.5f) ||
                                        (x == static_cast<int>(cx) && y == static_cast<int>(cy));
                        EXPECT_EQ(img.at(x, y) != 0u, in) << "r " << r << " centre " << cx << ", "
                                                          << cy << " pixel " << x << ", " << y;
                    }
                }
                const SDL_Rect d = img.dirty();
                EXPECT_LE(d.x, static_cast<int>(cx));
                EXPECT_GE(d.x + d.w, static_cast<int>(cx) + 1);
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
