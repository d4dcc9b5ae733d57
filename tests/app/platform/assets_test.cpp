// Finding the shipped files, and saying where it looked when they are missing.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "platform/assets.hpp"

namespace psb::app {
namespace {

TEST(Assets, TheShippedFontsAreFound) {
    const auto path = findAsset("fonts/DejaVuSansMono.ttf");
    EXPECT_EQ(path.filename(), "DejaVuSansMono.ttf");
    EXPECT_TRUE(std::filesystem::is_regular_file(path));
}

TEST(Assets, AMissingAssetNamesItselfAndEveryPlaceLooked) {
    try {
        (void)findAsset("fonts/NoSuchFont.ttf");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("fonts/NoSuchFont.ttf"), std::string::npos) << what;
        EXPECT_NE(what.find("PSB_ASSETS_DIR"), std::string::npos) << what;
        for (const auto& dir : assetDirectories()) {
            EXPECT_NE(what.find(dir.string()), std::string::npos) << dir;
        }
    }
}

TEST(Assets, TheShippedPresetsAreFound) {
    const auto presets = presetScenes();
    ASSERT_FALSE(presets.empty());
    EXPECT_EQ(presets.front().filename(), "01-original.json");
}

}  // namespace
}  // namespace psb::app
