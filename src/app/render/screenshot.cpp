#include "render/screenshot.hpp"

#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <stb_image_write.h>

#include <particle_sandbox/atomic_file.hpp>

namespace psb::app {

void readPixels(SDL_Renderer* renderer, const SDL_Rect& area, std::uint8_t* rgba) {
    if (SDL_RenderReadPixels(renderer, &area, SDL_PIXELFORMAT_RGBA32, rgba, area.w * 4) != 0) {
        throw std::runtime_error(std::string("cannot read the window's pixels: ") + SDL_GetError());
    }
    const std::size_t bytes =
        static_cast<std::size_t>(area.w) * static_cast<std::size_t>(area.h) * 4;
    for (std::size_t i = 3; i < bytes; i += 4)
        rgba[i] = 255;
}

std::string capturePng(SDL_Renderer* renderer) {
    int w = 0, h = 0;
    if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0 || w <= 0 || h <= 0) {
        throw std::runtime_error(std::string("cannot read the window size: ") + SDL_GetError());
    }
    // RGBA32 is R, G, B, A in memory order whatever the endianness: the layout stb wants.
    std::vector<unsigned char> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                                      4);
    if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGBA32, pixels.data(), w * 4) !=
        0) {
        throw std::runtime_error(std::string("cannot read the window's pixels: ") + SDL_GetError());
    }
    // The window is opaque; whatever alpha the target keeps, the file should not be see-through.
    for (std::size_t i = 3; i < pixels.size(); i += 4)
        pixels[i] = 255;
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
    };
    if (stbi_write_png_to_func(append, &png, w, h, 4, pixels.data(), w * 4) == 0) {
        throw std::runtime_error("cannot encode the PNG image");
    }
    return png;
}

std::filesystem::path screenshotPath(const std::filesystem::path& dir, const std::tm& when,
                                     const std::string& extension) {
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &when);
    const std::string base = std::string("particle-sandbox-") + stamp;
    std::filesystem::path p = dir / (base + extension);
    const auto taken = [](const std::filesystem::path& q) {
        std::error_code ec;
        return std::filesystem::exists(q, ec) ||
               std::filesystem::exists(std::filesystem::path(q.string() + ".part"), ec);
    };
    for (int k = 2; taken(p); ++k)
        p = dir / (base + "-" + std::to_string(k) + extension);
    return p;
}

std::filesystem::path saveScreenshot(SDL_Renderer* renderer, const std::filesystem::path& dir) {
    const std::string png = capturePng(renderer);
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    const std::filesystem::path path = screenshotPath(dir, local);
    writeFileAtomically(path, png);
    return path;
}

}  // namespace psb::app
