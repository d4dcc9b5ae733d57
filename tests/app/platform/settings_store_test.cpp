// The desktop settings file on disk: where XDG puts it, written when a setting changes and read
// back, and a broken file reported with its path and ignored.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "platform/settings_store.hpp"
#include "temp_dir_test.hpp"

namespace psb::app {
namespace {

std::string contents(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(SettingsStore, TheFileIsWhereXdgSays) {
    EXPECT_EQ(settingsPath("/cfg", "/home/u"),
              std::filesystem::path("/cfg/particle-sandbox/settings.json"));
    EXPECT_EQ(settingsPath(nullptr, "/home/u"),
              std::filesystem::path("/home/u/.config/particle-sandbox/settings.json"));
    // A relative XDG_CONFIG_HOME is invalid (the specification): HOME's folder instead.
    EXPECT_EQ(settingsPath("cfg", "/home/u"),
              std::filesystem::path("/home/u/.config/particle-sandbox/settings.json"));
    EXPECT_EQ(settingsPath("", "/home/u"),
              std::filesystem::path("/home/u/.config/particle-sandbox/settings.json"));
    EXPECT_FALSE(settingsPath(nullptr, nullptr).has_value());
    EXPECT_FALSE(settingsPath("", "").has_value());
}

class SettingsStoreFile : public TempDirTest {
  protected:
    SettingsStoreFile() : TempDirTest("psb-settings-store") {}
    [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
};

TEST_F(SettingsStoreFile, NothingIsWrittenUntilASettingChangesThenItIsReadBack) {
    const auto file = dir() / "config" / "particle-sandbox" / "settings.json";
    SettingsStore store(file);
    const SettingsRead none = store.load(ViewOptions{});
    EXPECT_TRUE(none.commands.empty());
    EXPECT_TRUE(none.problems.empty()) << "no file is no problem";
    EXPECT_FALSE(store.save(ViewOptions{}).has_value());
    EXPECT_FALSE(std::filesystem::exists(file)) << "the defaults are not written";

    ViewOptions v;
    v.theme = Theme::Light;
    v.uiScale = 2.0;
    v.uiScaleAutomatic = false;
    EXPECT_FALSE(store.save(v).has_value());
    ASSERT_TRUE(std::filesystem::exists(file)) << "the folder is made";
    EXPECT_EQ(contents(file), settingsText(v));
    // No temporary file left beside it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(file.parent_path()),
                            std::filesystem::directory_iterator()),
              1);

    SettingsStore next(file);
    const SettingsRead read = next.load(ViewOptions{});
    EXPECT_TRUE(read.problems.empty());
    EXPECT_EQ(read.commands.size(), 2u);  // the scale and the theme
}

TEST_F(SettingsStoreFile, ABrokenFileIsReportedWithItsPathAndIgnored) {
    const auto file = dir() / "settings.json";
    std::ofstream(file) << "{\"ui\": {\"theme\": \"light\"";
    SettingsStore store(file);
    const SettingsRead read = store.load(ViewOptions{});
    EXPECT_TRUE(read.commands.empty());
    ASSERT_EQ(read.problems.size(), 1u);
    EXPECT_NE(read.problems[0].find(file.string()), std::string::npos) << read.problems[0];
    EXPECT_NE(read.problems[0].find("not JSON"), std::string::npos) << read.problems[0];

    // A value out of range: said with the path, the rest read.
    std::ofstream(file, std::ios::trunc) << R"({"ui": {"scale": 9, "theme": "light"}})";
    const SettingsRead partly = SettingsStore(file).load(ViewOptions{});
    ASSERT_EQ(partly.problems.size(), 1u);
    EXPECT_EQ(partly.problems[0],
              "Settings file " + file.string() + ": ui.scale: 9 is outside 0.75 to 3 (left out)");
    EXPECT_EQ(partly.commands.size(), 1u);

    // A folder where the file should be: said, not fatal, and a save says why it failed once.
    const auto folder = dir() / "folder.json";
    std::filesystem::create_directories(folder / "x");
    SettingsStore odd(folder);
    EXPECT_EQ(odd.load(ViewOptions{}).problems.size(), 1u);
    ViewOptions v;
    v.labels = true;
    const auto problem = odd.save(v);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find(folder.string()), std::string::npos) << *problem;
    v.arrows = false;
    EXPECT_FALSE(odd.save(v).has_value()) << "said once";
}

}  // namespace
}  // namespace psb::app
