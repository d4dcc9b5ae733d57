#pragma once
// What the programs say about themselves: the project's version (CMake's project() version)
// and, when built from a git checkout, the revision it was built from.

#include <string>
#include <string_view>

namespace psb {

/// The project version, e.g. "0.1.0".
[[nodiscard]] std::string_view projectVersion();

/// The git revision the build was made from, 12 hex digits, with "-dirty" when tracked files
/// had uncommitted changes; empty when not built from a git checkout.
[[nodiscard]] std::string_view gitRevision();

/// The --version text: "PROGRAM 0.1.0 (git 1a2b3c4d5e6f)", without the revision part when
/// gitRevision() is empty. No trailing newline.
[[nodiscard]] std::string versionLine(std::string_view program);

}  // namespace psb
