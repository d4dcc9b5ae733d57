// The ImGui holder without a window: input fed through io(), frames drawn offscreen.

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

#include <imgui.h>

#include "gui/gui_context.hpp"
#include "platform/assets.hpp"
#include "render/offscreen_test.hpp"
#include "view/palette.hpp"

namespace psb::app {
namespace {

constexpr int kSize = 300;

class GuiContextTest : public OffscreenTest {
  protected:
    GuiContextTest() : OffscreenTest(kSize) {}

    /// One frame with a "Play" button at a fixed place; returns whether it was clicked.
    bool frame(GuiContext& gui) {
        gui.beginFrame(kSize, kSize);
        ImGui::SetNextWindowPos(ImVec2(20, 20));
        ImGui::SetNextWindowSize(ImVec2(150, 100));
        ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoSavedSettings);
        const bool clicked = ImGui::Button("Play", ImVec2(80, 30));
        button0_ = ImGui::GetItemRectMin();
        button1_ = ImGui::GetItemRectMax();
        ImGui::End();
        EXPECT_EQ(gui.endFrame(), 0);
        return clicked;
    }
    /// A mouse event of `type` at window point (x, y): the left button, one wheel notch down.
    static SDL_Event mouse(Uint32 type, int x, int y) {
        SDL_Event e{};
        e.type = type;
        if (type == SDL_MOUSEMOTION) {
            e.motion.x = x;
            e.motion.y = y;
        } else if (type == SDL_MOUSEWHEEL) {
            e.wheel.y = -1;
            e.wheel.preciseY = -1.f;
            e.wheel.mouseX = x;
            e.wheel.mouseY = y;
        } else {
            e.button.button = SDL_BUTTON_LEFT;
            e.button.x = x;
            e.button.y = y;
        }
        return e;
    }
    static SDL_Event mouseButton(Uint32 type, int x = 0, int y = 0) { return mouse(type, x, y); }
    static SDL_Event motion(int x, int y) { return mouse(SDL_MOUSEMOTION, x, y); }
    static SDL_Event wheel(int x, int y) { return mouse(SDL_MOUSEWHEEL, x, y); }

    ImVec2 button0_, button1_;
};

TEST_F(GuiContextTest, PressAndReleaseOverAButtonClicksItOnce) {
    GuiContext gui(sdl_);
    frame(gui);
    const ImVec2 centre((button0_.x + button1_.x) / 2, (button0_.y + button1_.y) / 2);
    ImGuiIO& io = gui.io();
    io.MousePos = centre;
    EXPECT_FALSE(frame(gui));
    io.MouseDown[0] = true;
    EXPECT_FALSE(frame(gui));
    io.MouseDown[0] = false;
    EXPECT_TRUE(frame(gui));
    EXPECT_FALSE(frame(gui));
}

TEST_F(GuiContextTest, ClicksOverAPanelAreTakenAndClicksElsewhereAreNot) {
    GuiContext gui(sdl_);
    ImGuiIO& io = gui.io();
    io.MousePos = ImVec2(60, 60);  // over the panel
    frame(gui);
    frame(gui);
    EXPECT_TRUE(gui.wantsMouse());
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 60, 60)));
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONUP, 60, 60)));

    io.MousePos = ImVec2(250, 250);  // over the box, away from the panel
    frame(gui);
    EXPECT_FALSE(gui.wantsMouse());
    EXPECT_FALSE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 250, 250)));
    SDL_Event key{};
    key.type = SDL_KEYDOWN;
    key.key.keysym.sym = SDLK_SPACE;
    EXPECT_FALSE(gui.handleEvent(key)) << "keys reach the app while no text field is active";
    SDL_Event quit{};
    quit.type = SDL_QUIT;
    EXPECT_FALSE(gui.handleEvent(quit));
}

TEST_F(GuiContextTest, AFirstClickAfterThePointerEntersAPanelIsThePanels) {
    // The pointer was over the box in the last frame; it moves onto the panel and presses
    // before another frame is drawn (a quick hand, a loaded machine): ImGui's capture flag is
    // still the box's, the press and its release are the panel's all the same.
    GuiContext gui(sdl_);
    gui.io().MousePos = ImVec2(250, 250);
    frame(gui);
    frame(gui);
    ASSERT_FALSE(gui.wantsMouse());
    EXPECT_FALSE(gui.handleEvent(motion(60, 60)));
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 60, 60)));
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONUP, 60, 60)));
    // A press on the box is the world's, and so is its release over the panel.
    EXPECT_FALSE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 250, 250)));
    EXPECT_FALSE(gui.handleEvent(motion(60, 60)));
    EXPECT_FALSE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONUP, 60, 60)));
}

TEST_F(GuiContextTest, AClickOnTheBoxRightAfterThePanelIsTheBoxs) {
    // The pointer was on the panel in the last frame (a field just typed in, a dialog's button)
    // and goes to a ball and clicks before another frame is drawn: ImGui's capture flag still
    // says the panel's, and the first click on the ball did nothing.
    GuiContext gui(sdl_);
    gui.io().MousePos = ImVec2(60, 60);
    frame(gui);
    frame(gui);
    ASSERT_TRUE(gui.wantsMouse());
    EXPECT_FALSE(gui.handleEvent(motion(250, 250)));
    EXPECT_FALSE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 250, 250)));
    EXPECT_FALSE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONUP, 250, 250)));
    // A press on the panel, let go over the box: the release is the panel's, as its press.
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONDOWN, 60, 60)));
    EXPECT_TRUE(gui.handleEvent(motion(250, 250)));
    EXPECT_TRUE(gui.handleEvent(mouseButton(SDL_MOUSEBUTTONUP, 250, 250)));
    EXPECT_FALSE(gui.handleEvent(motion(260, 260)));
}

TEST_F(GuiContextTest, AWheelTurnOverAPanelIsThePanelsEvenAsThePointerArrives) {
    GuiContext gui(sdl_);
    gui.io().MousePos = ImVec2(250, 250);
    frame(gui);
    frame(gui);
    EXPECT_FALSE(gui.handleEvent(wheel(250, 250))) << "over the box the wheel zooms";
    EXPECT_TRUE(gui.handleEvent(wheel(60, 60))) << "over the panel it is the panel's";
}

TEST_F(GuiContextTest, KeysGoToATextFieldBeingTypedIn) {
    GuiContext gui(sdl_);
    char path[64] = "scene.json";
    ImVec2 field;
    const auto frameWithField = [&] {
        gui.beginFrame(kSize, kSize);
        ImGui::SetNextWindowPos(ImVec2(20, 20));
        ImGui::SetNextWindowSize(ImVec2(200, 80));
        ImGui::Begin("Save", nullptr, ImGuiWindowFlags_NoSavedSettings);
        ImGui::InputText("path", path, sizeof path);
        field = ImVec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) / 2 - 30,
                       (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) / 2);
        ImGui::End();
        EXPECT_EQ(gui.endFrame(), 0);
    };
    frameWithField();
    SDL_Event key{};
    key.type = SDL_KEYDOWN;
    key.key.keysym.sym = SDLK_r;
    EXPECT_FALSE(gui.handleEvent(key)) << "R resets the scene while nothing is being typed";
    ImGuiIO& io = gui.io();
    io.MousePos = field;
    frameWithField();
    io.MouseDown[0] = true;
    frameWithField();
    io.MouseDown[0] = false;
    frameWithField();
    frameWithField();
    EXPECT_TRUE(gui.wantsKeyboard());
    EXPECT_TRUE(gui.handleEvent(key)) << "R is a letter of the file name being typed";
    SDL_Event text{};
    text.type = SDL_TEXTINPUT;
    text.text.text[0] = 'r';
    EXPECT_TRUE(gui.handleEvent(text));
}

TEST_F(GuiContextTest, TwoContextsKeepTheirOwnState) {
    GuiContext a(sdl_);
    GuiContext b(sdl_);
    a.io().MousePos = ImVec2(60, 60);
    b.io().MousePos = ImVec2(250, 250);
    frame(a);
    frame(b);
    frame(a);
    frame(b);
    EXPECT_TRUE(a.wantsMouse());
    EXPECT_FALSE(b.wantsMouse());
}

TEST_F(GuiContextTest, LoadsTheAppsFontAndNamesAMissingOne) {
    GuiOptions options;
    options.font = findAsset("fonts/DejaVuSans.ttf");
    options.fontPixels = 18.f;
    GuiContext gui(sdl_, options);
    ASSERT_EQ(gui.io().Fonts->Fonts.Size, 1);
    EXPECT_FLOAT_EQ(gui.io().Fonts->Fonts[0]->FontSize, 18.f);
    EXPECT_NE(gui.renderer().fontTexture(), nullptr);
    frame(gui);

    options.font = "no/such/font.ttf";
    try {
        GuiContext missing(sdl_, options);
        FAIL() << "a missing font was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("no/such/font.ttf"), std::string::npos) << e.what();
    }
    // The failed holder left nothing current; the first still works.
    frame(gui);
}

TEST_F(GuiContextTest, AScaleOrThemeAskedForWithinAFrameTakesEffectAtTheNext) {
    // A control of the panel (UI scale, theme) acts while its frame is being built, when ImGui
    // has locked the font atlas; a new atlas then aborted the program (ImFontAtlas::
    // ClearInputData's assertion, found by random input on the window).
    GuiOptions options;
    options.font = findAsset("fonts/DejaVuSans.ttf");
    GuiContext gui(sdl_, options);
    gui.beginFrame(kSize, kSize);
    ImGui::Begin("Controls");
    gui.setScale(2.f);
    gui.setTheme(Theme::Light);
    EXPECT_FLOAT_EQ(gui.scale(), 1.f) << "this frame is drawn at the scale it began with";
    ImGui::End();
    EXPECT_EQ(gui.endFrame(), 0);
    const ImVec4 darkText = ImGui::GetStyle().Colors[ImGuiCol_Text];
    gui.beginFrame(kSize, kSize);
    EXPECT_FLOAT_EQ(gui.scale(), 2.f);
    EXPECT_FLOAT_EQ(gui.io().Fonts->Fonts[0]->FontSize, 2.f * options.fontPixels);
    EXPECT_NE(ImGui::GetStyle().Colors[ImGuiCol_Text].x, darkText.x) << "the light theme's text";
    EXPECT_EQ(gui.endFrame(), 0);
    EXPECT_FALSE(gui.takeProblem());
}

TEST_F(GuiContextTest, ASlidersDigitsReadOverItsHandleInBothThemes) {
    // The value is written over the handle; an opaque blue handle hid the digit under it.
    GuiContext gui(sdl_);
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        gui.setTheme(theme);
        const ImGuiStyle& style = ImGui::GetStyle();
        const auto over = [](ImVec4 top, ImVec4 under) {
            const auto mix = [&](float a, float b) {
                return static_cast<std::uint8_t>(255.f * (top.w * a + (1.f - top.w) * b) + 0.5f);
            };
            return Rgba{mix(top.x, under.x), mix(top.y, under.y), mix(top.z, under.z), 255};
        };
        const ImVec4 window = style.Colors[ImGuiCol_WindowBg];
        const Rgba frame = over(style.Colors[ImGuiCol_FrameBg], window);
        const ImVec4 frameOpaque(frame.r / 255.f, frame.g / 255.f, frame.b / 255.f, 1.f);
        const Rgba handle = over(style.Colors[ImGuiCol_SliderGrabActive], frameOpaque);
        const Rgba text = over(style.Colors[ImGuiCol_Text], ImVec4(0, 0, 0, 1));
        EXPECT_GE(contrastRatio(text, handle), 4.5) << (theme == Theme::Light ? "light" : "dark");
    }
}

TEST_F(GuiContextTest, DialogsAreOpaqueOverTheBoxInBothThemes) {
    // A modal dialog (quit, new scene, save) drawn over a red box: its background is its own
    // colour, not mixed with the red under it (ImGui's popups are 94 % and 98 % opaque).
    GuiContext gui(sdl_);
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        const char* name = theme == Theme::Light ? "light" : "dark";
        gui.setTheme(theme);
        EXPECT_FLOAT_EQ(ImGui::GetStyle().Colors[ImGuiCol_PopupBg].w, 1.f) << name;
        for (int k = 0; k < 3; ++k) {
            SDL_SetRenderDrawColor(sdl_, 255, 0, 0, 255);
            SDL_RenderClear(sdl_);
            gui.beginFrame(kSize, kSize);
            if (k == 0) ImGui::OpenPopup("Quit");
            ImGui::SetNextWindowPos(ImVec2(50, 50));
            ImGui::SetNextWindowSize(ImVec2(200, 200));
            if (ImGui::BeginPopupModal("Quit", nullptr, ImGuiWindowFlags_NoTitleBar)) {
                ImGui::EndPopup();
            }
            EXPECT_EQ(gui.endFrame(), 0);
            SDL_RenderPresent(sdl_);
        }
        const SDL_Color inside = pixel(150, 200);
        const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_PopupBg];
        EXPECT_NEAR(inside.r, 255.f * bg.x, 2.0) << name << ": red shows through";
        EXPECT_NEAR(inside.g, 255.f * bg.y, 2.0) << name;
        EXPECT_NEAR(inside.b, 255.f * bg.z, 2.0) << name;
        ImGui::CloseCurrentPopup();
    }
}

TEST_F(GuiContextTest, ADialogsTitleBarLineRunsItsFullWidth) {
    // The light theme's line under a dialog's title (New scene) at 200 % stopped halfway across
    // it: ImGui's textured lines want a bilinear-filtered atlas, which this renderer does not
    // sample: lines are geometry. (The pixels below did not show the half line in this small
    // window; the app's 920-pixel dialog did.) The line is as dark at the right end as at the
    // left.
    GuiContext gui(sdl_);
    for (const Theme theme : {Theme::Dark, Theme::Light}) {
        gui.setTheme(theme);
        EXPECT_FALSE(ImGui::GetStyle().AntiAliasedLinesUseTex) << "textured lines";
    }
    gui.setScale(2.f);  // the projector's 200 %: 2 pixels a point
    for (int k = 0; k < 3; ++k) {
        SDL_SetRenderDrawColor(sdl_, 255, 255, 255, 255);
        SDL_RenderClear(sdl_);
        gui.beginFrame(kSize, kSize);
        if (k == 0) ImGui::OpenPopup("New scene");
        ImGui::SetNextWindowPos(ImVec2(10, 20));
        ImGui::SetNextWindowSize(ImVec2(kSize / 2 - 20, 80));
        if (ImGui::BeginPopupModal("New scene")) ImGui::EndPopup();
        EXPECT_EQ(gui.endFrame(), 0);
        SDL_RenderPresent(sdl_);
    }
    const int line = 2 * (20 + static_cast<int>(ImGui::GetFrameHeight()));  // pixels
    const auto darkness = [&](int x) {
        int most = 0;  // over the rows about the title bar's bottom
        for (int y = line - 4; y <= line + 2; ++y) {
            const SDL_Color c = pixel(x, y);
            most = std::max(most, 255 - (c.r + c.g + c.b) / 3);
        }
        return most;
    };
    const int left = darkness(30), right = darkness(kSize - 30);
    EXPECT_GT(left, 60) << "a line under the title";
    EXPECT_NEAR(right, left, 20) << "the line stops short of the right end";
    ImGui::CloseCurrentPopup();
}

TEST_F(GuiContextTest, AFrameWithoutAWindowNeedsASize) {
    GuiContext gui(sdl_);
    EXPECT_THROW(gui.beginFrame(), std::logic_error);
}

}  // namespace
}  // namespace psb::app
