#include "scene/scene_overrides.hpp"

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "scene/json_values.hpp"
#include "support/printable.hpp"

namespace psb::detail {
namespace {

/// A path's steps: a key of an object, or an index into an array.
using Step = std::variant<std::string, std::size_t>;

/// Paths longer than this are refused: no scene key comes near it.
constexpr std::size_t kMaxPathLength = 1024;

std::vector<Step> steps(const std::string& path, const auto& fail) {
    if (path.empty()) fail("an empty path (say which value: world.restitution)");
    if (path.size() > kMaxPathLength) fail("a path longer than 1024 characters");
    std::vector<Step> out;
    std::size_t i = 0;
    while (i < path.size()) {
        if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            if (out.empty() || close == std::string::npos || close == i + 1) {
                fail("an index must follow a key, as in particles[3]");
            }
            std::size_t index = 0;
            for (std::size_t k = i + 1; k < close; ++k) {
                if (path[k] < '0' || path[k] > '9' || index > kMaxSceneParticles) {
                    fail("an index is a whole number, as in particles[3]");
                }
                index = index * 10 + static_cast<std::size_t>(path[k] - '0');
            }
            out.emplace_back(index);
            i = close + 1;
            if (i < path.size() && path[i] != '.' && path[i] != '[') {
                fail("a '.' or '[' must follow an index");
            }
            if (i < path.size() && path[i] == '.') ++i;
            continue;
        }
        const std::size_t end = path.find_first_of(".[", i);
        const std::string key = path.substr(i, end == std::string::npos ? end : end - i);
        if (key.empty()) fail("an empty key (two dots, or a dot at an end)");
        out.emplace_back(key);
        if (end == std::string::npos) break;
        i = path[end] == '.' ? end + 1 : end;
        if (path[end] == '.' && i == path.size()) fail("an empty key (a dot at the end)");
    }
    return out;
}

}  // namespace

void applyOverride(nlohmann::json& root, const SceneOverride& o, std::string_view source) {
    const auto fail = [&](const std::string& problem) {
        throw SceneError(std::string(source) + ": " + printable(o.option) + " " +
                         printable(o.path) + ": " + problem);
    };
    const std::vector<Step> path = steps(o.path, fail);
    nlohmann::json* at = &root;
    std::string where;  // the path so far, for messages
    const auto here = [&] { return where.empty() ? std::string("(root)") : where; };
    for (std::size_t k = 0; k < path.size(); ++k) {
        if (const auto* key = std::get_if<std::string>(&path[k])) {
            // A key into an array of one block (generate.count for a one-block generate list)
            // means that block; into a longer one it must say which.
            if (at->is_array() && at->size() == 1) at = &(*at)[0];
            if (at->is_array()) {
                fail(here() + " is an array of " + std::to_string(at->size()) +
                     " elements: say which, as in " + element(where, 0) + "." + printable(*key));
            }
            if (at->is_null()) {
                if (!o.create) fail(here() + " is not in the scene");
                *at = nlohmann::json::object();
            }
            if (!at->is_object()) {
                fail(here() + " is " + typeName(*at) + ", not an object: it has no key '" +
                     printable(*key) + "'");
            }
            where = member(where, *key);
            at = &(*at)[*key];
        } else {
            const std::size_t index = std::get<std::size_t>(path[k]);
            if (!at->is_array()) {
                fail(here() + (at->is_null() ? std::string(" is not in the scene")
                                             : " is " + typeName(*at) + ", not an array"));
            }
            if (index >= at->size()) {
                fail(here() + " has " + std::to_string(at->size()) + " elements: no index " +
                     std::to_string(index));
            }
            where = element(where, index);
            at = &(*at)[index];
        }
    }
    // JSON text as JSON; anything else (a name with spaces, a word) as a string.
    nlohmann::json value = nlohmann::json::parse(o.value, nullptr, false);
    if (value.is_discarded()) value = o.value;
    *at = std::move(value);
}

}  // namespace psb::detail
