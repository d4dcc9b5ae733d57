#pragma once
// A test fixture that draws with SDL's software renderer into an offscreen surface and reads the
// pixels back: the app's Renderer, a 12 px font and a camera at 1 px/m with the world origin at
// the surface's top-left.

#include <gtest/gtest.h>

#include <memory>

#include <SDL.h>

#include "platform/assets.hpp"
#include "render/renderer.hpp"
#include "render/text.hpp"
#include "session/camera.hpp"

namespace psb::app {

class OffscreenTest : public ::testing::Test {
  protected:
    /// A size × size surface.
    explicit OffscreenTest(int size) : size_(size) {}

    void SetUp() override {
        surface_ = SDL_CreateRGBSurfaceWithFormat(0, size_, size_, 32, SDL_PIXELFORMAT_ARGB8888);
        ASSERT_NE(surface_, nullptr) << SDL_GetError();
        sdl_ = SDL_CreateSoftwareRenderer(surface_);
        ASSERT_NE(sdl_, nullptr) << SDL_GetError();
        font_ = std::make_unique<Font>(sdl_, findAsset("fonts/DejaVuSansMono.ttf"), 12);
        renderer_ = std::make_unique<Renderer>(sdl_, font_.get());
        camera_.setViewport(size_, size_);
        camera_.set(1.0, Vec2::Zero());
    }
    void TearDown() override {
        renderer_.reset();
        font_.reset();
        if (sdl_ != nullptr) SDL_DestroyRenderer(sdl_);
        if (surface_ != nullptr) SDL_FreeSurface(surface_);
    }

    /// The colour of pixel (x, y) as last presented.
    [[nodiscard]] SDL_Color pixel(int x, int y) const {
        const auto* row = static_cast<const Uint8*>(surface_->pixels) + y * surface_->pitch;
        const Uint32 v = reinterpret_cast<const Uint32*>(row)[x];
        SDL_Color c{};
        SDL_GetRGBA(v, surface_->format, &c.r, &c.g, &c.b, &c.a);
        return c;
    }

    int size_;
    SDL_Surface* surface_ = nullptr;
    SDL_Renderer* sdl_ = nullptr;
    std::unique_ptr<Font> font_;
    std::unique_ptr<Renderer> renderer_;
    Camera camera_;
};

}  // namespace psb::app
