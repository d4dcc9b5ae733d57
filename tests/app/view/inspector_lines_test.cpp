// The inspector panel's text: SI values of the selected particle, and the edit prompt.

#include <gtest/gtest.h>

#include "view/inspector_lines.hpp"

namespace psb::app {
namespace {

Particle sample() {
    Particle p;
    p.id = {4, 1};
    p.position = {520, 160};
    p.velocity = {-60, 80};  // speed 100 m/s
    p.mass = 18;
    p.radius = 45;
    return p;
}

TEST(InspectorPanel, ShowsStateMomentumAndEnergyInSiUnits) {
    const auto lines = inspectorLines(sample(), EditPrompt{});
    const std::vector<std::string> want = {
        "Particle 5",  // slot 4: the fifth particle (particleNumber)
        "position        (520, 160) m",
        "velocity        (-60.0, 80.0) m/s",
        "speed           100 m/s",
        "momentum        (-1 080, 1 440) kg m/s",
        "kinetic energy  90.0 kJ",  // 18 kg × (100 m/s)² / 2
        "mass            18.0 kg",
        "radius          45.0 m",
        "Enter: edit",
    };
    EXPECT_EQ(lines, want);
}

TEST(InspectorPanel, ShowsThePromptFieldsWithTheActiveOneMarked) {
    EditPrompt prompt;
    prompt.open(sample());
    prompt.type("25");
    prompt.nextField();
    prompt.setError("radius: must be > 0 m, got -1");
    const auto lines = inspectorLines(sample(), prompt);
    ASSERT_GE(lines.size(), 5u);
    const std::vector<std::string> tail(lines.end() - 5, lines.end());
    const std::vector<std::string> want = {
        "  mass   25 kg",
        "> radius 45_ m",
        "  vx     -60 m/s",
        "  vy     80 m/s",
        "Refused: radius: must be > 0 m, got -1",
    };
    EXPECT_EQ(tail, want);
}

TEST(InspectorPanel, APromptOnAnotherParticleIsNotShown) {
    EditPrompt prompt;
    Particle other = sample();
    other.id = {9, 0};
    prompt.open(other);
    EXPECT_EQ(inspectorLines(sample(), prompt).back(), "Enter: edit");
}

}  // namespace
}  // namespace psb::app
