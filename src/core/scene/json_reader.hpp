#pragma once
// Parsing untrusted JSON text into a DOM, with errors a person can act on.
//
// nlohmann's own DOM parser reports a syntax error with a byte offset and a number that
// overflows a double without any position; it silently keeps the last of two equal keys and
// accepts any nesting depth. This reader runs nlohmann's SAX parser with a handler that builds
// the same DOM but tracks the JSON path of the value being read, so that every error names
// the line, the column and the path, refuses duplicate keys, and stops at kMaxSceneNesting.

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace psb::detail {

/// 1-based line and column of the byte at `offset` (0-based) in `text`; columns count bytes.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
[[nodiscard]] TextPosition positionOf(std::string_view text, std::size_t offset);

/// Parses `text`; throws SceneError whose message starts with `source`.
[[nodiscard]] nlohmann::json readJson(std::string_view text, std::string_view source);

}  // namespace psb::detail
