#include "platform/settings_file.hpp"
#include "session/units.hpp"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace psb::app {

namespace {

const char* keyOf(ShowOption option) {
    switch (option) {
        case ShowOption::Arrows:
            return "arrows";
        case ShowOption::Labels:
            return "labels";
        case ShowOption::Momentum:
            return "momentum";
        case ShowOption::Plots:
            return "plots";
        case ShowOption::Speeds:
            return "speeds";
        case ShowOption::Profile:
            return "profile";
        case ShowOption::Bins:
            return "bins";
        case ShowOption::Collision:
            return "collision";
        case ShowOption::Values:
            return "values";
        case ShowOption::Ruler:
            return "ruler";
        case ShowOption::Grid:
            return "grid";
        case ShowOption::Spin:
            return "spin";
        case ShowOption::YUp:
            return "y_up";
    }
    return "";
}

void readUi(const nlohmann::json& ui, const ViewOptions& view, SettingsRead& out) {
    if (const auto it = ui.find("scale"); it != ui.end()) {
        if (it->is_string() && it->get<std::string>() == "auto") {
            if (!view.uiScaleAutomatic)
                out.commands.emplace_back(cmd::SetUiScale{view.uiScale, true});
        } else if (!it->is_number()) {
            out.problems.push_back("ui.scale: expected \"auto\" or a number from " +
                                   plainNumber(kMinUiScale) + " to " + plainNumber(kMaxUiScale));
        } else if (const double s = it->get<double>(); !(s >= kMinUiScale && s <= kMaxUiScale)) {
            out.problems.push_back("ui.scale: " + plainNumber(s) + " is outside " +
                                   plainNumber(kMinUiScale) + " to " + plainNumber(kMaxUiScale));
        } else if (s != view.uiScale || view.uiScaleAutomatic) {
            out.commands.emplace_back(cmd::SetUiScale{s, false});
        }
    }
    if (const auto it = ui.find("theme"); it != ui.end()) {
        const std::string name = it->is_string() ? it->get<std::string>() : std::string();
        if (name != "dark" && name != "light") {
            out.problems.push_back("ui.theme: expected \"dark\" or \"light\"");
        } else {
            const Theme theme = name == "light" ? Theme::Light : Theme::Dark;
            if (theme != view.theme) out.commands.emplace_back(cmd::SetTheme{theme});
        }
    }
}

}  // namespace

std::string settingsText(const ViewOptions& view) {
    nlohmann::ordered_json j;
    j["version"] = 1;
    for (const ShowOption o : kKeptOptions)
        j["show"][keyOf(o)] = view.shown(o);
    if (view.uiScaleAutomatic) {
        j["ui"]["scale"] = "auto";
    } else {
        j["ui"]["scale"] = view.uiScale;
    }
    j["ui"]["theme"] = toString(view.theme);
    return j.dump(2) + "\n";
}

SettingsRead readSettings(const std::string& text, const ViewOptions& view) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error("not JSON: it breaks off or goes wrong at character " +
                                 std::to_string(e.byte));
    }
    if (!j.is_object()) throw std::runtime_error("expected a JSON object, {...}");
    SettingsRead out;
    if (const auto show = j.find("show"); show != j.end()) {
        if (!show->is_object()) {
            out.problems.push_back("show: expected an object, {\"arrows\": true, ...}");
        } else {
            for (const ShowOption o : kKeptOptions) {
                const auto it = show->find(keyOf(o));
                if (it == show->end()) continue;
                if (!it->is_boolean()) {
                    out.problems.push_back(std::string("show.") + keyOf(o) +
                                           ": expected true or false");
                    continue;
                }
                if (it->get<bool>() != view.shown(o)) {
                    out.commands.emplace_back(cmd::SetShow{o, it->get<bool>()});
                }
            }
        }
    }
    if (const auto ui = j.find("ui"); ui != j.end()) {
        if (!ui->is_object()) {
            out.problems.push_back("ui: expected an object, {\"scale\": ..., \"theme\": ...}");
        } else {
            readUi(*ui, view, out);
        }
    }
    return out;
}

bool keptSettingsDiffer(const ViewOptions& view, const ViewOptions& other) {
    for (const ShowOption o : kKeptOptions) {
        if (view.shown(o) != other.shown(o)) return true;
    }
    return view.uiScaleAutomatic != other.uiScaleAutomatic || view.theme != other.theme ||
           (!view.uiScaleAutomatic && view.uiScale != other.uiScale);
}

}  // namespace psb::app
