#pragma once
/// \file
/// Scenes built in code, so that the app can open without any file, and the list of the preset
/// files shipped in assets/scenes/.

#include <filesystem>
#include <vector>

#include <particle_sandbox/scene.hpp>

namespace psb {

/// The original program's opening scene, fixed, at 1 pixel = 1 cm: a 7 m × 7 m box with walls,
/// no gravity, e = 1, and a handful of particles of 3..20 kg with radius 2.5 cm/kg × mass,
/// speeds up to 3 m/s (the original's ±5 px per frame at 60 frames per second), placed without
/// overlaps. Always the same scene; assets/scenes/01-original.json holds the same particles.
[[nodiscard]] Scene defaultScene();

/// The scene files (`*.json`) directly inside `directory`, sorted by file name, so that the
/// number prefixes of the presets (01-..., 02-...) give their order. Empty when the directory
/// does not exist or cannot be read; never throws.
[[nodiscard]] std::vector<std::filesystem::path> sceneFiles(const std::filesystem::path& directory);

}  // namespace psb
