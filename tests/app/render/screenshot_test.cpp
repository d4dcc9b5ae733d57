// F12's PNG: drawn offscreen with the software renderer, encoded, written, read back with
// stb_image.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <SDL.h>
#include <stb_image.h>
#include <unistd.h>

#include <particle_sandbox/scene.hpp>

#include "render/screenshot.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

class ScreenshotTest : public ::testing::Test {
  protected:
    void SetUp() override {
        surface_ = SDL_CreateRGBSurfaceWithFormat(0, kW, kH, 32, SDL_PIXELFORMAT_ARGB8888);
        ASSERT_NE(surface_, nullptr) << SDL_GetError();
        sdl_ = SDL_CreateSoftwareRenderer(surface_);
        ASSERT_NE(sdl_, nullptr) << SDL_GetError();
        dir_ = fs::temp_directory_path() / ("psb-shot-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // Black, with a red square at (10..29, 20..39) and a green pixel at (70, 5).
        SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
        SDL_RenderClear(sdl_);
        SDL_SetRenderDrawColor(sdl_, 255, 0, 0, 255);
        const SDL_Rect square{10, 20, 20, 20};
        SDL_RenderFillRect(sdl_, &square);
        SDL_SetRenderDrawColor(sdl_, 0, 255, 0, 255);
        SDL_RenderDrawPoint(sdl_, 70, 5);
    }
    void TearDown() override {
        if (sdl_ != nullptr) SDL_DestroyRenderer(sdl_);
        if (surface_ != nullptr) SDL_FreeSurface(surface_);
        fs::remove_all(dir_);
    }

    struct Image {
        int w = 0, h = 0;
        std::vector<unsigned char> rgb;
        [[nodiscard]] std::array<int, 3> at(int x, int y) const {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * w + x);
            return {rgb[i], rgb[i + 1], rgb[i + 2]};
        }
    };
    static Image decode(const std::string& png) {
        Image im;
        int channels = 0;
        unsigned char* data =
            stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                  static_cast<int>(png.size()), &im.w, &im.h, &channels, 3);
        if (data == nullptr) return im;
        im.rgb.assign(data, data + static_cast<std::size_t>(im.w) * im.h * 3);
        stbi_image_free(data);
        return im;
    }

    static constexpr int kW = 96, kH = 64;
    SDL_Surface* surface_ = nullptr;
    SDL_Renderer* sdl_ = nullptr;
    fs::path dir_;
};

TEST_F(ScreenshotTest, ThePngHoldsTheRenderedPixels) {
    const Image im = decode(capturePng(sdl_));
    ASSERT_EQ(im.w, kW);
    ASSERT_EQ(im.h, kH);
    EXPECT_EQ(im.at(15, 25), (std::array<int, 3>{255, 0, 0}));
    EXPECT_EQ(im.at(29, 39), (std::array<int, 3>{255, 0, 0}));
    EXPECT_EQ(im.at(30, 40), (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(im.at(70, 5), (std::array<int, 3>{0, 255, 0}));
    EXPECT_EQ(im.at(0, 0), (std::array<int, 3>{0, 0, 0}));
}

TEST_F(ScreenshotTest, SaveWritesANamedFileThatReadsBack) {
    const fs::path p = saveScreenshot(sdl_, dir_);
    EXPECT_EQ(p.parent_path(), dir_);
    const std::string name = p.filename().string();
    // particle-sandbox-YYYYMMDD-HHMMSS.png
    EXPECT_EQ(name.rfind("particle-sandbox-", 0), 0u) << name;
    EXPECT_EQ(name.size(), std::string("particle-sandbox-20240101-120000.png").size()) << name;
    std::ifstream in(p, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const Image im = decode(bytes);
    EXPECT_EQ(im.w, kW);
    EXPECT_EQ(im.h, kH);
    EXPECT_EQ(im.at(15, 25), (std::array<int, 3>{255, 0, 0}));
}

TEST_F(ScreenshotTest, TwoInTheSameSecondGetDistinctNames) {
    std::tm when{};
    when.tm_year = 124;  // 2024
    when.tm_mon = 2;
    when.tm_mday = 5;
    when.tm_hour = 9;
    when.tm_min = 7;
    when.tm_sec = 3;
    const fs::path first = screenshotPath(dir_, when);
    EXPECT_EQ(first.filename(), "particle-sandbox-20240305-090703.png");
    std::ofstream(first) << "x";
    EXPECT_EQ(screenshotPath(dir_, when).filename(), "particle-sandbox-20240305-090703-2.png");
}

TEST_F(ScreenshotTest, AFailedWriteSaysWhy) {
    try {
        (void)saveScreenshot(sdl_, dir_ / "no" / "such");
        FAIL() << "no exception";
    } catch (const SaveError& e) {
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace psb::app
