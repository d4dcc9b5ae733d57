#pragma once
// Applying SceneOverride (scene.hpp) to a scene file's JSON before the reader checks it: the
// runner's --set and --seed, a sweep's parameters.

#include <string_view>

#include <nlohmann/json.hpp>
#include <particle_sandbox/scene.hpp>

namespace psb::detail {

/// Sets the value at `o.path` in `root`, making missing objects on the way. Throws SceneError
/// starting with `source` and naming the path: a malformed path, a step through a value that
/// is neither an object nor an array, an index past an array's end, a key into an array of more
/// than one element.
void applyOverride(nlohmann::json& root, const SceneOverride& o, std::string_view source);

}  // namespace psb::detail
