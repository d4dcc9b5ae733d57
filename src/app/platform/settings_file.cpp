#include "platform/settings_file.hpp"

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
    }
    return "";
}

}  // namespace

std::string settingsText(const ViewOptions& view) {
    nlohmann::ordered_json j;
    j["version"] = 1;
    for (const ShowOption o : kKeptOptions)
        j["show"][keyOf(o)] = view.shown(o);
    return j.dump(2) + "\n";
}

std::vector<Command> settingsCommands(const std::string& text, const ViewOptions& view) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error("not JSON: it breaks off or goes wrong at character " +
                                 std::to_string(e.byte));
    }
    if (!j.is_object() || !j.contains("show") || !j["show"].is_object()) {
        throw std::runtime_error("expected an object with \"show\"");
    }
    std::vector<Command> out;
    for (const ShowOption o : kKeptOptions) {
        const auto it = j["show"].find(keyOf(o));
        if (it == j["show"].end()) continue;
        if (!it->is_boolean()) {
            throw std::runtime_error(std::string("show.") + keyOf(o) + ": expected true or false");
        }
        if (it->get<bool>() != view.shown(o)) out.emplace_back(cmd::SetShow{o, it->get<bool>()});
    }
    return out;
}

}  // namespace psb::app
