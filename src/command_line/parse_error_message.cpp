#include "parse_error_message.hpp"

#include <string_view>
#include <vector>

#include <particle_sandbox/detail/nearest_name.hpp>

namespace psb {
namespace {

/// Every spelling of every option of `app`: "--seed", "-d", ...
std::vector<std::string> optionNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options()) {
        for (const std::string& l : o->get_lnames())
            names.push_back("--" + l);
        for (const std::string& s : o->get_snames())
            names.push_back("-" + s);
    }
    return names;
}

std::string unknownOption(const CLI::App& app, const std::string& argument) {
    // "--sed=3" names the option "--sed".
    const std::string name = argument.substr(0, argument.find('='));
    const std::vector<std::string> names = optionNames(app);
    const std::vector<std::string_view> views(names.begin(), names.end());
    const std::string_view nearest = detail::nearestName(name, views);
    std::string message = "unknown option '" + name + "'";
    if (!nearest.empty()) message += " (did you mean '" + std::string(nearest) + "'?)";
    return message;
}

std::string strayArgument(const CLI::App& app, const std::string& argument) {
    std::string taken;
    for (const CLI::Option* o : app.get_options()) {
        if (!o->get_positional() || o->count() == 0) continue;
        taken += (taken.empty() ? "" : ", ") + o->get_name() + " is '" + o->as<std::string>() + "'";
    }
    return "unexpected argument '" + argument + "' (" + (taken.empty() ? "" : taken + "; ") +
           "options start with '-')";
}

}  // namespace

std::string parseErrorMessage(const CLI::App& app, const CLI::ParseError& error) {
    const bool extra = dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr;
    // A misspelt required option ("--duraton 1") leaves the option missing as well: the typo is
    // what to report, not "--duration is required".
    const bool required = dynamic_cast<const CLI::RequiredError*>(&error) != nullptr;
    if (!extra && !required) return error.what();
    // The leftovers in the order given; an unknown option's value follows it, so the first
    // that looks like an option is what went wrong, else the first stray argument.
    const std::vector<std::string> extras = app.remaining();
    for (const std::string& a : extras) {
        if (a.size() > 1 && a[0] == '-') return unknownOption(app, a);
    }
    if (extra && !extras.empty()) return strayArgument(app, extras.front());
    return error.what();
}

}  // namespace psb
