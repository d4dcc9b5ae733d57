// The selection and its edit prompt (edit_prompt.hpp): selecting from a table, the prompt's
// keys, and one value of one particle set as text from the panel. The edit is checked here and
// written by the document.

#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/notices.hpp"
#include "session/particle_edit.hpp"
#include "session/scene_view.hpp"
#include "session/tools.hpp"

namespace psb::app {

void Tools::handle(const cmd::Select& c, Context& x) {
    if (c.id.isNull() || !x.doc.world.contains(c.id)) {
        if (selection.id()) {
            selection.clear();
            closePrompt();
        }
        return;
    }
    if (prompt.target() != c.id) closePrompt();
    if (selection.id() != c.id) editRefusal.clear();
    selection.select(c.id);
}

void Tools::handle(const cmd::OpenEdit&, Context& x) {
    const auto id = selection.id();
    if (!id) {
        x.notices.say(x.notices.key("Click a particle to select it, then Enter edits it",
                                    "Tap a particle to select it, then edit it in the panel's "
                                    "Selected particle"));
        return;
    }
    prompt.open(x.doc.world.get(*id), x.view.axes(x.doc.world.def()));
    x.notices.log("Editing particle " + std::to_string(particleNumber(*id)));
}

void Tools::handle(const cmd::EditType& c, Context&) {
    prompt.type(c.text);
}

void Tools::handle(const cmd::EditField& c, Context&) {
    if (c.back) {
        prompt.previousField();
    } else {
        prompt.nextField();
    }
}

void Tools::handle(const cmd::EditBackspace&, Context&) {
    prompt.backspace();
}

void Tools::handle(const cmd::EditApply&, Context& x) {
    const Axes axes = x.view.axes(x.doc.world.def());
    const EditResult r =
        x.doc.editParticle(checkEdit(x.doc.world, prompt.target(), prompt.texts(), axes), axes);
    if (r.applied) {
        closePrompt();
        x.notices.say(r.message);
        x.edit.userAction("edit particle");
    } else {
        // The prompt stays open with its text, so the value can be corrected.
        prompt.setError(r.message);
        x.notices.say("Edit refused: " + r.message, Notice::Level::Warning);
    }
}

void Tools::handle(const cmd::EditParticle& c, Context& x) {
    if (prompt.active() && prompt.target() == c.id) closePrompt();
    const Axes axes = x.view.axes(x.doc.world.def());
    const EditResult r =
        x.doc.editParticle(checkValue(x.doc.world, c.id, c.field, c.text, axes), axes);
    if (!r.applied) {
        editRefusal = r.message;
        x.notices.say("Edit refused: " + r.message, Notice::Level::Warning);
        return;
    }
    editRefusal.clear();
    x.notices.say(r.message);
    x.edit.userAction("edit particle");
}

}  // namespace psb::app
