#pragma once
// What a command's handler tells the undo history: the change it made, by its label. The
// handler reports it; Session::apply files it once the handler is done (session.hpp, "Undo"),
// so that no part of the session needs the history to say what it did.

#include <string>

namespace psb::app {

class EditReport {
  public:
    /// The user made the edit `what` ("delete particle", "set restitution"): it becomes an undo
    /// entry (the state before the command), the energy drift is measured from here on, and
    /// there are unsaved changes. A command that continues the previous one (a slider still
    /// being dragged) passes `continues`: it is part of that action (and of its undo entry), not
    /// a new one.
    void userAction(std::string what, bool continues = false) {
        remember(what);
        action_ = std::move(what);
        continues_ = continues;
    }
    /// A change undo restores that is not an edit of the scene (a setting, a scene opened or
    /// restarted): filed under `what`, with nothing unsaved. The first label a command reports
    /// is the one filed.
    void remember(const std::string& what) {
        if (label_.empty()) label_ = what;
    }

    /// The label to file the state before the command under; empty: none.
    [[nodiscard]] const std::string& label() const { return label_; }
    /// The user action reported; empty: none.
    [[nodiscard]] const std::string& action() const { return action_; }
    [[nodiscard]] bool continues() const { return continues_; }

  private:
    std::string label_;
    std::string action_;
    bool continues_ = false;
};

}  // namespace psb::app
