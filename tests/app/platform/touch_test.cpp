// Two fingers: the first one's drag ends when the second lands, then they pan and zoom.

#include <gtest/gtest.h>

#include "platform/touch.hpp"

namespace psb::app {
namespace {

constexpr SDL_Point kOutput{1000, 500};

SDL_TouchFingerEvent finger(Uint32 type, SDL_FingerID id, float x, float y) {
    SDL_TouchFingerEvent e{};
    e.type = type;
    e.fingerId = id;
    e.x = x / kOutput.x;  // SDL gives fractions of the window
    e.y = y / kOutput.y;
    return e;
}

TEST(TouchGestures, OneFingerLeavesTheMouseToSdl) {
    TouchGestures t;
    EXPECT_TRUE(t.translate(finger(SDL_FINGERDOWN, 1, 100, 100), kOutput, Vec2(100, 100)).empty());
    EXPECT_TRUE(
        t.translate(finger(SDL_FINGERMOTION, 1, 150, 120), kOutput, Vec2(150, 120)).empty());
    EXPECT_FALSE(t.pinching());
    EXPECT_TRUE(t.translate(finger(SDL_FINGERUP, 1, 150, 120), kOutput, Vec2(150, 120)).empty());
}

TEST(TouchGestures, ASecondFingerEndsTheDragThenPansAndZooms) {
    TouchGestures t;
    (void)t.translate(finger(SDL_FINGERDOWN, 1, 400, 200), kOutput, Vec2(400, 200));
    const auto second = t.translate(finger(SDL_FINGERDOWN, 2, 600, 200), kOutput, Vec2(400, 200));
    ASSERT_EQ(second.size(), 1u);
    ASSERT_TRUE(std::holds_alternative<cmd::PointerUp>(second[0]));
    EXPECT_EQ(std::get<cmd::PointerUp>(second[0]).screen, Vec2(400, 200));
    // ... as a pinch's, not a click (tools_hand.cpp: no "Selection cleared", no launch).
    EXPECT_TRUE(std::get<cmd::PointerUp>(second[0]).pinch);
    EXPECT_TRUE(t.pinching());

    // The second finger moves 100 px right: the midpoint moves 50 px, the spread grows 200 -> 300.
    const auto spread = t.translate(finger(SDL_FINGERMOTION, 2, 700, 200), kOutput, Vec2());
    ASSERT_EQ(spread.size(), 2u);
    ASSERT_TRUE(std::holds_alternative<cmd::Pan>(spread[0]));
    EXPECT_NEAR(std::get<cmd::Pan>(spread[0]).pixels.x(), 50.0, 1e-3);
    EXPECT_NEAR(std::get<cmd::Pan>(spread[0]).pixels.y(), 0.0, 1e-3);
    ASSERT_TRUE(std::holds_alternative<cmd::Zoom>(spread[1]));
    EXPECT_NEAR(std::get<cmd::Zoom>(spread[1]).factor, 1.5, 1e-4);
    EXPECT_NEAR(std::get<cmd::Zoom>(spread[1]).screen.x(), 550.0, 1e-3);

    // Lifting one finger keeps the gesture (no new drag) until both are up.
    (void)t.translate(finger(SDL_FINGERUP, 1, 400, 200), kOutput, Vec2());
    EXPECT_TRUE(t.pinching());
    EXPECT_TRUE(t.translate(finger(SDL_FINGERMOTION, 2, 650, 200), kOutput, Vec2()).empty());
    (void)t.translate(finger(SDL_FINGERUP, 2, 650, 200), kOutput, Vec2());
    EXPECT_FALSE(t.pinching());
}

TEST(TouchGestures, FingersTooCloseTogetherPanWithoutZooming) {
    TouchGestures t;
    (void)t.translate(finger(SDL_FINGERDOWN, 1, 500, 200), kOutput, Vec2(500, 200));
    (void)t.translate(finger(SDL_FINGERDOWN, 2, 505, 200), kOutput, Vec2(500, 200));
    const auto moved = t.translate(finger(SDL_FINGERMOTION, 2, 510, 210), kOutput, Vec2());
    ASSERT_EQ(moved.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<cmd::Pan>(moved[0]));
}

}  // namespace
}  // namespace psb::app
