#pragma once
// Reading typed values out of a JSON DOM (json_reader.hpp) with the path of each in hand: every
// failure is a SceneError naming the source, the path (`particles[3].mass`) and the problem, in
// words a person can act on. The scene's schema (scene_reader.cpp) is written with it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/detail/nearest_name.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/validation.hpp>

#include "support/printable.hpp"

namespace psb::detail {

using json = nlohmann::json;
using Keys = std::initializer_list<std::string_view>;

/// Numbers in messages as the exports write them: the shortest text that reads back as the same
/// double.
[[nodiscard]] inline std::string messageNumber(double v) {
    return csv::number(v);
}

/// "an object", "a string", ...: what a value is, for "expected X, got Y".
[[nodiscard]] inline std::string typeName(const json& j) {
    switch (j.type()) {
        case json::value_t::null:
            return "null";
        case json::value_t::object:
            return "an object";
        case json::value_t::array:
            return "an array";
        case json::value_t::string:
            return "a string";
        case json::value_t::boolean:
            return "a boolean";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
            return "an integer";
        case json::value_t::number_float:
            return "a number";
        default:
            return "an unsupported value";
    }
}

/// The path of `key` in the object at `path`.
[[nodiscard]] inline std::string member(const std::string& path, std::string_view key) {
    // Keys come from the file: a megabyte-long key must not make a megabyte-long message.
    std::string k(key.substr(0, 64));
    if (key.size() > 64) k += "...";
    return path.empty() ? k : path + "." + k;
}

/// The path of element `i` of the array at `path`.
[[nodiscard]] inline std::string element(const std::string& path, std::size_t i) {
    return (path.empty() ? "(root)" : path) + "[" + std::to_string(i) + "]";
}

/// Reads values out of the DOM; every failure becomes a SceneError naming the source and path.
class ValueReader {
  public:
    explicit ValueReader(std::string_view source) : source_(source) {}

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw SceneError(std::string(source_) + ": " +
                         detail::printable((path.empty() ? "(root)" : path) + ": " + problem));
    }

    void expectType(const json& j, const std::string& path, bool ok, const char* want) const {
        if (!ok) fail(path, std::string("expected ") + want + ", got " + typeName(j));
    }

    const json& object(const json& j, const std::string& path, Keys known) const {
        expectType(j, path, j.is_object(), "an object");
        for (const auto& [key, value] : j.items()) {
            if (std::find(known.begin(), known.end(), key) == known.end()) {
                fail(member(path, key), "unknown key" + detail::suggestion(key, known));
            }
        }
        return j;
    }

    static const json* find(const json& obj, std::string_view key) {
        const auto it = obj.find(key);
        return it == obj.end() ? nullptr : &*it;
    }

    const json& require(const json& obj, const std::string& path, std::string_view key) const {
        const json* v = find(obj, key);
        if (!v) fail(member(path, key), "required key is missing");
        return *v;
    }

    /// A finite number of magnitude at most kMaxSceneMagnitude.
    double number(const json& j, const std::string& path) const {
        expectType(j, path, j.is_number(), "a number");
        const double v = j.get<double>();
        if (!std::isfinite(v) || std::abs(v) > kMaxSceneMagnitude) {
            fail(path, "magnitude above " + messageNumber(kMaxSceneMagnitude) + " (got " +
                           messageNumber(v) + ")");
        }
        return v;
    }

    double positive(const json& j, const std::string& path) const {
        const double v = number(j, path);
        if (!(v > 0.0)) fail(path, "must be > 0 (got " + messageNumber(v) + ")");
        return v;
    }

    /// A mass: positive and at least the smallest normal double, so that World can use 1/m.
    double mass(const json& j, const std::string& path) const {
        const double v = positive(j, path);
        if (v < std::numeric_limits<double>::min()) {
            fail(path, "must be at least " + messageNumber(std::numeric_limits<double>::min()) +
                           " (got " + messageNumber(v) + ")");
        }
        return v;
    }

    double nonNegative(const json& j, const std::string& path) const {
        const double v = number(j, path);
        if (v < 0.0) fail(path, "must be >= 0 (got " + messageNumber(v) + ")");
        return v;
    }

    double inRange(const json& j, const std::string& path, double lo, double hi) const {
        const double v = number(j, path);
        if (v < lo || v > hi) {
            fail(path, "must be in [" + messageNumber(lo) + ", " + messageNumber(hi) + "] (got " +
                           messageNumber(v) + ")");
        }
        return v;
    }

    std::int64_t integer(const json& j, const std::string& path, std::int64_t lo,
                         std::int64_t hi) const {
        expectType(j, path, j.is_number_integer(), "an integer");
        if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) {
            fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                           std::to_string(j.get<std::uint64_t>()) + ")");
        }
        const std::int64_t v = j.get<std::int64_t>();
        if (v < lo || v > hi) {
            fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                           std::to_string(v) + ")");
        }
        return v;
    }

    bool boolean(const json& j, const std::string& path) const {
        expectType(j, path, j.is_boolean(), "true or false");
        return j.get<bool>();
    }

    std::string string(const json& j, const std::string& path) const {
        expectType(j, path, j.is_string(), "a string");
        return j.get<std::string>();
    }

    const json& array(const json& j, const std::string& path, std::size_t size,
                      const char* want) const {
        expectType(j, path, j.is_array() && j.size() == size, want);
        return j;
    }

    Vec2 vec2(const json& j, const std::string& path) const {
        if (j.is_array() && j.size() != 2) {
            fail(path,
                 "expected an array of 2 numbers, got " + std::to_string(j.size()) + " elements");
        }
        array(j, path, 2, "an array of 2 numbers");
        return {number(j[0], element(path, 0)), number(j[1], element(path, 1))};
    }

    Color color(const json& j, const std::string& path) const {
        if (j.is_array() && j.size() != 3) {
            fail(path, "expected [r, g, b], got " + std::to_string(j.size()) + " elements");
        }
        array(j, path, 3, "[r, g, b]");
        auto channel = [&](std::size_t i) {
            return static_cast<std::uint8_t>(integer(j[i], element(path, i), 0, 255));
        };
        return Color{channel(0), channel(1), channel(2)};
    }

  private:
    std::string_view source_;
};

}  // namespace psb::detail
