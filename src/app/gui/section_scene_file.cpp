// The Scene section's document part: the title and description the user writes, the file the
// scene belongs to with its unsaved mark, and Save, Save As and Revert.

#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"

namespace psb::app {

using widgets::tip;

namespace {

template <std::size_t N>
void copyText(std::array<char, N>& to, const std::string& from) {
    const std::size_t n = std::min(from.size(), N - 1);
    std::memcpy(to.data(), from.data(), n);
    to[n] = '\0';
}

float textWidth(std::string_view text) {
    return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x;
}

// The room a line has in a multi-line field as wide as `width`: its padding and the scroll bar
// it shows once the lines pass its height.
float fieldRoom(float width) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return width - 2.f * style.FramePadding.x - style.ScrollbarSize - 1.f;
}

// ImGui 1.86's multi-line field does not wrap: after each change its lines are broken again
// (soft_wrap.hpp), in place, so the start of the text stays in view as it is typed.
int rewrap(ImGuiInputTextCallbackData* data) {
    auto* wrap = static_cast<std::pair<SoftWrap*, float>*>(data->UserData);
    std::string shown(data->Buf, static_cast<std::size_t>(data->BufTextLen));
    if (wrap->first->edited(shown, wrap->second, textWidth)) {
        std::memcpy(data->Buf, shown.data(), shown.size());
        data->BufDirty = true;
    }
    return 0;
}

}  // namespace

void ControlPanel::sceneText(const Session& s) {
    // The fields show the scene's text except while they are being typed in; leaving a field
    // after a change sends both (one undoable edit).
    ImGui::TextUnformatted("Title");
    if (!titleActive_) copyText(title_, s.meta().name);
    ImGui::SetNextItemWidth(-1.f);
    ImGui::InputText("##title", title_.data(), title_.size(), ImGuiInputTextFlags_AutoSelectAll);
    titleActive_ = ImGui::IsItemActive();
    const bool titleDone = ImGui::IsItemDeactivatedAfterEdit();
    mark("title");
    tip("The scene's title: the window's title shows it, and a save keeps it");
    const float room = fieldRoom(ImGui::GetContentRegionAvail().x);
    if (!descriptionActive_) {
        copyText(description_, descriptionEditing_
                                   ? descriptionWrap_.start(s.meta().description, room, textWidth)
                                   : s.meta().description);
    }
    ImGui::TextUnformatted("Description");
    bool edit = false;
    if (!descriptionEditing_) {
        ImGui::SameLine();
        edit = widgets::smallButton("Edit", touchWidth_);
        mark("description edit");
        tip("Write what the scene shows (Enter or a click elsewhere keeps it)");
    }
    const ImVec2 size(
        -1.f, ImGui::GetTextLineHeightWithSpacing() * 4.f + 2.f * ImGui::GetStyle().FramePadding.y);
    bool descriptionDone = false;
    if (!descriptionEditing_) {
        // Read with its words wrapped (this ImGui's multi-line field does not wrap them); a
        // click on it, or Edit, opens the field.
        ImGui::BeginChild("##description text", size, true);
        ImGui::PushTextWrapPos(0.f);
        if (description_[0] == '\0') {
            ImGui::TextDisabled("(none yet: click to write one)");
        } else {
            ImGui::TextUnformatted(description_.data());
        }
        ImGui::PopTextWrapPos();
        const bool clicked = ImGui::IsWindowHovered() && ImGui::IsMouseClicked(0);
        ImGui::EndChild();
        mark("description");
        tip("What the scene shows, for whoever opens it next; a save keeps it. Click to edit");
        if (clicked || edit) {
            descriptionEditing_ = true;
            focusDescription_ = true;
        }
    } else {
        if (focusDescription_) ImGui::SetKeyboardFocusHere();
        std::pair<SoftWrap*, float> wrap{&descriptionWrap_, room};
        ImGui::InputTextMultiline(
            "##description", description_.data(), description_.size(), size,
            ImGuiInputTextFlags_CtrlEnterForNewLine | ImGuiInputTextFlags_CallbackEdit, rewrap,
            &wrap);
        descriptionActive_ = ImGui::IsItemActive();
        if (descriptionActive_) focusDescription_ = false;
        descriptionDone = ImGui::IsItemDeactivatedAfterEdit();
        // Left (Enter, a click elsewhere, Esc) or Done: back to the wrapped text.
        if (ImGui::IsItemDeactivated()) descriptionEditing_ = false;
        mark("description");
        tip("What the scene shows, for whoever opens it next; a save keeps it. Enter or a click "
            "elsewhere keeps what you typed (Ctrl+Enter: a new line)");
    }
    if (titleDone || descriptionDone) {
        // The description as typed: its soft breaks spaces again.
        const std::string description = descriptionEditing_ || descriptionDone
                                            ? descriptionWrap_.text(description_.data())
                                            : std::string(description_.data());
        out_.emplace_back(cmd::SetSceneText{title_.data(), description});
    }
}

void ControlPanel::sceneFile(const Session& s) {
    const SceneFile& f = s.sceneFile();
    // In a page the path is in the page's own memory, which means nothing to the user: the file
    // is named, and a save says it went to the browser's downloads.
    const std::string file = !f.path    ? std::string()
                             : browser_ ? f.path->filename().string()
                                        : f.path->string();
    if (f.path) {
        widgets::wrapped("File: " + file);
        if (!f.writable) {
            widgets::wrappedDisabled("(read-only here: Save asks for a new name)");
        }
    } else {
        widgets::wrappedDisabled("Not saved in a file yet: Save asks for a name");
    }
    mark("file", f.path ? "File: " + file : std::string());
    if (s.unsavedChanges()) {
        widgets::wrappedColored(widgets::caution(s.view().theme), "Unsaved changes");
        mark("unsaved");
    }
    if (ImGui::Button("Save")) out_.emplace_back(cmd::Save{});
    mark("Save");
    tip(!f.writable ? "Save the scene: asks for a file name first (Ctrl+S)"
        : browser_  ? ("Download the scene again as " + file + " (Ctrl+S)").c_str()
                    : ("Write the scene to " + file + " (Ctrl+S)").c_str());
    ImGui::SameLine();
    if (ImGui::Button("Save As...")) out_.emplace_back(cmd::AskSaveAs{});
    mark("Save As");
    tip("Save the scene under a new name; the scene then belongs to that file (Ctrl+Shift+S)");
    ImGui::SameLine();
    if (ImGui::Button("Revert")) out_.emplace_back(cmd::Revert{});
    mark("Revert");
    tip(f.path ? ("Back to the file as it was last opened or saved, read again: " + file +
                  " (undo brings the changes back)")
                     .c_str()
               : "Back to the scene as it was made (undo brings the changes back)");
    if (s.fileError().empty() && s.lastSave()) {
        const std::string saved = browser_ ? "Saved as " + s.lastSave()->filename().string() +
                                                 ", a download: in your downloads (or where "
                                                 "the browser asked). Open reads it back"
                                           : "Saved to " + s.lastSave()->string();
        widgets::wrappedDisabled(saved);
        mark("saved", saved);
    }
}

}  // namespace psb::app
