#pragma once
// F12: the window as a PNG file. The pixels are read back from the renderer with
// SDL_RenderReadPixels (after drawing, before SDL_RenderPresent, when the back buffer still
// holds the frame), encoded with stb_image_write and written atomically (psb::writeFileAtomically),
// so a failed write names the reason and leaves no half-written file.

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <string>

#include <SDL.h>

namespace psb::app {

/// Reads the `area` of `renderer`'s current target into `rgba` (area.w × area.h × 4 bytes, R,
/// G, B, A in memory order, alpha made opaque): a frame for a video. Throws std::runtime_error
/// with SDL's reason when the pixels cannot be read.
void readPixels(SDL_Renderer* renderer, const SDL_Rect& area, std::uint8_t* rgba);

/// The PNG image (file bytes) of everything drawn on `renderer`'s current target. Throws
/// std::runtime_error with SDL's reason when the pixels cannot be read.
[[nodiscard]] std::string capturePng(SDL_Renderer* renderer);

/// `dir`/particle-sandbox-YYYYMMDD-HHMMSS`extension` for the local time `when`; when that file
/// (or a video's part file, NAME.part) exists, the first free of ...-2, ...-3, ...
[[nodiscard]] std::filesystem::path screenshotPath(const std::filesystem::path& dir,
                                                   const std::tm& when,
                                                   const std::string& extension = ".png");

/// Captures `renderer` and writes it to a new screenshotPath in `dir`; returns the path.
/// Throws std::runtime_error (psb::SaveError for the write) saying why it failed.
std::filesystem::path saveScreenshot(SDL_Renderer* renderer, const std::filesystem::path& dir);

}  // namespace psb::app
