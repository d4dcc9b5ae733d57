#pragma once
// What the session has to say (a mode refused, a file saved): notices, which the app shows for
// a few seconds and logs. Every part of the session says what it did through the one Notices
// the session keeps; the app takes them once a frame. The session keeps no clock of its own.

#include <string>
#include <vector>

namespace psb::app {

/// Something the session says: shown on screen (`show`) and/or written to the log (`log`).
struct Notice {
    enum class Level { Info, Warning, Error };
    Level level = Level::Info;
    std::string text;
    bool show = true;
    bool log = true;
    /// Non-empty: a newer notice of the same topic replaces this one on screen while it is the
    /// last shown (a slider being dragged says each value without filling the message box).
    std::string topic = {};
};

/// "[I] ", "[W] ", "[E] ": the log's prefix for `level`.
[[nodiscard]] const char* logPrefix(Notice::Level level);

/// The notices said since the app last took them, oldest first.
class Notices {
  public:
    /// Shown and logged.
    void say(std::string text, Notice::Level level = Notice::Level::Info) {
        notices_.push_back({level, std::move(text), true, true});
    }
    /// Logged only.
    void log(std::string text, Notice::Level level = Notice::Level::Info) {
        notices_.push_back({level, std::move(text), false, true});
    }
    /// Anything else (shown only, or under a topic).
    void add(Notice notice) { notices_.push_back(std::move(notice)); }
    /// Shown and logged after all else said until the app takes them: the message line shows
    /// the last two, and what a command did by the way must not be pushed off it by what it
    /// says of itself (a preset's two lines hid "Recording stopped").
    void sayLast(std::string text, Notice::Level level = Notice::Level::Info) {
        last_.push_back({level, std::move(text), true, true});
    }
    /// Messages name the panel's button, not the key: the user's hands are on a touch screen
    /// (a page on a phone or a tablet, SessionOptions::touch, cmd::SetTouch).
    bool touch = false;
    /// `key` where there are keys, `button` (the panel's control for it) on a touch screen.
    [[nodiscard]] const char* key(const char* key, const char* button) const {
        return touch ? button : key;
    }
    /// Undo's key, or the panel's Undo (in Time) on a touch screen.
    [[nodiscard]] const char* undoKey() const { return key("Ctrl+Z", "Time: Undo"); }
    /// What was said since the last call.
    [[nodiscard]] std::vector<Notice> take() {
        std::vector<Notice> out;
        out.swap(notices_);
        for (Notice& n : last_)
            out.push_back(std::move(n));
        last_.clear();
        return out;
    }

  private:
    std::vector<Notice> notices_;
    std::vector<Notice> last_;  ///< sayLast's
};

}  // namespace psb::app
