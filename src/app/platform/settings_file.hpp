#pragma once
// The settings the program keeps between runs, as a small JSON file: what is shown (the Show
// section's checkboxes, keys A, S, V, K, D, O, J, I, Q, Shift+G), the UI's scale and the theme,
//   {"version": 1, "show": {"arrows": true, "labels": false, ...},
//    "ui": {"scale": "auto", "theme": "dark"}}
// ("scale" is "auto" or a number, 0.75 to 3). The desktop program keeps it in the user's config
// folder (settings_store.hpp), the web page in the browser's storage (browser_settings.hpp).
//
// Reading is lenient where it can be: a key it does not know is skipped (a newer program's file
// still opens), and a value out of range or of the wrong kind is left out with a problem said;
// only a text that is not a JSON object is refused whole.

#include <string>
#include <vector>

#include "session/command.hpp"
#include "session/view_options.hpp"

namespace psb::app {

/// The options kept, in their file's order.
inline constexpr ShowOption kKeptOptions[] = {
    ShowOption::Arrows, ShowOption::Labels,  ShowOption::Momentum,  ShowOption::Plots,
    ShowOption::Speeds, ShowOption::Profile, ShowOption::Collision, ShowOption::Values,
    ShowOption::Grid,   ShowOption::Spin,    ShowOption::YUp};
// Not kept: the ruler, laid across the middle of each scene's box, would come back lying over
// the next run's particles.

/// `view`'s kept settings as the file's text.
[[nodiscard]] std::string settingsText(const ViewOptions& view);

/// What a settings file asks for.
struct SettingsRead {
    /// The commands that restore the settings over the view they were read against (only those
    /// that differ; a setting the text does not name stays). An automatic scale comes as
    /// SetUiScale{.automatic = true}, its value for the app to fill in.
    std::vector<Command> commands;
    /// What was left out and why ("ui.scale: 5 is outside 0.75 to 3").
    std::vector<std::string> problems;
};

/// The settings in `text` over `view`. Throws std::runtime_error saying what is wrong with a
/// text that is not a JSON object.
[[nodiscard]] SettingsRead readSettings(const std::string& text, const ViewOptions& view);

/// Whether `view`'s kept settings differ from `other`'s (the file would change).
[[nodiscard]] bool keptSettingsDiffer(const ViewOptions& view, const ViewOptions& other);

}  // namespace psb::app
