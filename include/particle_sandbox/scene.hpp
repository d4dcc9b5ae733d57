#pragma once
/// \file
/// Scene files: a world, how to step it, and its particles, as versioned JSON. The app and the
/// headless runner share this one loader. The format is documented in docs/scenes.md.

#include <cstddef>
#include <filesystem>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/scene_info.hpp>
#include <particle_sandbox/solver_settings.hpp>
#include <particle_sandbox/world.hpp>
#include <particle_sandbox/world_def.hpp>

namespace psb {

/// A scene in memory: everything a scene file says, with any `generate` block already expanded
/// into particles. What it says of itself (name, description, dt, trails, bins) is its
/// SceneInfo (scene_info.hpp).
struct Scene : SceneInfo {
    int version = 1;  ///< as read; written as the lowest version that has what the scene uses
    WorldDef world;
    SolverSettings solver;
    std::vector<ParticleDef> particles;
    /// Accept overlapping particles when loading. A file written by hand should not overlap, so
    /// the loader refuses overlaps by default; a snapshot of a running world may hold the small
    /// overlaps a step leaves behind, so sceneFromWorld sets this when it finds any.
    bool allowOverlaps = false;
    /// The ball droppers and how far each has got (version 4; see World::setDroppers).
    Droppers droppers;
};

/// Limits that keep any input, however hostile, from exhausting memory or time.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{256} << 20;  ///< 256 MiB
inline constexpr std::size_t kMaxSceneParticles = 1'000'000;  ///< listed plus generated
inline constexpr std::size_t kMaxSceneObstacles = 100'000;    ///< pegs plus segments
inline constexpr int kMaxSceneNesting = 64;                   ///< JSON object/array depth
/// Largest magnitude accepted for any physical number in a scene (metres, m/s, kg, m/s²).
inline constexpr double kMaxSceneMagnitude = 1e15;
/// The densest packing fraction a `generate` block and scenes::gas and scenes::brownian accept:
/// π/4 ≈ 0.785, the fraction of the plane a square lattice of touching discs covers. They place
/// discs of one radius on such a lattice (scene_generate.hpp), so π/4 is the physical limit of
/// their placement, approached but never reached in a finite region: a region holds
/// ⌊w / 2r⌋ · ⌊h / 2r⌋ discs (a part in a million less), and a count above that is refused
/// with that number. Discs of mixed radii (scenes::gas) are placed at random and jam far below
/// it (see scenes::gas).
inline constexpr double kMaxPackingFraction = std::numbers::pi / 4.0;

/// A scene that cannot be read or is not valid. what() is one line for the user, naming the
/// file, the JSON path and the problem, e.g.
///   `gas.json: particles[3].mass: must be > 0 (got -1)`.
class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A save that failed (no permission, a directory in the way, disk full, ...). The file that
/// was there before is left intact.
class SaveError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// One change made to a scene file's JSON before it is read, as a sweep asks for it: the value
/// at `path` (keys joined by dots, array elements by index: `world.restitution`,
/// `generate.count`, `generate[1].seed`, `particles[0].velocity`) set to `value`, JSON text
/// (`0.9`, `true`, `[1, 2]`, `"text"`; anything that is not JSON is taken as a string). Missing
/// objects on the way are made; the scene is then checked as a file would be, so a key the
/// format does not know is refused with the nearest known one.
struct SceneOverride {
    std::string path;
    std::string value;
    /// What asked for it, for messages (the runner's option).
    std::string option = "--set";
    /// Make missing objects on the way; false: everything before the last key must be there.
    bool create = true;
};

/// Parses and validates scene JSON, `overrides` applied in order first. `source` names the
/// input in messages (a path or "<stdin>"). Throws SceneError (a path that crosses a value
/// that is not an object or array, or an index past an array's end, included).
[[nodiscard]] Scene parseScene(std::string_view json, std::string_view source,
                               std::span<const SceneOverride> overrides = {});

/// Reads and parses a scene file, `overrides` applied first. Throws SceneError (also for a
/// file that cannot be read).
[[nodiscard]] Scene loadScene(const std::filesystem::path& path,
                              std::span<const SceneOverride> overrides = {});

/// Scene JSON for `scene`; doubles are written so that they read back bit for bit. Throws
/// InvalidArgument if a number is not finite (JSON cannot hold it).
[[nodiscard]] std::string serializeScene(const Scene& scene);

/// Writes `scene` to `path` atomically: a temporary file beside it, flushed, then renamed over
/// the target (see writeFileAtomically in atomic_file.hpp). Throws SaveError saying why
/// (including a non-finite number in the scene); the old file is untouched on failure.
void saveScene(const Scene& scene, const std::filesystem::path& path);

/// A world built from a scene (its box, laws, solver settings, particles and droppers),
/// particles added in the scene's order. The scene's frame length (Scene::dt) is not the
/// world's: step the world by it. Throws InvalidArgument for a scene the world refuses, or a
/// dt not finite and > 0 (parseScene has already checked everything a file can get wrong).
[[nodiscard]] World makeWorld(const Scene& scene);

/// A scene describing the world's current state: its box, laws, solver settings, particles
/// in number order (particleNumber: the scene opens with the numbers they had, less the gaps
/// of removed ones) and droppers (a held particle is saved as a free one), with the frame
/// length `dt` the world is stepped by (the world does not know it). Sets allowOverlaps when
/// some particles overlap, so that the snapshot always loads back.
[[nodiscard]] Scene sceneFromWorld(const World& world, double dt, std::string name = {},
                                   std::string description = {});

}  // namespace psb
