#pragma once
/// \file
/// What a scene says of itself beside its world: its name and description, the frame length
/// it is stepped by, which particles' trails show, and the bins it counts. The one record of
/// these facts: a Scene is one (scene.hpp), and the app keeps the scene it shows as one.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/bins.hpp>

namespace psb {

struct SceneInfo {
    // Initialised, so that SceneInfo{"name"} names only what it gives.
    std::string name = {};
    std::string description = {};
    /// Indices into the scene's particles of those whose trail shows from the start (a
    /// particle's "trail": true), ascending. A property of the view: the world does not keep it.
    std::vector<std::size_t> trails = {};
    /// The board's bins and what they should hold (a Galton board's), if the scene says: a
    /// measurement the runner reports and the app draws. The world does not keep it.
    std::optional<Bins> bins = {};
    /// The frame length, seconds, finite and > 0: how far each World::step of this scene goes,
    /// the `dt` the app and particle-sim pass to it (`world.step(scene.dt)`). The file keeps it
    /// in its solver block, `"solver": {"dt": ...}` (this default where it does not); the world
    /// keeps no copy.
    double dt = 0.01;
};

}  // namespace psb
