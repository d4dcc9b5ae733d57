#pragma once
/// \file
/// Particle colour.

#include <cstdint>

namespace psb {

/// An 8-bit RGB colour. The core stores it for the app and for scene files; physics ignores it.
struct Color {
    std::uint8_t r = 255;
    std::uint8_t g = 255;
    std::uint8_t b = 255;
    friend bool operator==(Color a, Color b) = default;
};

}  // namespace psb
