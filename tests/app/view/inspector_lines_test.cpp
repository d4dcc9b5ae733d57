// The inspector panel's text: SI values of the selected particle, and the edit prompt.

#include <gtest/gtest.h>

#include <algorithm>

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
    ASSERT_GE(lines.size(), 7u);
    const std::vector<std::string> tail(lines.end() - 7, lines.end());
    const std::vector<std::string> want = {
        "  mass   25 kg",
        "> radius 45_ m",
        "  vx     -60 m/s",
        "  vy     80 m/s",
        "  omega  0 rad/s",
        "  k      0.5 (I = k m r\u00b2)",
        "Refused: radius: must be > 0 m, got -1",
    };
    EXPECT_EQ(tail, want);
}

TEST(InspectorPanel, InAWorldWithRotationShowsTheSpinBothEnergiesAndK) {
    Particle p = sample();
    p.angularVelocity = 2.0 * 3.14159265358979323846;  // one turn a second
    p.inertiaFactor = 0.4;
    const auto lines = inspectorLines(p, EditPrompt{}, true, true);
    const std::vector<std::string> want = {
        "Particle 5",
        "position        (520, 160) m",
        "velocity        (-60.0, 80.0) m/s",
        "speed           100 m/s",
        "momentum        (-1 080, 1 440) kg m/s",
        "angular velocity 6.28 rad/s = 60.0 rev/min",
        "kinetic energy  90.0 kJ translation",
        // 0.4 × 18 kg × (45 m)² × (2π /s)² / 2 = 287.8 kJ
        "                288 kJ rotation",
        "mass            18.0 kg",
        "radius          45.0 m",
        "inertia factor  k = 0.4 (I = k m r\u00b2)",
        "Enter: edit",
    };
    EXPECT_EQ(lines, want);
}

TEST(InspectorPanel, AParticleWithFixedRotationSaysSo) {
    Particle p = sample();
    p.fixedRotation = true;
    const auto lines = inspectorLines(p, EditPrompt{}, true, true);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "turning         fixed rotation (never turns)"),
              lines.end());
    EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                            [](const std::string& l) {
                                return l.find("angular velocity") != std::string::npos;
                            }),
              0);
}

TEST(InspectorPanel, OnATouchScreenItNamesThePanelsFieldsAndNoKeyTheScreenLacks) {
    // A tablet has no Enter to open the prompt: the panel's Selected particle edits.
    const auto shown = inspectorLines(sample(), EditPrompt{}, true, false, {}, true);
    EXPECT_EQ(shown.back(), "Edit: the panel's Selected particle");
    // A prompt opened all the same (a keyboard beside the screen): its on-screen keyboard has
    // Enter, neither Tab nor Esc; a tap on empty space closes it.
    EditPrompt prompt;
    prompt.open(sample());
    for (const bool readings : {true, false}) {
        const auto lines = inspectorLines(sample(), prompt, readings, false, {}, true);
        EXPECT_NE(
            std::find(lines.begin(), lines.end(), "Edit  Enter: apply  tap empty space: cancel"),
            lines.end());
        for (const std::string& l : lines) {
            EXPECT_EQ(l.find("Tab"), std::string::npos) << l;
            EXPECT_EQ(l.find("Esc"), std::string::npos) << l;
        }
    }
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
