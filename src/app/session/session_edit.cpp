// The selection and its edit prompt (edit_prompt.hpp): selecting from a table, the prompt's
// keys, and one value of one particle set as text from the panel.

#include "session/session.hpp"

namespace psb::app {

void Session::handle(const cmd::Select& c) {
    Tools& t = tools_;
    if (c.id.isNull() || !doc_.world.contains(c.id)) {
        if (t.selection.id()) {
            t.selection.clear();
            t.closePrompt();
        }
        return;
    }
    if (t.prompt.target() != c.id) t.closePrompt();
    if (t.selection.id() != c.id) t.editRefusal.clear();
    t.selection.select(c.id);
}

void Session::handle(const cmd::OpenEdit&) {
    const auto id = tools_.selection.id();
    if (!id) {
        notices_.say("Click a particle to select it, then Enter edits it");
        return;
    }
    tools_.prompt.open(doc_.world.get(*id), axes());
    notices_.log("Editing particle " + std::to_string(particleNumber(*id)));
}

void Session::handle(const cmd::EditType& c) {
    tools_.prompt.type(c.text);
}

void Session::handle(const cmd::EditField& c) {
    if (c.back) {
        tools_.prompt.previousField();
    } else {
        tools_.prompt.nextField();
    }
}

void Session::handle(const cmd::EditBackspace&) {
    tools_.prompt.backspace();
}

void Session::handle(const cmd::EditApply&) {
    EditPrompt& prompt = tools_.prompt;
    const EditResult r = applyEdit(doc_.world, prompt.target(), prompt.texts(), axes());
    if (r.applied) {
        tools_.closePrompt();
        notices_.say(r.message);
        edit_.userAction("edit particle");
    } else {
        // The prompt stays open with its text, so the value can be corrected.
        prompt.setError(r.message);
        notices_.say("Edit refused: " + r.message, Notice::Level::Warning);
    }
}

void Session::handle(const cmd::EditParticle& c) {
    if (tools_.prompt.active() && tools_.prompt.target() == c.id) tools_.closePrompt();
    const EditResult r = editParticleValue(doc_.world, c.id, c.field, c.text, axes());
    if (!r.applied) {
        tools_.editRefusal = r.message;
        notices_.say("Edit refused: " + r.message, Notice::Level::Warning);
        return;
    }
    tools_.editRefusal.clear();
    notices_.say(r.message);
    edit_.userAction("edit particle");
}

}  // namespace psb::app
