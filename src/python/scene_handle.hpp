#pragma once
// A scene as Python holds it: the core's Scene and, when it came from a file or a text, that
// text and the overrides applied to it (a sweep over seeds regenerates particles from it).

#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

namespace psb::python {

struct PyScene : Scene {
    /// Where it came from, for messages ("gas.json", "<string>", "<world>").
    std::string source = "<scene>";
    /// The JSON text it was parsed from, before its generate blocks were expanded.
    std::optional<std::string> text;
    /// The overrides applied to `text` when it was read.
    std::vector<SceneOverride> overrides;
};

/// Checks `scene` as a scene file is checked (serialised and read back), so that a value set
/// from Python is refused with the file's message, e.g. "<scene>: particles[3].mass: must be
/// > 0 (got -1)". Throws SceneError.
void checkScene(const PyScene& scene);

}  // namespace psb::python
