#pragma once
// Suggesting what the user probably meant: the nearest of a list of known names.

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace psb::detail {

/// Levenshtein distance (insertions, deletions, substitutions; each costs 1).
[[nodiscard]] std::size_t editDistance(std::string_view a, std::string_view b);

/// " (did you mean 'x'?)" for the nearest known name when it is close (at most a third of the
/// longer name's letters changed, and at least 1 allowed), else " (expected one of: a, b, c)".
[[nodiscard]] std::string suggestion(std::string_view got,
                                     std::initializer_list<std::string_view> known);

}  // namespace psb::detail
