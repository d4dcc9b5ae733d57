// The description's field wraps as it is typed: soft breaks in place of spaces.

#include <gtest/gtest.h>

#include <string>

#include "view/soft_wrap.hpp"

namespace psb::app {
namespace {

// One unit a byte: a room of 10 holds ten characters.
const MeasureText kChars = [](std::string_view t) { return static_cast<float>(t.size()); };

TEST(SoftWrap, BreaksAtTheLastSpaceThatKeepsEachLineWithinTheRoom) {
    SoftWrap w;
    const std::string shown = w.start("Two balls collide head on in a box", 10.f, kChars);
    EXPECT_EQ(shown, "Two balls\ncollide\nhead on in\na box");
    EXPECT_EQ(shown.size(), std::string("Two balls collide head on in a box").size());
    EXPECT_EQ(w.text(shown), "Two balls collide head on in a box");
}

TEST(SoftWrap, TheUsersOwnLineBreaksStayAndAWordTooLongStaysWhole) {
    SoftWrap w;
    const std::string shown = w.start("First.\nA verylongwordindeed here", 10.f, kChars);
    EXPECT_EQ(shown, "First.\nA\nverylongwordindeed\nhere");
    EXPECT_EQ(w.text(shown), "First.\nA verylongwordindeed here");
}

TEST(SoftWrap, TypingAtTheEndMovesTheLastWordDownInPlace) {
    SoftWrap w;
    std::string shown = w.start("one two", 10.f, kChars);
    EXPECT_EQ(shown, "one two");
    for (const char c : std::string(" three")) {
        shown += c;
        w.edited(shown, 10.f, kChars);
    }
    EXPECT_EQ(shown, "one two\nthree");
    EXPECT_EQ(w.text(shown), "one two three");
    // Deleting a word joins the lines again: the soft break was a space.
    shown.erase(4, 4);  // "two" and the break after it
    w.edited(shown, 10.f, kChars);
    EXPECT_EQ(w.text(shown), "one three");
    EXPECT_EQ(shown, "one three");
}

TEST(SoftWrap, AnEditInTheMiddleKeepsTheUsersBreaksAndRewrapsTheRest) {
    SoftWrap w;
    std::string shown = w.start("aa bb\ncc dd ee ff", 8.f, kChars);
    EXPECT_EQ(shown, "aa bb\ncc dd ee\nff");
    shown.insert(3, "xxxx ");  // "aa xxxx bb\n..."
    EXPECT_TRUE(w.edited(shown, 8.f, kChars));
    EXPECT_EQ(shown, "aa xxxx\nbb\ncc dd ee\nff");
    EXPECT_EQ(w.text(shown), "aa xxxx bb\ncc dd ee ff");
}

}  // namespace
}  // namespace psb::app
