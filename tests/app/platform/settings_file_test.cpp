// The page's settings file: what it keeps, and a broken one refused with the reason.

#include <gtest/gtest.h>

#include <stdexcept>

#include "platform/settings_file.hpp"

namespace psb::app {
namespace {

TEST(SettingsFile, KeepsTheShowOptionsAndRestoresOnlyThoseThatDiffer) {
    ViewOptions shown;
    shown.arrows = false;
    shown.plots = true;
    const std::string text = settingsText(shown);
    EXPECT_NE(text.find("\"arrows\": false"), std::string::npos) << text;
    EXPECT_NE(text.find("\"plots\": true"), std::string::npos) << text;

    const auto commands = settingsCommands(text, ViewOptions{});
    ASSERT_EQ(commands.size(), 2u);
    const auto& a = std::get<cmd::SetShow>(commands[0]);
    EXPECT_EQ(a.option, ShowOption::Arrows);
    EXPECT_FALSE(a.on);
    const auto& p = std::get<cmd::SetShow>(commands[1]);
    EXPECT_EQ(p.option, ShowOption::Plots);
    EXPECT_TRUE(p.on);
    EXPECT_TRUE(settingsCommands(text, shown).empty());
}

TEST(SettingsFile, AnOptionNotNamedStays) {
    EXPECT_TRUE(settingsCommands(R"({"version": 1, "show": {}})", ViewOptions{}).empty());
}

TEST(SettingsFile, ABrokenFileIsRefusedWithTheReason) {
    const auto why = [](const std::string& text) {
        try {
            (void)settingsCommands(text, ViewOptions{});
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(why("{\"show\": {\"arrows\": tru"),
              "not JSON: it breaks off or goes wrong at character 24");
    EXPECT_EQ(why("[1, 2]"), "expected an object with \"show\"");
    EXPECT_EQ(why(R"({"show": {"labels": "yes"}})"), "show.labels: expected true or false");
}

}  // namespace
}  // namespace psb::app
