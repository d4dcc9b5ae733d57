#pragma once
// The settings the page keeps between visits (the web build; the desktop program keeps none):
// what is shown (the Show section's checkboxes, keys A, S, V, K, D, O, J, I, Q, Shift+G), as a small JSON
// file,
//   {"version": 1, "show": {"arrows": true, "labels": false, ...}}
// which browser_settings.hpp keeps in the browser's storage.

#include <string>
#include <vector>

#include "session/command.hpp"
#include "session/view_options.hpp"

namespace psb::app {

/// The options kept, in their file's order.
inline constexpr ShowOption kKeptOptions[] = {
    ShowOption::Arrows,    ShowOption::Labels, ShowOption::Momentum,
    ShowOption::Plots,     ShowOption::Speeds, ShowOption::Profile,
    ShowOption::Collision, ShowOption::Values, ShowOption::Ruler,
    ShowOption::Grid,      ShowOption::Spin};

/// `view`'s kept options as the file's text.
[[nodiscard]] std::string settingsText(const ViewOptions& view);
/// The commands that restore the options in `text` over `view` (only those that differ; an
/// option the text does not name stays). Throws std::runtime_error saying what is wrong with a
/// broken text.
[[nodiscard]] std::vector<Command> settingsCommands(const std::string& text,
                                                    const ViewOptions& view);

}  // namespace psb::app
