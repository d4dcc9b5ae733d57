#include "scene/json_reader.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "support/printable.hpp"

namespace psb::detail {
namespace {

using json = nlohmann::json;
using DomParser = nlohmann::detail::json_sax_dom_parser<json>;

/// One open object or array, for naming the path of the value being read.
struct Frame {
    bool array = false;
    std::size_t next = 0;        // arrays: index of the next element
    std::string key;             // objects: the key just read
    std::set<std::string> keys;  // objects: keys seen so far
    bool inValue = false;        // between a key (or an element's start) and its value's end
};

/// nlohmann's DOM builder plus path tracking. nlohmann::json::sax_parse is a template on the
/// handler type, so the functions below hide (not override) the base's and are called instead.
class TrackingParser : public DomParser {
  public:
    TrackingParser(json& result, std::string_view text, std::string_view source)
        : DomParser(result, /*allow_exceptions=*/false), text_(text), source_(source) {}

    bool null() { return value() && done(DomParser::null()); }
    bool boolean(bool v) { return value() && done(DomParser::boolean(v)); }
    bool number_integer(json::number_integer_t v) {
        return value() && done(DomParser::number_integer(v));
    }
    bool number_unsigned(json::number_unsigned_t v) {
        return value() && done(DomParser::number_unsigned(v));
    }
    bool number_float(json::number_float_t v, const std::string& s) {
        return value() && done(DomParser::number_float(v, s));
    }
    bool string(std::string& v) { return value() && done(DomParser::string(v)); }
    bool binary(json::binary_t& v) { return value() && done(DomParser::binary(v)); }

    bool start_object(std::size_t n) {
        open(false);
        return DomParser::start_object(n);
    }
    bool end_object() {
        frames_.pop_back();
        return done(DomParser::end_object());
    }
    bool start_array(std::size_t n) {
        open(true);
        return DomParser::start_array(n);
    }
    bool end_array() {
        frames_.pop_back();
        return done(DomParser::end_array());
    }
    bool key(std::string& k) {
        Frame& f = frames_.back();
        f.key = k;
        f.inValue = true;
        if (!f.keys.insert(k).second) fail(path() + ": duplicate key");
        return DomParser::key(k);
    }

    bool parse_error(std::size_t position, const std::string& token,
                     const nlohmann::detail::exception& ex) {
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 1,
        // column 5: syntax error while parsing value - ..."; keep only the part after the
        // position, which we compute ourselves from the byte offset.
        std::string what = ex.what();
        if (const auto bracket = what.find("] "); bracket != std::string::npos) {
            what.erase(0, bracket + 2);
        }
        if (const auto colon = what.find(": ");
            what.starts_with("parse error") && colon != std::string::npos) {
            what.erase(0, colon + 2);
        }
        // Invalid UTF-8 or control characters quoted from the input must not reach a terminal.
        what = printable(what);
        // `position` counts the bytes read, so the offending byte is the last one read; a number
        // that overflows (error 406) has been read whole, so point at its first digit instead.
        std::size_t offset = position == 0 ? 0 : position - 1;
        if (ex.id == 406 && token.size() <= position) offset = position - token.size();
        const TextPosition at = positionOf(text_, offset);
        std::string where =
            "line " + std::to_string(at.line) + ", column " + std::to_string(at.column);
        if (const std::string p = path(); p != "(root)") where += " (" + p + ")";
        fail(where + ": " + what);
    }

  private:
    [[noreturn]] void fail(const std::string& message) const {
        throw SceneError(std::string(source_) + ": " + message);
    }

    // A value begins inside the current container: advance the array index.
    bool value() {
        if (++values_ > kMaxValues) {
            fail("more than " + std::to_string(kMaxValues) + " JSON values");
        }
        if (!frames_.empty() && frames_.back().array) {
            Frame& f = frames_.back();
            f.key = std::to_string(f.next++);
            f.inValue = true;
        }
        return true;
    }

    // A value ended: a later syntax error is no longer inside it.
    bool done(bool ok) {
        if (!frames_.empty()) frames_.back().inValue = false;
        return ok;
    }

    void open(bool array) {
        value();
        if (frames_.size() >= static_cast<std::size_t>(kMaxSceneNesting)) {
            fail("nested deeper than " + std::to_string(kMaxSceneNesting) + " levels");
        }
        Frame f;
        f.array = array;
        frames_.push_back(std::move(f));
    }

    // The path of the value being read, e.g. particles[3].mass ("(root)" at the top); between
    // values, the path of the container.
    [[nodiscard]] std::string path() const {
        std::string p;
        for (const Frame& f : frames_) {
            if (!f.inValue) break;
            if (f.array) {
                p += "[" + f.key + "]";
            } else {
                if (!p.empty()) p += '.';
                p += f.key;
            }
        }
        return p.empty() ? "(root)" : p;
    }

    // A million particles take about 11 values each; beyond this a file is hostile, and its
    // DOM (~100 bytes per value) would take gigabytes.
    static constexpr std::size_t kMaxValues = 16'000'000;

    std::string_view text_;
    std::string_view source_;
    std::size_t values_ = 0;
    std::vector<Frame> frames_;
};

}  // namespace

TextPosition positionOf(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    TextPosition at;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

nlohmann::json readJson(std::string_view text, std::string_view source) {
    json result;
    TrackingParser handler(result, text, source);
    const bool ok = json::sax_parse(text.begin(), text.end(), &handler);
    if (!ok) throw SceneError(std::string(source) + ": could not parse JSON");
    return result;
}

}  // namespace psb::detail
