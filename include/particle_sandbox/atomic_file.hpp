#pragma once
/// \file
/// Replacing a file so that readers see either the old contents or the new, never a mixture.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <particle_sandbox/scene.hpp>

namespace psb {

/// Writes `contents` to `path` atomically: a temporary file in the same directory, written,
/// flushed and fsync'ed, then renamed over `path` (and the directory fsync'ed). On any failure
/// the temporary file is removed, the file that was at `path` is left as it was, and SaveError
/// (declared in scene.hpp) is thrown naming the path and the reason.
///
/// A `path` that exists and is neither a regular file nor a directory (a device such as
/// /dev/null, a named pipe, /dev/stdout) is written in place instead: there is no file to
/// replace, and renaming over it would put a regular file where the device was.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

/// Why writeFileAtomically(path, ...) would fail before writing anything, or nullopt when it
/// would not: the reason is the text its SaveError gives after "cannot save PATH: " (the
/// directory does not exist or is not a directory, a directory is in the way, no file can be
/// created in the directory, a device cannot be opened for writing). Whether a file can be
/// created is found by creating one and removing it at once (unnamed where the file system
/// allows), so permissions, read-only mounts and ACLs all count; nothing that exists is
/// touched. A failure that comes only with the data (a full disk) is not foreseen.
[[nodiscard]] std::optional<std::string> atomicWriteProblem(const std::filesystem::path& path);

}  // namespace psb
