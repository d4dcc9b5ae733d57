#pragma once
/// \file
/// Replacing a file so that readers see either the old contents or the new, never a mixture.

#include <filesystem>
#include <string_view>

#include <particle_sandbox/scene.hpp>

namespace psb {

/// Writes `contents` to `path` atomically: a temporary file in the same directory, written,
/// flushed and fsync'ed, then renamed over `path` (and the directory fsync'ed). On any failure
/// the temporary file is removed, the file that was at `path` is left as it was, and SaveError
/// (declared in scene.hpp) is thrown naming the path and the reason.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace psb
