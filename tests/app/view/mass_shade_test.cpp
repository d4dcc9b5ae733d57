// Mass as shade (mass_shade.hpp): a 1 kg and a 3 kg ball get fills a stated contrast apart on
// both themes, the heavier darker, neither lost against the background, and equal masses keep
// the scene's colours.

#include <gtest/gtest.h>

#include <vector>

#include "view/mass_shade.hpp"
#include "view/palette.hpp"

namespace psb::app {
namespace {

Rgba rgba(Color c) {
    return Rgba{c.r, c.g, c.b};
}

/// Scene colours to try: the presets' (the default blue-grey, the big ball's orange, grey),
/// the Okabe-Ito set, and the extremes.
const std::vector<Color> kColours = {
    {150, 170, 190}, {230, 120, 60},  {100, 180, 255}, {128, 128, 128}, {230, 159, 0},
    {86, 180, 233},  {0, 158, 115},   {0, 114, 178},   {213, 94, 0},    {204, 121, 167},
    {255, 230, 0},   {255, 255, 255}, {0, 0, 0},       {255, 0, 0},     {40, 40, 40},
};

TEST(MassShade, OneAndThreeKilogramBallsGetFillsAtLeastTheStatedContrastApart) {
    const std::vector<double> masses{1.0, 3.0};
    const MassRange range = massRange(masses);
    ASSERT_TRUE(range.varies());
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        const Rgba background = palette(theme).background;
        for (const Color scene : kColours) {
            // As drawn: the light theme maps a scene's colour first (palette.hpp).
            const Color colour = theme == Theme::Light ? lightColour(scene) : scene;
            const MassShades shades = massShades(colour, theme);
            const Color light = shades.at(range.place(1.0)), heavy = shades.at(range.place(3.0));
            const std::string what = std::string(theme == Theme::Dark ? "dark" : "light") +
                                     " theme, colour " + std::to_string(scene.r) + "," +
                                     std::to_string(scene.g) + "," + std::to_string(scene.b);
            EXPECT_GE(contrastRatio(rgba(light), rgba(heavy)), kMinContrast) << what;
            // The heavier is the darker: less contrast against black.
            EXPECT_LT(contrastRatio(rgba(heavy), Rgba{0, 0, 0}),
                      contrastRatio(rgba(light), Rgba{0, 0, 0}))
                << what;
            // Neither is harder to see than WCAG's 3:1 for graphics, or than the colour was.
            const double floor = std::min(3.0, contrastRatio(rgba(colour), background));
            EXPECT_GE(contrastRatio(rgba(light), background), floor - 1e-9) << what;
            EXPECT_GE(contrastRatio(rgba(heavy), background), floor - 1e-9) << what;
        }
    }
}

TEST(MassShade, AMassBetweenTakesTheShadeAtItsPlaceOnALogScale) {
    const std::vector<double> masses{1.0, 100.0, 10.0, 1.0};
    const MassRange range = massRange(masses);
    EXPECT_EQ(range.lo, 1.0);
    EXPECT_EQ(range.hi, 100.0);
    EXPECT_NEAR(range.place(10.0), 0.5, 1e-12);
    EXPECT_EQ(range.place(1000.0), 1.0);
    const MassShades s{Color{200, 200, 200}, Color{100, 100, 100}};
    EXPECT_EQ(s.at(0.5), (Color{150, 150, 150}));
}

TEST(MassShade, EqualMassesAreNotShaded) {
    EXPECT_FALSE(massRange(std::vector<double>{2.0, 2.0, 2.0}).varies());
    EXPECT_FALSE(massRange(std::vector<double>{}).varies());
    EXPECT_FALSE(massRange(std::vector<double>{1.0, 1.0 + 1e-9}).varies());
    // Non-finite or non-positive masses (never from a valid world) are left out of the range.
    EXPECT_FALSE(massRange(std::vector<double>{1.0, 0.0, -3.0}).varies());
}

}  // namespace
}  // namespace psb::app
