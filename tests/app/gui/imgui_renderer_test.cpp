// The ImGui adapter drawing with SDL's software renderer into an offscreen surface (no window):
// known ImGui frames, read back pixel by pixel.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include <imgui.h>

#include "gui/gui_context.hpp"
#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 400;
constexpr SDL_Color kClear{10, 20, 30, 255};
constexpr SDL_Color kPanelBlue{0, 0, 255, 255};
constexpr SDL_Color kButtonGreen{0, 204, 0, 255};  // ImGui rounds 0.8 * 255 to 204

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoScrollbar |
                                    ImGuiWindowFlags_NoSavedSettings;

bool same(SDL_Color a, SDL_Color b, int tolerance = 1) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}

std::string str(SDL_Color c) {
    std::ostringstream os;
    os << '(' << int{c.r} << ", " << int{c.g} << ", " << int{c.b} << ')';
    return os.str();
}

class ImGuiRendererTest : public OffscreenTest {
  protected:
    ImGuiRendererTest() : OffscreenTest(kSize) {}

    void SetUp() override {
        OffscreenTest::SetUp();
        gui_ = std::make_unique<GuiContext>(sdl_);
        ImGuiStyle& style = ImGui::GetStyle();
        style.WindowBorderSize = 0.f;
        style.WindowRounding = 0.f;
        style.FrameRounding = 0.f;
        style.Colors[ImGuiCol_WindowBg] = ImVec4(0.f, 0.f, 1.f, 1.f);
        style.Colors[ImGuiCol_Button] = ImVec4(0.f, 0.8f, 0.f, 1.f);
        style.Colors[ImGuiCol_Text] = ImVec4(1.f, 1.f, 1.f, 1.f);
    }
    void TearDown() override {
        gui_.reset();
        OffscreenTest::TearDown();
    }

    void clear() {
        SDL_SetRenderDrawColor(sdl_, kClear.r, kClear.g, kClear.b, 255);
        SDL_RenderClear(sdl_);
    }
    /// Ends the ImGui frame, draws it and flushes SDL's batch into the surface.
    void finish() {
        EXPECT_EQ(gui_->endFrame(), 0) << SDL_GetError();
        SDL_RenderPresent(sdl_);
    }
    void fixedWindow(ImVec2 pos, ImVec2 size) {
        ImGui::SetNextWindowPos(pos);
        ImGui::SetNextWindowSize(size);
        ImGui::Begin("panel", nullptr, kFixed);
    }

    std::unique_ptr<GuiContext> gui_;
};

TEST_F(ImGuiRendererTest, ButtonIsDrawnInItsColourInsideItsRect) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(240, 160));
    ImGui::Button("Go", ImVec2(100, 40));
    const ImVec2 b0 = ImGui::GetItemRectMin(), b1 = ImGui::GetItemRectMax();
    ImGui::End();
    finish();

    ASSERT_NEAR(b1.x - b0.x, 100.f, 0.5f);
    // Corners of the button (clear of its centred label), the panel beside it, and outside.
    for (auto [x, y] : {std::pair{b0.x + 3, b0.y + 3},
                        {b1.x - 4, b0.y + 3},
                        {b0.x + 3, b1.y - 4},
                        {b1.x - 4, b1.y - 4}}) {
        const SDL_Color c = pixel(static_cast<int>(x), static_cast<int>(y));
        EXPECT_TRUE(same(c, kButtonGreen)) << "button at " << x << "," << y << ": " << str(c);
    }
    EXPECT_TRUE(same(pixel(static_cast<int>(b1.x) + 20, static_cast<int>(b0.y) + 5), kPanelBlue));
    EXPECT_TRUE(same(pixel(200, 170), kPanelBlue)) << str(pixel(200, 170));
    EXPECT_TRUE(same(pixel(10, 10), kClear)) << str(pixel(10, 10));
    EXPECT_TRUE(same(pixel(270, 100), kClear)) << str(pixel(270, 100));
    EXPECT_TRUE(same(pixel(100, 190), kClear)) << str(pixel(100, 190));
}

TEST_F(ImGuiRendererTest, TextIsDrawnFromTheFontAtlas) {
    ASSERT_NE(gui_->renderer().fontTexture(), nullptr);
    EXPECT_EQ(ImGui::GetIO().Fonts->TexID, gui_->renderer().fontTexture());
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(240, 160));
    ImGui::Text("Hello, teachers");
    const ImVec2 t0 = ImGui::GetItemRectMin(), t1 = ImGui::GetItemRectMax();
    ImGui::End();
    finish();

    int white = 0, blue = 0;
    for (int y = static_cast<int>(t0.y); y < static_cast<int>(t1.y); ++y) {
        for (int x = static_cast<int>(t0.x); x < static_cast<int>(t1.x); ++x) {
            const SDL_Color c = pixel(x, y);
            white += c.r > 200 && c.g > 200 && c.b > 200;
            blue += same(c, kPanelBlue);
        }
    }
    // Glyphs cover part of the text's box, not all of it: the atlas was sampled, not its
    // white pixel alone.
    const int area = static_cast<int>((t1.x - t0.x) * (t1.y - t0.y));
    EXPECT_GT(white, area / 20) << white << " white of " << area;
    EXPECT_GT(blue, area / 3) << blue << " blue of " << area;
}

TEST_F(ImGuiRendererTest, TranslucentShapesBlendAndOpaqueOnesCover) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(0, 0), ImVec2(kSize, kSize));
    ImDrawList& list = *ImGui::GetWindowDrawList();
    list.AddRectFilled(ImVec2(0, 0), ImVec2(200, 100), IM_COL32(255, 0, 0, 255));
    list.AddRectFilled(ImVec2(50, 0), ImVec2(150, 100), IM_COL32(0, 0, 255, 128));  // half blue
    list.AddRectFilled(ImVec2(50.5f, 50.5f), ImVec2(60.5f, 60.5f),
                       IM_COL32(0, 255, 0, 255));  // off the pixel grid: drawn as triangles
    ImGui::End();
    finish();
    EXPECT_TRUE(same(pixel(20, 20), SDL_Color{255, 0, 0, 255})) << str(pixel(20, 20));
    EXPECT_TRUE(same(pixel(100, 20), SDL_Color{127, 0, 128, 255}, 2)) << str(pixel(100, 20));
    EXPECT_TRUE(same(pixel(55, 55), SDL_Color{0, 255, 0, 255})) << str(pixel(55, 55));
}

TEST_F(ImGuiRendererTest, TextTakesItsColour) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(240, 160));
    ImGui::TextColored(ImVec4(1.f, 1.f, 0.f, 1.f), "Energy kept");
    const ImVec2 t0 = ImGui::GetItemRectMin(), t1 = ImGui::GetItemRectMax();
    ImGui::End();
    finish();
    int yellow = 0, white = 0;
    for (int y = static_cast<int>(t0.y); y < static_cast<int>(t1.y); ++y) {
        for (int x = static_cast<int>(t0.x); x < static_cast<int>(t1.x); ++x) {
            const SDL_Color c = pixel(x, y);
            yellow += c.r > 200 && c.g > 200 && c.b < 60;
            white += c.r > 200 && c.g > 200 && c.b > 200;
        }
    }
    EXPECT_GT(yellow, 30);
    EXPECT_EQ(white, 0);
    Uint8 r = 0, g = 0, b = 0, a = 0;
    SDL_GetTextureColorMod(gui_->renderer().fontTexture(), &r, &g, &b);
    SDL_GetTextureAlphaMod(gui_->renderer().fontTexture(), &a);
    EXPECT_EQ(r + g + b + a, 4 * 255) << "the atlas's colour modulation is put back";
}

TEST_F(ImGuiRendererTest, DrawingStaysInsideTheWindowsClipRect) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(100, 100), ImVec2(100, 100));
    // A red square far larger than the window: ImGui clips it to the window by the command's
    // clip rect, not by cutting the geometry.
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(0, 0), ImVec2(400, 400),
                                              IM_COL32(255, 0, 0, 255));
    // And a nested clip rect: green only inside [120,140]², drawn over [100,200]².
    ImGui::PushClipRect(ImVec2(120, 120), ImVec2(140, 140), true);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(100, 100), ImVec2(200, 200),
                                              IM_COL32(0, 255, 0, 255));
    ImGui::PopClipRect();
    ImGui::End();
    finish();

    const SDL_Color red{255, 0, 0, 255}, green{0, 255, 0, 255};
    EXPECT_TRUE(same(pixel(130, 130), green)) << str(pixel(130, 130));
    EXPECT_TRUE(same(pixel(119, 130), red)) << str(pixel(119, 130));
    EXPECT_TRUE(same(pixel(141, 130), red)) << str(pixel(141, 130));
    EXPECT_TRUE(same(pixel(180, 180), red)) << str(pixel(180, 180));
    for (auto [x, y] :
         {std::pair{99, 150}, {201, 150}, {150, 99}, {150, 201}, {50, 50}, {300, 300}}) {
        EXPECT_TRUE(same(pixel(x, y), kClear))
            << "outside at " << x << "," << y << ": " << str(pixel(x, y));
    }
}

TEST_F(ImGuiRendererTest, PixelScaleDrawsPointsAsSeveralPixels) {
    clear();
    gui_->beginFrame(kSize / 2, kSize / 2, 1.f / 60.f, 2.f);
    fixedWindow(ImVec2(10, 10), ImVec2(150, 100));
    ImGui::Button("Go", ImVec2(60, 30));
    const ImVec2 b0 = ImGui::GetItemRectMin(), b1 = ImGui::GetItemRectMax();
    ImGui::End();
    finish();

    // The button spans [2·b0, 2·b1] pixels: its far corner is green, beyond it is the panel.
    const int x1 = static_cast<int>(2 * b1.x), y1 = static_cast<int>(2 * b1.y);
    EXPECT_TRUE(same(pixel(x1 - 3, y1 - 3), kButtonGreen)) << str(pixel(x1 - 3, y1 - 3));
    EXPECT_TRUE(
        same(pixel(static_cast<int>(2 * b0.x) + 2, static_cast<int>(2 * b0.y) + 2), kButtonGreen));
    EXPECT_TRUE(same(pixel(x1 + 4, y1 - 3), kPanelBlue)) << str(pixel(x1 + 4, y1 - 3));
    // The panel ends at 2 · 160 = 320 pixels, not at 160.
    EXPECT_TRUE(same(pixel(300, 100), kPanelBlue)) << str(pixel(300, 100));
    EXPECT_TRUE(same(pixel(330, 100), kClear)) << str(pixel(330, 100));
}

TEST_F(ImGuiRendererTest, DrawListsBeyondSixteenBitIndicesAreDrawnWhole) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(0, 0), ImVec2(kSize, kSize));
    ImDrawList& list = *ImGui::GetWindowDrawList();
    // 18 000 one-pixel squares (72 000 vertices) on a 150-pixel-wide band; the last one red.
    for (int k = 0; k < 18000; ++k) {
        const float x = static_cast<float>(k % 150), y = static_cast<float>(k / 150);
        list.AddRectFilled(ImVec2(x, y), ImVec2(x + 1, y + 1),
                           k == 17999 ? IM_COL32(255, 0, 0, 255) : IM_COL32(0, 255, 0, 255));
    }
    ImGui::End();
    finish();
    EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, 65536);
    EXPECT_TRUE(same(pixel(149, 119), SDL_Color{255, 0, 0, 255})) << str(pixel(149, 119));
    EXPECT_TRUE(same(pixel(10, 100), SDL_Color{0, 255, 0, 255})) << str(pixel(10, 100));
    EXPECT_TRUE(same(pixel(10, 125), kPanelBlue)) << str(pixel(10, 125));
}

TEST_F(ImGuiRendererTest, ImageShowsTheSdlTextureItNames) {
    SDL_Texture* tex =
        SDL_CreateTexture(sdl_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, 4, 4);
    ASSERT_NE(tex, nullptr) << SDL_GetError();
    std::vector<Uint8> magenta(4 * 4 * 4);
    for (std::size_t i = 0; i < magenta.size(); i += 4) {
        magenta[i] = 255;
        magenta[i + 1] = 0;
        magenta[i + 2] = 255;
        magenta[i + 3] = 255;
    }
    ASSERT_EQ(SDL_UpdateTexture(tex, nullptr, magenta.data(), 16), 0) << SDL_GetError();

    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(200, 200));
    ImGui::Image(tex, ImVec2(64, 64));
    const ImVec2 i0 = ImGui::GetItemRectMin();
    ImGui::End();
    finish();
    SDL_DestroyTexture(tex);

    EXPECT_TRUE(same(pixel(static_cast<int>(i0.x) + 32, static_cast<int>(i0.y) + 32),
                     SDL_Color{255, 0, 255, 255}))
        << str(pixel(static_cast<int>(i0.x) + 32, static_cast<int>(i0.y) + 32));
    EXPECT_TRUE(same(pixel(static_cast<int>(i0.x) + 70, static_cast<int>(i0.y) + 32), kPanelBlue));
}

TEST_F(ImGuiRendererTest, CallersClipRectDrawColourAndBlendModeAreRestored) {
    const SDL_Rect clip{5, 6, 70, 80};
    SDL_RenderSetClipRect(sdl_, &clip);
    SDL_SetRenderDrawColor(sdl_, 1, 2, 3, 4);
    SDL_SetRenderDrawBlendMode(sdl_, SDL_BLENDMODE_ADD);
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(100, 100));
    ImGui::Button("Go");
    ImGui::End();
    finish();
    SDL_Rect after{};
    SDL_RenderGetClipRect(sdl_, &after);
    EXPECT_TRUE(SDL_RenderIsClipEnabled(sdl_));
    EXPECT_EQ(after.x, clip.x);
    EXPECT_EQ(after.y, clip.y);
    EXPECT_EQ(after.w, clip.w);
    EXPECT_EQ(after.h, clip.h);

    Uint8 r = 0, g = 0, b = 0, a = 0;
    SDL_GetRenderDrawColor(sdl_, &r, &g, &b, &a);
    EXPECT_EQ(r, 1);
    EXPECT_EQ(g, 2);
    EXPECT_EQ(b, 3);
    EXPECT_EQ(a, 4);
    SDL_BlendMode mode = SDL_BLENDMODE_NONE;
    SDL_GetRenderDrawBlendMode(sdl_, &mode);
    EXPECT_EQ(mode, SDL_BLENDMODE_ADD);

    SDL_RenderSetClipRect(sdl_, nullptr);
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(20, 20), ImVec2(100, 100));
    ImGui::Button("Go");
    ImGui::End();
    finish();
    EXPECT_FALSE(SDL_RenderIsClipEnabled(sdl_));
}

TEST_F(ImGuiRendererTest, NothingIsDrawnForAnEmptyDisplay) {
    clear();
    gui_->beginFrame(kSize, kSize);
    fixedWindow(ImVec2(0, 0), ImVec2(400, 400));
    ImGui::End();
    ImGui::Render();
    ImDrawData data = *ImGui::GetDrawData();
    data.DisplaySize = ImVec2(0, 0);  // a minimised window
    EXPECT_EQ(gui_->renderer().render(data), 0);
    SDL_RenderPresent(sdl_);
    EXPECT_TRUE(same(pixel(200, 200), kClear));
}

}  // namespace
}  // namespace psb::app
