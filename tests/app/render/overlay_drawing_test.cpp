// The HUD while a video records, drawn offscreen (render/overlay_drawing.hpp): the video's HUD
// goes into the frame, the screen's is drawn over it once the frame is taken, and nothing of
// the video's shows beside it.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include <SDL.h>

#include "render/offscreen_test.hpp"
#include "render/overlay_drawing.hpp"
#include "view/overlays.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

class RecordedHudTest : public OffscreenTest {
  protected:
    RecordedHudTest() : OffscreenTest(800) {}
};

TEST_F(RecordedHudTest, TheScreensHudCoversTheVideosWhole) {
    // A past frame recorded: the video's first line names how far back it is and is longer
    // than the screen's, whose HUD (opaque, drawn after the frame is taken) was only as wide
    // as its own lines: the end of the video's first line ("...| PAUSED") showed beside it.
    Overlays o;
    o.hud = {"Time 2.88 s | x1 | 2 particles | PAUSED", "Viewing 0.02 s back: Space continues"};
    o.hudRecorded = {"Time 2.88 s (0.02 s back) | x1 | 2 particles | PAUSED", "Kinetic energy"};
    o.messagesAfterCapture = true;
    PanelLayout layout;
    const PixelPoint screen = textBoxSize(*font_, o.hud),
                     video = textBoxSize(*font_, o.hudRecorded);
    ASSERT_GT(video.x, screen.x + 20);
    layout.hud = {10, 10, video.x, std::max(screen.y, video.y)};
    SDL_SetRenderDrawColor(sdl_, 0, 0, 0, 255);
    SDL_RenderClear(sdl_);
    const Palette& colours = palette(Theme::Light);
    drawOverlays(sdl_, *font_, o, layout, colours);  // the frame, as the video takes it
    drawMessages(sdl_, *font_, o, layout, colours);  // then the screen's HUD over it
    SDL_RenderPresent(sdl_);
    // Right of the screen's lines, within the video's first line: the panel alone, no text.
    std::set<std::tuple<int, int, int>> seen;
    for (int y = layout.hud.y + 2; y < layout.hud.y + font_->lineHeight(); ++y) {
        for (int x = layout.hud.x + screen.x + 2; x < layout.hud.x + video.x - 2; ++x) {
            const SDL_Color c = pixel(x, y);
            seen.insert({c.r, c.g, c.b});
        }
    }
    EXPECT_EQ(seen.size(), 1u) << "the video's first line shows beside the screen's HUD";
}

TEST_F(RecordedHudTest, TheHelpCoversTheWholeWindowAndStaysOutOfTheVideo) {
    // The help (H) was as wide as its lines: the charts and the legend showed in a strip at its
    // right. And it went into the video, which holds no key hints.
    Overlays o;
    o.showHelp = true;
    o.help = {"Controls", "", "Space   pause / play"};
    o.helpAt = {8, 8};
    PanelLayout layout;
    const Palette& colours = palette(Theme::Light);
    const auto frame = [&](bool recording) {
        o.messagesAfterCapture = recording;
        SDL_SetRenderDrawColor(sdl_, 255, 0, 0, 255);  // the charts and legend, in red
        SDL_RenderClear(sdl_);
        drawOverlays(sdl_, *font_, o, layout, colours);
    };
    const auto redLeft = [&] {
        int red = 0;
        for (int y = 0; y < 800; y += 7)
            for (int x = 0; x < 800; x += 7) {
                const SDL_Color c = pixel(x, y);
                red += c.r == 255 && c.g == 0 && c.b == 0 ? 1 : 0;
            }
        return red;
    };
    frame(false);
    SDL_RenderPresent(sdl_);
    EXPECT_EQ(redLeft(), 0) << "something under the help shows";
    frame(true);  // the video's frame: no help in it
    SDL_RenderPresent(sdl_);
    EXPECT_GT(redLeft(), 10000) << "the help is in the video's frame";
    drawMessages(sdl_, *font_, o, layout, colours);  // once the frame is taken
    SDL_RenderPresent(sdl_);
    EXPECT_EQ(redLeft(), 0) << "the help on the screen";
}

}  // namespace
}  // namespace psb::app
