// A particle's label (particle_labels.hpp): one compact form, its values in two lines, or its
// name alone; measured as the drawing layer draws it.

#include <gtest/gtest.h>

#include "view/fixed_measure.hpp"
#include "view/particle_labels.hpp"

namespace psb::app {
namespace {

TEST(ParticleLabel, TwoLinesOfItsValuesOrItsNameAlone) {
    // The original's first ball at 200 %: five lines ("x velocity: 1.80 m/s", "y velocity: ...",
    // "p: ...", "mass: ...") beside some balls, one ("particle 2") beside others. Two lines, the
    // same for every label.
    const ParticleLabelText t = particleLabelText(1, 12.0, 1.8, -1.2);
    EXPECT_EQ(t.values[0], "particle 1, 12.0 kg");
    EXPECT_EQ(t.values[1], "v (1.80, -1.20) m/s");
    EXPECT_EQ(t.name, "particle 1");
    // What rounds to zero reads 0.00, never -0.00.
    EXPECT_EQ(particleLabelText(3, 1.0, -0.004, -0.0).values[1], "v (0.00, 0.00) m/s");
    EXPECT_EQ(particleLabelText(12, 0.25, 0.0, 0.0).values[0], "particle 12, 0.250 kg");
}

TEST(ParticleLabel, ItsAskMeasuresBothFormsInTheLabelsFont) {
    const test::FixedMeasure font(2.0);  // 16 pixels a character, 34 a line
    const ParticleLabelText t = particleLabelText(1, 12.0, 1.8, -1.2);
    const LabelAsk a = particleLabelAsk(t, {100, 100, 40, 40}, font, true);
    EXPECT_EQ(a.disc, (PixelRect{100, 100, 40, 40}));
    EXPECT_EQ(a.size.x, 19 * 16 + 4);
    EXPECT_EQ(a.size.y, 2 * 34 + 1);
    EXPECT_EQ(a.nameSize.x, 10 * 16 + 4);
    EXPECT_EQ(a.nameSize.y, 34 + 1);
    EXPECT_TRUE(a.inBox);
}

}  // namespace
}  // namespace psb::app
