#pragma once
// Text from a file (a key, a name, a quoted token) made safe to print on a terminal: the one
// escaping rule of every message the core builds from its input.

#include <string>
#include <string_view>

namespace psb::detail {

/// `text` with every byte that could drive a terminal or garble it written as \xHH: the C0
/// controls and DEL, the C1 controls (U+0080 to U+009F, which a UTF-8 terminal obeys), and any
/// byte that is not part of well-formed UTF-8. Well-formed UTF-8 otherwise stays as it is, so a
/// name in any script reads as written.
[[nodiscard]] std::string printable(std::string_view text);

}  // namespace psb::detail
