// The control panel's Last collision section: the card (session/last_collision.hpp) as a table
// of before and after, with what the collision kept and lost. Shown while J (or the Show
// section's checkbox) has the card on. Below the table, the momenta diagram
// (view/momenta_diagram.hpp): before and after, tip to tail, on one scale.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <imgui.h>
#include <imgui_internal.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "view/collision_card_lines.hpp"
#include "view/momenta_diagram.hpp"
#include "view/palette.hpp"

namespace psb::app {

void ControlPanel::lastCollision(const Session& s) {
    const bool turnedOn = s.view().collision && !cardShown_;
    cardShown_ = s.view().collision;
    // A new collision on the card, or R clearing it, while it was shown: the controls below it
    // stay where they are (keepAnchor), the user may be working there.
    const std::optional<double> seen =
        s.lastCollision() ? std::optional<double>(s.lastCollision()->collision.time) : std::nullopt;
    // For the frames its text takes to settle too (wrapped text takes the width the frame before
    // found).
    if (s.view().collision && !turnedOn && seen != cardSeen_) {
        cardSettling_ = 3;
    } else if (cardSettling_ > 0) {
        --cardSettling_;
    }
    cardChanged_ = s.view().collision && cardSettling_ > 0;
    cardSeen_ = seen;
    afterCard_ = items_.size();
    // Held (a finger or a button down on the panel, holdLayout): the card keeps the height it
    // had when the hold began, so that nothing below it moves under the finger.
    const bool held = layoutHeld();
    if (!held) heldCardHeight_.reset();
    if (!s.view().collision && !heldCardHeight_) return;
    const float top = ImGui::GetCursorPosY();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    if (heldCardHeight_) {
        ImGuiWindow* w = ImGui::GetCurrentWindow();
        ImGui::PushClipRect(ImVec2(w->Pos.x, topLeft.y),
                            ImVec2(w->Pos.x + w->Size.x, topLeft.y + *heldCardHeight_), true);
    }
    if (s.view().collision) {
        // Turned on, the section opens where it is: the panel never scrolls to it (a student
        // reaching for a button below found the card under the pointer instead).
        if (turnedOn) ImGui::SetNextItemOpen(true);
        const bool open = ImGui::CollapsingHeader("Last collision", ImGuiTreeNodeFlags_DefaultOpen);
        mark("section Last collision");
        if (open) card(s);
    }
    if (heldCardHeight_) {
        ImGui::PopClipRect();
        ImGui::SetCursorPosY(top + *heldCardHeight_);
    } else if (held) {
        heldCardHeight_ = ImGui::GetCursorPosY() - top;
    }
    afterCard_ = items_.size();
}

void ControlPanel::card(const Session& s) {
    const std::optional<CollisionCard>& card = s.lastCollision();
    const std::optional<Particle> selected = s.selected();
    if (!card) {
        const std::string run = s.touch() ? ": run time (Play)" : ": run time (Space)";
        // A small scene's card listens all along; a large one's only while it is shown.
        const bool allAlong = LastCollision::listening(false, s.world().size());
        const std::string since = allAlong ? " yet" : " since the card was shown";
        widgets::wrappedDisabled(
            selected
                ? "Particle " + std::to_string(particleNumber(selected->id)) + " has not collided" +
                      (allAlong ? std::string(" since it was selected") : since) + run
                : "No collision between two particles" + since + run +
                      ", or select a particle to follow its collisions");
        return;
    }
    const CollisionCardText text = collisionCardText(*card, s.axes());
    widgets::wrapped(text.title);
    mark("collision title");
    // Stepped back before it through the recorded frames: the card stays, and says so.
    if (const std::string ahead = cardAhead(*card, s.world().time()); !ahead.empty()) {
        widgets::wrappedDisabled(ahead);
        mark("collision ahead");
    }
    widgets::wrappedDisabled(card->follows != 0 ? "The selected particle's last collision"
                                                : "The last collision between two particles "
                                                  "(select one to follow it)");
    // The names' column as wide as their longest word and their units ("kinetic" over
    // "energy"): the values' columns keep the room for a vector in one line, which in a gas's
    // collision ("(-0.236, -0.306)") wrapped onto two at 200 %.
    float names = 0.f;
    for (const CollisionCardText::Row& r : text.rows) {
        names = std::max(names, ImGui::CalcTextSize(r.unit.c_str()).x);
        for (std::size_t from = 0; from < r.name.size();) {
            const std::size_t end = std::min(r.name.find(' ', from), r.name.size());
            names = std::max(names, ImGui::CalcTextSize(r.name.substr(from, end - from).c_str()).x);
            from = end + 1;
        }
    }
    // Before and after side by side where two vectors fit beside the names; else each quantity's
    // name on a line of its own and its values under it, one a line: in the panel's 240 points
    // at 200 % a gas's vector ("(0.694, -0.0908)") broke over two lines beside the other.
    float widest = 0.f;
    for (const CollisionCardText::Row& r : text.rows) {
        widest = std::max({widest, ImGui::CalcTextSize(r.before.c_str()).x,
                           ImGui::CalcTextSize(r.after.c_str()).x});
    }
    const float pad = ImGui::GetStyle().CellPadding.x;
    if (std::ceil(names) + 2.f * widest + 6.f * pad > ImGui::GetContentRegionAvail().x) {
        stackedCard(text);
    } else if (ImGui::BeginTable("collision", 3,
                                 ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, std::ceil(names));
        ImGui::TableSetupColumn("before", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("after", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableHeadersRow();
        for (const CollisionCardText::Row& r : text.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.f);
            ImGui::TextUnformatted(r.name.c_str());
            ImGui::PopTextWrapPos();
            if (!r.unit.empty()) ImGui::TextDisabled("%s", r.unit.c_str());
            widgets::tip(r.help.c_str());
            ImGui::TableNextColumn();
            widgets::wrapped(r.before);
            mark("collision " + r.name + " before");
            ImGui::TableNextColumn();
            widgets::wrapped(r.after);
            mark("collision " + r.name + " after");
        }
        ImGui::EndTable();
    }
    for (const std::string& note : text.notes)
        widgets::wrapped(note);
    momenta(*card, momentaColours(s.view().theme));
}

void ControlPanel::stackedCard(const CollisionCardText& text) {
    const float tag = std::max(ImGui::CalcTextSize("before").x, ImGui::CalcTextSize("after").x);
    for (const CollisionCardText::Row& r : text.rows) {
        ImGui::PushID(r.name.c_str());
        widgets::wrapped(r.unit.empty() ? r.name : r.name + " (" + r.unit + ")");
        widgets::tip(r.help.c_str());
        if (ImGui::BeginTable("values", 2, ImGuiTableFlags_SizingFixedFit)) {
            ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, std::ceil(tag));
            ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
            for (const auto& [when, value] :
                 {std::pair{"before", &r.before}, {"after", &r.after}}) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", when);
                ImGui::TableNextColumn();
                widgets::wrapped(*value);
                mark("collision " + r.name + " " + when);
            }
            ImGui::EndTable();
        }
        ImGui::PopID();
    }
}

namespace {

/// The diagram's colours (momentaColours): particle 1's, particle 2's, the total's.
ImU32 arrowColor(MomentaDiagram::Kind kind, const std::array<Color, 3>& colours) {
    const std::size_t k = kind == MomentaDiagram::Kind::First    ? 0
                          : kind == MomentaDiagram::Kind::Second ? 1
                                                                 : 2;
    return IM_COL32(colours[k].r, colours[k].g, colours[k].b, 255);
}

/// `color` as a label on the panel: darkened (or lightened) to read (view/palette.hpp's
/// readableText); Okabe-Ito orange on the light theme's panel is 2:1.
ImU32 readableLabel(ImU32 color) {
    const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    const auto channel = [](float v) { return static_cast<std::uint8_t>(std::lround(255.f * v)); };
    const auto part = [&](int shift) {
        return static_cast<std::uint8_t>((color >> shift) & 0xFFu);
    };
    const Rgba r =
        readableText(Rgba{part(IM_COL32_R_SHIFT), part(IM_COL32_G_SHIFT), part(IM_COL32_B_SHIFT)},
                     Rgba{channel(bg.x), channel(bg.y), channel(bg.z)});
    return IM_COL32(r.r, r.g, r.b, 255);
}

/// One half of the diagram in a square canvas `side` pixels wide at the cursor.
void drawHalf(const MomentaDiagram& d, const std::vector<MomentaDiagram::Arrow>& arrows,
              const char* id, float side, const std::array<Color, 3>& colours) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, ImVec2(side, side));
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const ImU32 faint = ImGui::GetColorU32(ImGuiCol_Border);
    draw.AddRect(at, ImVec2(at.x + side, at.y + side), faint);
    const ImVec2 centre(at.x + 0.5f * side, at.y + 0.5f * side);
    const float font = ImGui::GetFontSize();
    // The axes dashed, under the arrows: an arrow along one (a total along x in an oblique
    // collision) is drawn whole over the dashes and reads as an arrow, not as the axis.
    const float dash = 0.3f * font;
    for (float t = 0.f; t < side; t += 2.f * dash) {
        const float end = std::min(side, t + dash);
        draw.AddLine(ImVec2(at.x + t, centre.y), ImVec2(at.x + end, centre.y), faint);
        draw.AddLine(ImVec2(centre.x, at.y + t), ImVec2(centre.x, at.y + end), faint);
    }
    const float head = 0.45f * font;
    std::vector<Vec2> sizes;
    for (const MomentaDiagram::Arrow& a : arrows) {
        const ImVec2 size = ImGui::CalcTextSize(a.label.c_str());
        sizes.emplace_back(size.x, size.y);
    }
    // Each label inside the square, clear of the arrows, the axes and the other labels
    // (view/momenta_diagram.hpp); an arrow's head is 0.45 font wide, half of it either side.
    const std::vector<Vec2> labels = momentaLabelPlaces(d, arrows, side, sizes, 0.25 * font + 1.0);
    for (std::size_t k = 0; k < arrows.size(); ++k) {
        const MomentaDiagram::Arrow& a = arrows[k];
        const Vec2 from = d.fromPixels(a, side), to = d.toPixels(a, side);
        const ImVec2 p0(at.x + static_cast<float>(from.x()), at.y + static_cast<float>(from.y()));
        const ImVec2 p1(at.x + static_cast<float>(to.x()), at.y + static_cast<float>(to.y()));
        const ImU32 color = arrowColor(a.kind, colours);
        draw.AddText(ImVec2(at.x + static_cast<float>(labels[k].x()),
                            at.y + static_cast<float>(labels[k].y())),
                     readableLabel(color), a.label.c_str());
        const float thick = a.kind == MomentaDiagram::Kind::Total ? 0.16f * font : 0.11f * font;
        const Vec2 along = to - from;
        const double length = along.norm();
        if (!(length > 0.5)) {  // nothing to point: a dot, so "no momentum" still shows
            draw.AddCircleFilled(p1, 0.2f * font, color);
            continue;
        }
        const Vec2 u = along / length, n(-u.y(), u.x());
        const double h = std::min<double>(head, 0.6 * length);
        const Vec2 base = to - h * u;
        draw.AddLine(
            p0, ImVec2(at.x + static_cast<float>(base.x()), at.y + static_cast<float>(base.y())),
            color, thick);
        const Vec2 l = base + 0.5 * h * n, r = base - 0.5 * h * n;
        draw.AddTriangleFilled(
            p1, ImVec2(at.x + static_cast<float>(l.x()), at.y + static_cast<float>(l.y())),
            ImVec2(at.x + static_cast<float>(r.x()), at.y + static_cast<float>(r.y())), color);
    }
}

}  // namespace

void ControlPanel::momenta(const CollisionCard& card, const std::array<Color, 3>& colours) {
    const MomentaDiagram d = momentaDiagram(card);
    ImGui::Spacing();
    ImGui::TextUnformatted("Momenta, tip to tail");
    widgets::tip(
        card.pair() ? "Each particle's momentum m v as an arrow, the second drawn from the first's "
                      "tip, and the total from the start to the last tip. Before and after are on "
                      "one scale: the total's arrow does not change in a collision between two "
                      "particles"
                    : "The particle's momentum m v before and after, on one scale: a wall or an "
                      "obstacle changes it");
    mark("momenta diagram");
    const float gap = ImGui::GetStyle().ItemSpacing.x;
    const float side = std::clamp(0.5f * (ImGui::GetContentRegionAvail().x - gap),
                                  4.0f * ImGui::GetFontSize(), 14.0f * ImGui::GetFontSize());
    ImGui::BeginGroup();
    ImGui::TextDisabled("before");
    drawHalf(d, d.before, "##momenta before", side, colours);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextDisabled("after");
    drawHalf(d, d.after, "##momenta after", side, colours);
    ImGui::EndGroup();
    widgets::wrappedDisabled(momentaDiagramScale(d));
}

}  // namespace psb::app
