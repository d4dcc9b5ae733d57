// The themes' colours (view/palette.hpp): text readable on its background (WCAG's 4.5:1), the
// light theme's plot and momentum colours distinct and from the Okabe–Ito palette, and particle
// colours mapped onto it.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "view/palette.hpp"

namespace psb::app {
namespace {

/// `over` drawn with its opacity on the opaque `under`.
Rgba blend(Rgba over, Rgba under) {
    const auto mix = [&](std::uint8_t a, std::uint8_t b) {
        return static_cast<std::uint8_t>((a * over.a + b * (255 - over.a)) / 255);
    };
    return {mix(over.r, under.r), mix(over.g, under.g), mix(over.b, under.b), 255};
}

const std::vector<Rgba> kOkabeIto = {{0, 0, 0},     {230, 159, 0},  {86, 180, 233},
                                     {0, 158, 115}, {240, 228, 66}, {0, 114, 178},
                                     {213, 94, 0},  {204, 121, 167}};

TEST(Palette, ContrastRatioIsWcags) {
    EXPECT_NEAR(contrastRatio({0, 0, 0}, {255, 255, 255}), 21.0, 1e-9);
    EXPECT_NEAR(contrastRatio({255, 255, 255}, {255, 255, 255}), 1.0, 1e-9);
    EXPECT_NEAR(contrastRatio({118, 118, 118}, {255, 255, 255}), 4.54, 0.01);  // WCAG's grey
}

TEST(Palette, TheTextPanelsAreOpaqueSoNothingShowsThroughThem) {
    // The Galton board at 200 %: the balls' velocity arrows below the box ran on through the
    // messages' line, seen through its translucent panel. A panel (the HUD, the messages, the
    // inspector, the charts, the momentum legend) hides what is under it.
    for (const Theme theme : {Theme::Dark, Theme::Light})
        EXPECT_EQ(palette(theme).panel.a, 255) << toString(theme);
}

TEST(Palette, TextIsReadableOnItsBackgroundInBothThemes) {
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        const Palette& p = palette(theme);
        const Rgba panel = blend(p.panel, p.background);
        const Rgba label = blend(p.labelBox, p.background);
        SCOPED_TRACE(toString(theme));
        EXPECT_GE(contrastRatio(p.text, p.background), 4.5);
        EXPECT_GE(contrastRatio(p.text, panel), 4.5);
        EXPECT_GE(contrastRatio(p.tickText, panel), 4.5);
        EXPECT_GE(contrastRatio(p.labelText, label), 4.5);
        EXPECT_GE(contrastRatio(p.warning, p.background), 4.5);
        EXPECT_GE(contrastRatio(p.caution, p.controls), 4.5);
        EXPECT_GE(contrastRatio(p.walls, p.background), 4.5);
    }
    // The light theme is light: a white background, near-black text.
    EXPECT_EQ(palette(Theme::Light).background, (Rgba{255, 255, 255}));
    EXPECT_GE(contrastRatio(palette(Theme::Light).text, {255, 255, 255}), 15.0);
}

TEST(Palette, LegendsInTheirCurvesColoursAreReadableOnThePanel) {
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        const Palette& p = palette(theme);
        const Rgba panel = blend(p.panel, p.background);
        SCOPED_TRACE(toString(theme));
        for (const Rgba c :
             {p.energyPlot, p.pxPlot, p.pyPlot, p.ratePlot, p.histogramBar, p.theoryCurve, p.binBar,
              p.normalCurve, p.momentumArrow, p.totalMomentum, p.centreOfMass}) {
            // The panel as drawn (its opacity over the background), and as the code passes it.
            EXPECT_GE(contrastRatio(readableText(c, panel), panel), 4.5);
            EXPECT_GE(contrastRatio(readableText(c, p.panel), panel), 4.4);
        }
    }
    // Okabe-Ito orange on the light panel is 2:1; its text shade keeps the hue, darker.
    const Rgba orange{230, 159, 0};
    const Rgba text = readableText(orange, palette(Theme::Light).panel);
    EXPECT_LT(contrastRatio(orange, {243, 243, 243}), 2.5);
    EXPECT_LT(text.r, orange.r);
    EXPECT_GT(text.r, text.g);
    EXPECT_GT(text.g, text.b);
    EXPECT_EQ(readableText({17, 17, 17}, {255, 255, 255}), (Rgba{17, 17, 17})) << "kept";
}

TEST(Palette, TheLightThemesChartColoursAreOkabeItoAndDistinct) {
    const Palette& p = palette(Theme::Light);
    const std::vector<Rgba> plots = {p.energyPlot, p.pxPlot, p.pyPlot, p.ratePlot};
    const std::vector<Rgba> momentum = {p.momentumArrow, p.totalMomentum, p.centreOfMass};
    for (const auto& group : {plots, momentum}) {
        for (std::size_t i = 0; i < group.size(); ++i) {
            EXPECT_NE(std::find(kOkabeIto.begin(), kOkabeIto.end(), group[i]), kOkabeIto.end())
                << "colour " << i;
            for (std::size_t j = i + 1; j < group.size(); ++j)
                EXPECT_NE(group[i], group[j]);
            // Lines on white: at least 2:1 (they are not text; WCAG asks 3:1 of large shapes,
            // which Okabe–Ito's orange and sky blue miss, drawn thick instead).
            EXPECT_GE(contrastRatio(group[i], p.background), 2.0) << "colour " << i;
        }
    }
}

TEST(Palette, ParticleColoursMapOntoOkabeItoOnTheLightTheme) {
    EXPECT_FALSE(palette(Theme::Dark).mapParticles);
    EXPECT_TRUE(palette(Theme::Light).mapParticles);
    const auto mapped = [](Color c) {
        const Color m = lightColour(c);
        return Rgba{m.r, m.g, m.b};
    };
    // White, grey and black particles become black: they would vanish on white.
    EXPECT_EQ(mapped({255, 255, 255}), (Rgba{0, 0, 0}));
    EXPECT_EQ(mapped({128, 128, 128}), (Rgba{0, 0, 0}));
    EXPECT_EQ(mapped({0, 0, 0}), (Rgba{0, 0, 0}));
    // Red and green, the pair deuteranopes confuse, become vermillion and bluish green.
    EXPECT_EQ(mapped({255, 0, 0}), (Rgba{213, 94, 0}));
    EXPECT_EQ(mapped({0, 200, 0}), (Rgba{0, 158, 115}));
    EXPECT_EQ(mapped({255, 200, 0}), (Rgba{230, 159, 0}));     // yellow: orange, seen on white
    EXPECT_EQ(mapped({40, 60, 220}), (Rgba{0, 114, 178}));     // a dark blue: blue
    EXPECT_EQ(mapped({120, 200, 255}), (Rgba{86, 180, 233}));  // a light one: sky blue
    EXPECT_EQ(mapped({255, 0, 255}), (Rgba{204, 121, 167}));
    for (int r = 0; r < 256; r += 51) {
        for (int g = 0; g < 256; g += 51) {
            for (int b = 0; b < 256; b += 51) {
                const Rgba m = mapped({static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g),
                                       static_cast<std::uint8_t>(b)});
                EXPECT_NE(std::find(kOkabeIto.begin(), kOkabeIto.end(), m), kOkabeIto.end());
                EXPECT_NE(m, (Rgba{240, 228, 66})) << "no yellow on white";
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
