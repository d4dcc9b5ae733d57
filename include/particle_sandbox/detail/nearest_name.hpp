#pragma once
// Suggesting what the user probably meant: the nearest of a list of known names. Shared by the
// scene reader (unknown keys and names) and the programs' command lines (unknown options).

#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

namespace psb::detail {

/// Levenshtein distance (insertions, deletions, substitutions; each costs 1).
[[nodiscard]] std::size_t editDistance(std::string_view a, std::string_view b);

/// The known name nearest `got` when it is close (suggestion()'s rule), else empty.
[[nodiscard]] std::string_view nearestName(std::string_view got,
                                           std::span<const std::string_view> known);

/// " (did you mean 'x'?)" for the nearest known name when it is close (at most a third of the
/// longer name's letters changed, and at least 1 allowed), else " (expected one of: a, b, c)".
[[nodiscard]] std::string suggestion(std::string_view got,
                                     std::initializer_list<std::string_view> known);

}  // namespace psb::detail
