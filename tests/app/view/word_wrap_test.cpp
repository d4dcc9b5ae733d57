// Wrapping at spaces: a number such as 9.81 is never split, whatever the room.

#include <gtest/gtest.h>

#include <string>

#include "view/word_wrap.hpp"

namespace psb::app {
namespace {

// One unit a character: the room is a number of characters.
float characters(std::string_view t) {
    return static_cast<float>(t.size());
}

TEST(WordWrap, BreaksOnlyAtSpacesAtEveryWidth) {
    // Every break ImGui's wrap allows after punctuation ("9." / "81") is one this must not make.
    const std::string text =
        "Balls poured through 8 rows of pegs under g = 9.81 m/s², restitution 0.30, p = 1/2; "
        "a ball 2.50 mm across.";
    // From the widest word up: a narrower room breaks "m/s²" after its '/', as a path.
    for (int room = 7; room <= static_cast<int>(text.size()) + 1; ++room) {
        const std::vector<std::string> lines = wrapAtSpaces(text, room, characters);
        std::string joined;
        for (const std::string& line : lines) {
            ASSERT_FALSE(line.empty()) << "room " << room;
            EXPECT_NE(line.front(), ' ') << "room " << room << ": '" << line << "'";
            // A line longer than the room is one word that could not be broken.
            if (static_cast<int>(line.size()) > room) {
                EXPECT_EQ(line.find(' '), std::string::npos) << "room " << room;
            }
            joined += (joined.empty() ? "" : " ") + line;
        }
        EXPECT_EQ(joined, text) << "room " << room << ": the lines are the text broken at spaces";
    }
}

TEST(WordWrap, APathIsNeverBrokenAfterItsFirstSeparator) {
    // "Saved (folder /tmp/...)" broke after the path's leading "/": a line ending "(folder /"
    // and the next starting "tmp/", read as "(folder / / tmp/...)".
    const std::string text = "Saved 3 files (folder /tmp/psb-output/lesson-1/values)";
    for (int room = 16; room <= 40; ++room) {
        const std::vector<std::string> lines = wrapAtSpaces(text, room, characters);
        for (const std::string& line : lines) {
            const bool lone = line.size() >= 2 && line.back() == '/' &&
                              (line[line.size() - 2] == ' ' || line[line.size() - 2] == '(');
            EXPECT_FALSE(lone) << "room " << room << ": '" << line << "'";
        }
    }
}

TEST(WordWrap, APathWiderThanTheLineGoesOnAfterASeparator) {
    // A saved file's path has no space: it ran past the panel's edge, cut.
    const std::string text = "Saved to /home/teacher/lessons/momentum/collision-2.json";
    const auto lines = wrapAtSpaces(text, 24, characters);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "Saved to /home/teacher/");
    EXPECT_EQ(lines[1], "lessons/momentum/");
    EXPECT_EQ(lines[2], "collision-2.json");
    for (const std::string& line : lines)
        EXPECT_LE(line.size(), 24u) << line;
    // A word without a separator still stands whole.
    EXPECT_EQ(wrapAtSpaces("a 0123456789", 5, characters).back(), "0123456789");
}

TEST(WordWrap, APathThatDoesNotFitAfterTheWordsBeforeItFillsTheirLine) {
    // A path narrower than the line but not beside the words before it went whole to a line of
    // its own, and the message needed a line more than its band holds.
    const std::string text = "Saved video /home/teacher/lessons/video-1.mp4: 3.4 s, 84 frames";
    const auto lines = wrapAtSpaces(text, 36, characters);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "Saved video /home/teacher/lessons/");
    EXPECT_EQ(lines[1], "video-1.mp4: 3.4 s, 84 frames");
    // A unit with one '/' is a word: it moves whole.
    EXPECT_EQ(wrapAtSpaces("speed 9.81 m/s", 12, characters).back(), "m/s");
}

TEST(WordWrap, KeepsLineBreaksAndIndentsContinuations) {
    const auto lines = wrapAtSpaces("one two three\nfour", 8, characters, "  ");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], "one two");
    EXPECT_EQ(lines[1], "  three");
    EXPECT_EQ(lines[2], "four");
}

}  // namespace
}  // namespace psb::app
