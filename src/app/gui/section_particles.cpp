// The control panel's particle tables: the selected particle's values, editable in place, and
// a table of every particle for small scenes (PhET's "more data").

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "session/units.hpp"
#include "view/inspector_lines.hpp"

namespace psb::app {

using widgets::row;
using widgets::tip;

namespace {

struct EditableField {
    ParticleField field;
    const char* name;
    const char* unit;
};
constexpr EditableField kFields[] = {
    {ParticleField::X, "x", "m"},
    {ParticleField::Y, "y", "m"},
    {ParticleField::Vx, "vx", "m/s"},
    {ParticleField::Vy, "vy", "m/s"},
    {ParticleField::Mass, "mass", "kg"},
    {ParticleField::Radius, "radius", "m"},
    {ParticleField::Omega, "\u03c9", "rad/s"},
    {ParticleField::Inertia, "k", "I = k m r\u00b2"},
};
constexpr const char* fieldHelp(ParticleField f, bool yUp) {
    switch (f) {
        case ParticleField::Y:
            return yUp ? "Its height above the box's floor (y up, Show). Type a new value and "
                         "press Enter"
                       : "How far below the box's top edge it is (y down: Show's y up is off). "
                         "Type a new value and press Enter";
        case ParticleField::Vy:
            return yUp ? "Its velocity upward (y up, Show): negative while it falls. Type a new "
                         "value and press Enter"
                       : "Its velocity downward (y down: Show's y up is off). Type a new value "
                         "and press Enter";
        case ParticleField::Omega:
            return yUp ? "The angular velocity: how fast it turns, positive counterclockwise (y "
                         "up). Type a new value and press Enter; a particle with fixed rotation "
                         "keeps 0"
                       : "The angular velocity: how fast it turns, positive clockwise on screen "
                         "(y down). Type a new value and press Enter; a particle with fixed "
                         "rotation keeps 0";
        case ParticleField::Inertia:
            return "The inertia factor k in the moment of inertia I = k m r\u00b2, above 0 and "
                   "at most 1: 1/2 a uniform disc, 2/5 a ball, 1 a ring. The smaller k, the "
                   "faster it rolls down a slope";
        default:
            return "Type a new value and press Enter (or click elsewhere); a value the world "
                   "cannot take is refused with the reason";
    }
}

/// `f`'s value as shown, in `axes` (the y up option).
double fieldValue(const Particle& p, ParticleField f, const Axes& axes) {
    switch (f) {
        case ParticleField::X:
            return p.position.x();
        case ParticleField::Y:
            return axes.y(p.position.y());
        case ParticleField::Vx:
            return p.velocity.x();
        case ParticleField::Vy:
            return axes.up(p.velocity.y());
        case ParticleField::Mass:
            return p.mass;
        case ParticleField::Radius:
            return p.radius;
        case ParticleField::Omega:
            return axes.spin(p.angularVelocity);
        case ParticleField::Inertia:
            return p.inertiaFactor;
    }
    return 0.0;
}

}  // namespace

void ControlPanel::selected(const Session& s) {
    const auto p = s.selected();
    // A new selection opens the section and brings it into view, once: the user may scroll
    // away from it after.
    const bool newSelection = p && p->id != shownSelection_;
    shownSelection_ = p ? p->id : kNullParticle;
    if (newSelection) ImGui::SetNextItemOpen(true);
    const float top = ImGui::GetCursorPosY();
    const bool open = ImGui::CollapsingHeader("Selected particle", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Selected particle");
    if (open) selectedValues(s, p);
    if (newSelection) {
        const float bottom = ImGui::GetCursorPosY(), scroll = ImGui::GetScrollY();
        const float shown = ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y;
        if (top < scroll || bottom > scroll + shown)
            ImGui::SetScrollY(std::min(top, bottom - shown));
    }
}

void ControlPanel::selectedValues(const Session& s, const std::optional<Particle>& p) {
    // A field typed in belongs to the particle it was typed for: a click on another particle
    // (or on empty space) both leaves the field, which applies the text, and changes the
    // selection, and the text goes to the particle it was meant for, not the new one.
    const bool typing =
        std::find(fieldActive_.begin(), fieldActive_.end(), true) != fieldActive_.end();
    if (!typing) fieldOwner_ = p ? p->id : kNullParticle;
    if (!p) {
        widgets::wrappedDisabled("Click a particle (or a row below) to see its values");
        // The fields are gone with the selection: what was being typed is applied.
        for (std::size_t k = 0; k < std::size(kFields); ++k) {
            if (fieldActive_[k] && fieldOwner_ != kNullParticle) {
                out_.emplace_back(
                    cmd::EditParticle{fieldOwner_, kFields[k].field, fieldText_[k].data()});
            }
        }
        fieldActive_.fill(false);
        return;
    }
    ImGui::Text("Particle %llu", static_cast<unsigned long long>(particleNumber(p->id)));
    ImGui::SameLine();
    if (widgets::smallButton("deselect", touchWidth_))
        out_.emplace_back(cmd::Select{kNullParticle});
    mark("deselect");
    tip("Forget the selection (or click empty space)");
    ImGui::SameLine();
    if (widgets::smallButton("delete", touchWidth_)) out_.emplace_back(cmd::DeleteParticle{p->id});
    mark("delete particle");
    tip("Remove this particle from the world (Ctrl+Z brings it back; Backspace or Delete "
        "removes a particle you hold)");
    if (!widgets::beginRows("selected")) return;
    const Axes axes = s.axes();
    for (std::size_t k = 0; k < std::size(kFields); ++k) {
        const EditableField& f = kFields[k];
        auto& text = fieldText_[k];
        // While a field is typed in it keeps the user's text; otherwise it shows the value now.
        if (!fieldActive_[k]) {
            text.fill('\0');
            fieldNumber(fieldValue(*p, f.field, axes)).copy(text.data(), text.size() - 1);
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        // Which way y counts, where the numbers are typed.
        const bool upward =
            axes.yUp && (f.field == ParticleField::Y || f.field == ParticleField::Vy);
        ImGui::Text("%s%s (%s)", f.name, upward ? " up" : "", f.unit);
        ImGui::TableNextColumn();
        ImGui::SetNextItemWidth(-1.f);
        ImGui::PushID(static_cast<int>(k));
        const bool enter = ImGui::InputText("##v", text.data(), text.size(),
                                            ImGuiInputTextFlags_EnterReturnsTrue |
                                                ImGuiInputTextFlags_CharsScientific |
                                                ImGuiInputTextFlags_AutoSelectAll);
        // Enter, or leaving the field (a click elsewhere, Tab) after typing, applies it.
        const bool left = ImGui::IsItemDeactivatedAfterEdit();
        fieldActive_[k] = ImGui::IsItemActive();
        mark(std::string("selected ") + f.name);
        if (enter || left) {
            out_.emplace_back(cmd::EditParticle{fieldOwner_, f.field, text.data()});
            fieldActive_[k] = false;
        }
        tip(fieldHelp(f.field, axes.yUp));
        ImGui::PopID();
    }
    const double speed = p->velocity.norm();
    row("speed", quantity(speed, "m/s", false), "How fast it moves, whatever the direction");
    row("momentum", quantity(p->mass * speed, "kg m/s", false), "m v: mass times speed");
    const SpinReading spin = spinReading(*p, axes);
    if (s.world().rotationInUse()) {
        row("turns",
            p->fixedRotation ? std::string("never (fixed rotation)")
                             : quantity(spin.revPerMin, "rev/min", false),
            axes.yUp ? "Turns a minute, counterclockwise when positive (y up); a particle with "
                       "fixed rotation slides without ever turning"
                     : "Turns a minute, clockwise when positive (y down); a particle with fixed "
                       "rotation slides without ever turning");
        row("kinetic energy", quantity(spin.translational, "J"),
            "Of its motion along its path, \u00bd m v\u00b2");
        row("  of rotation", quantity(spin.rotational, "J"),
            "Of its turning, \u00bd I \u03c9\u00b2 with I = k m r\u00b2");
    } else {
        row("kinetic energy", quantity(spin.translational, "J"), "\u00bd m v\u00b2");
    }
    ImGui::EndTable();
    if (!s.editRefusal().empty()) {
        widgets::wrappedColored(widgets::problem(s.view().theme), "Refused: " + s.editRefusal());
    }
}

void ControlPanel::allParticles(const Session& s) {
    const bool open = ImGui::CollapsingHeader("All particles");
    mark("section All particles");
    if (!open) return;
    const World& w = s.world();
    if (w.size() > kTableMaxParticles) {
        ImGui::TextDisabled("%zu particles: the table is for scenes of up to %zu", w.size(),
                            kTableMaxParticles);
        return;
    }
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("all", 5, flags)) return;
    ImGui::TableSetupColumn("#");
    ImGui::TableSetupColumn("x, y (m)");
    ImGui::TableSetupColumn("speed");
    ImGui::TableSetupColumn("kg");
    ImGui::TableSetupColumn("r (m)");
    ImGui::TableHeadersRow();
    const auto selectedId = s.selection().id();
    // By number (particleNumber), as the labels and the Selected section name them.
    std::vector<ParticleId> ids = w.ids();
    std::sort(ids.begin(), ids.end(),
              [](ParticleId a, ParticleId b) { return particleNumber(a) < particleNumber(b); });
    for (const ParticleId id : ids) {
        const Particle p = w.get(id);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char label[32];
        std::snprintf(label, sizeof label, "%llu",
                      static_cast<unsigned long long>(particleNumber(id)));
        if (ImGui::Selectable(label, selectedId && *selectedId == id,
                              ImGuiSelectableFlags_SpanAllColumns)) {
            out_.emplace_back(cmd::Select{id});
        }
        mark("row " + std::string(label));
        ImGui::TableNextColumn();
        // Each quantity as every other readout of it writes it (units.hpp): three figures.
        const Vec2 at = s.axes().point(p.position);
        ImGui::TextUnformatted(
            (quantity(at.x(), "", false) + ", " + quantity(at.y(), "", false)).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(quantity(p.velocity.norm(), "m/s", false).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(quantity(p.mass, "", false).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(quantity(p.radius, "", false).c_str());
    }
    ImGui::EndTable();
}

}  // namespace psb::app
