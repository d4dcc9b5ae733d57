// The settings file's text: what it keeps (the Show options, the UI's scale and theme), a round
// trip, and what a broken or odd file gives: refused whole with the reason when it is not a JSON
// object, the rest read with each bad value left out and said.

#include <gtest/gtest.h>

#include <stdexcept>

#include "platform/settings_file.hpp"

namespace psb::app {
namespace {

std::string refusal(const std::string& text) {
    try {
        (void)readSettings(text, ViewOptions{});
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "accepted";
}

/// `view` with the commands of `read` applied as the session would.
ViewOptions applied(ViewOptions view, const SettingsRead& read) {
    for (const Command& c : read.commands) {
        if (const auto* s = std::get_if<cmd::SetShow>(&c)) view.flag(s->option) = s->on;
        if (const auto* u = std::get_if<cmd::SetUiScale>(&c)) {
            view.uiScale = u->scale;
            view.uiScaleAutomatic = u->automatic;
        }
        if (const auto* t = std::get_if<cmd::SetTheme>(&c)) view.theme = t->theme;
    }
    return view;
}

TEST(SettingsFile, KeepsTheShowOptionsAndRestoresOnlyThoseThatDiffer) {
    ViewOptions shown;
    shown.arrows = false;
    shown.plots = true;
    const std::string text = settingsText(shown);
    EXPECT_NE(text.find("\"arrows\": false"), std::string::npos) << text;
    EXPECT_NE(text.find("\"plots\": true"), std::string::npos) << text;

    const SettingsRead read = readSettings(text, ViewOptions{});
    EXPECT_TRUE(read.problems.empty());
    ASSERT_EQ(read.commands.size(), 2u);
    const auto& a = std::get<cmd::SetShow>(read.commands[0]);
    EXPECT_EQ(a.option, ShowOption::Arrows);
    EXPECT_FALSE(a.on);
    const auto& p = std::get<cmd::SetShow>(read.commands[1]);
    EXPECT_EQ(p.option, ShowOption::Plots);
    EXPECT_TRUE(p.on);
    EXPECT_TRUE(readSettings(text, shown).commands.empty());
}

TEST(SettingsFile, TheScaleAndThemeMakeTheRoundTrip) {
    ViewOptions v;
    v.uiScale = 2.0;
    v.uiScaleAutomatic = false;
    v.theme = Theme::Light;
    v.labels = true;
    const std::string text = settingsText(v);
    EXPECT_NE(text.find("\"scale\": 2.0"), std::string::npos) << text;
    EXPECT_NE(text.find("\"theme\": \"light\""), std::string::npos) << text;
    const ViewOptions back = applied(ViewOptions{}, readSettings(text, ViewOptions{}));
    EXPECT_FALSE(keptSettingsDiffer(back, v));
    EXPECT_EQ(back.uiScale, 2.0);
    EXPECT_FALSE(back.uiScaleAutomatic);
    EXPECT_EQ(back.theme, Theme::Light);
    EXPECT_TRUE(back.labels);

    // An automatic scale is written as "auto" and read back as automatic, whatever it is now.
    ViewOptions automatic;
    automatic.uiScale = 1.5;
    const std::string autoText = settingsText(automatic);
    EXPECT_NE(autoText.find("\"scale\": \"auto\""), std::string::npos) << autoText;
    const SettingsRead read = readSettings(autoText, v);
    const ViewOptions again = applied(v, read);
    EXPECT_TRUE(again.uiScaleAutomatic);
}

TEST(SettingsFile, ASettingNotNamedStaysAndUnknownKeysAreSkipped) {
    EXPECT_TRUE(readSettings(R"({"version": 1, "show": {}})", ViewOptions{}).commands.empty());
    const SettingsRead read = readSettings(
        R"({"version": 7, "window": [1, 2], "show": {"sparkles": true, "labels": true},
            "ui": {"font": "big", "theme": "light"}})",
        ViewOptions{});
    EXPECT_TRUE(read.problems.empty());
    const ViewOptions v = applied(ViewOptions{}, read);
    EXPECT_TRUE(v.labels);
    EXPECT_EQ(v.theme, Theme::Light);
}

TEST(SettingsFile, AScaleOutOfRangeIsLeftOutAndSaid) {
    const SettingsRead read = readSettings(
        R"({"show": {"labels": true}, "ui": {"scale": 5, "theme": "dark"}})", ViewOptions{});
    ASSERT_EQ(read.problems.size(), 1u);
    EXPECT_EQ(read.problems[0], "ui.scale: 5 is outside 0.75 to 3");
    const ViewOptions v = applied(ViewOptions{}, read);
    EXPECT_TRUE(v.labels) << "the rest is read";
    EXPECT_TRUE(v.uiScaleAutomatic);
    for (const char* bad : {R"({"ui": {"scale": 0.5}})", R"({"ui": {"scale": -1}})",
                            R"({"ui": {"scale": "huge"}})", R"({"ui": {"scale": null}})"}) {
        EXPECT_EQ(readSettings(bad, ViewOptions{}).problems.size(), 1u) << bad;
        EXPECT_TRUE(readSettings(bad, ViewOptions{}).commands.empty()) << bad;
    }
    EXPECT_EQ(readSettings(R"({"ui": {"theme": "sepia"}})", ViewOptions{}).problems.at(0),
              "ui.theme: expected \"dark\" or \"light\"");
    EXPECT_EQ(readSettings(R"({"show": {"labels": "yes"}})", ViewOptions{}).problems.at(0),
              "show.labels: expected true or false");
}

TEST(SettingsFile, ATextThatIsNotAJsonObjectIsRefusedWithTheReason) {
    EXPECT_EQ(refusal("{\"show\": {\"arrows\": tru"),
              "not JSON: it breaks off or goes wrong at character 24");
    EXPECT_EQ(refusal("[1, 2]"), "expected a JSON object, {...}");
    EXPECT_EQ(refusal(""), "not JSON: it breaks off or goes wrong at character 1");
    EXPECT_EQ(refusal("\"dark\""), "expected a JSON object, {...}");
}

}  // namespace
}  // namespace psb::app
