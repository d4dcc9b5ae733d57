// The session's dialogs (session/dialog.hpp) as modal windows over the whole window: Save As (the
// folder in full, the name, Replace when the file exists), New scene (the box) and the quit
// question (Save, Discard, Cancel; with nothing unsaved, Quit and Stay). A modal window takes the
// keyboard, so its keys are here: Enter answers with the default button, Esc cancels.

#include <SDL_scancode.h>

#include <algorithm>
#include <cstring>
#include <string>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"

namespace psb::app {

namespace {

const char* titleOf(Dialog::Kind kind) {
    switch (kind) {
        case Dialog::Kind::SaveAs:
            return "Save scene as";
        case Dialog::Kind::NewScene:
            return "New scene";
        case Dialog::Kind::Quit:
            return "###quit";  // the title shown is the question's (quitTitle)
        case Dialog::Kind::None:
            break;
    }
    return "";
}

/// The quit dialog's window title: ImGui knows the window by what follows "###" (titleOf).
const char* quitTitle(const Dialog& d) {
    return d.unsaved ? "Unsaved changes###quit" : "Quit###quit";
}

bool pressed(ImGuiKey key) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false);
}

void errorLine(const std::string& error, Theme theme) {
    if (error.empty()) return;
    widgets::wrappedColored(widgets::problem(theme), error);
}

}  // namespace

void ControlPanel::keysLine(const Session& s, const char* keys) {
    // A touch screen has the dialog's buttons only.
    if (s.touch()) return;
    widgets::wrappedDisabled(keys);
    mark("dialog keys", keys);
}

void ControlPanel::dialog(const Session& s) {
    const Dialog& d = s.dialog();
    const int kind = static_cast<int>(d.kind);
    if (kind != shownDialog_) {
        // The session closed or changed the dialog: close the one ImGui shows.
        if (shownDialog_ != 0 &&
            ImGui::BeginPopupModal(titleOf(static_cast<Dialog::Kind>(shownDialog_)))) {
            ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
        }
        // A new dialog: its fields start from what the session proposes.
        shownDialog_ = kind;
        const std::string name = d.proposal.filename().string();
        const std::size_t n = std::min(name.size(), saveName_.size() - 1);
        std::memcpy(saveName_.data(), name.data(), n);
        saveName_[n] = '\0';
        newWidth_ = d.newScene.width;
        newHeight_ = d.newScene.height;
        newGravity_ = d.newScene.gravity;
        newWalls_ = d.newScene.walls;
        if (d.open()) ImGui::OpenPopup(titleOf(d.kind));  // the same id as quitTitle's
    }
    if (!d.open()) return;
    // On a touch screen its fields, box and buttons are a finger's targets, as the panel's.
    if (touch_) {
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding,
                            touchPadding(static_cast<float>(s.view().uiScaleInUse())));
    }
    modal(s);
    if (touch_) ImGui::PopStyleVar();
}

void ControlPanel::modal(const Session& s) {
    const Dialog& d = s.dialog();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->Size.x * 0.5f, vp->Size.y * 0.4f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(460.f, vp->Size.x - 20.f), 0.f));
    if (!ImGui::BeginPopupModal(d.kind == Dialog::Kind::Quit ? quitTitle(d) : titleOf(d.kind),
                                nullptr,
                                ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings)) {
        // Closed by ImGui itself (Esc): the session hears it as Cancel; otherwise it is opened
        // again next frame.
        if (pressed(ImGuiKey_Escape)) out_.emplace_back(cmd::CloseDialog{});
        shownDialog_ = 0;
        return;
    }
    // The key that opened the dialog (Esc asking to quit) is not its answer.
    const bool keys = !ImGui::IsWindowAppearing();
    const bool enter = keys && (pressed(ImGuiKey_Enter) || pressed(ImGuiKey_KeyPadEnter));
    const bool escape = keys && pressed(ImGuiKey_Escape);
    const auto button = [this](const char* label, const char* name) {
        const bool b = ImGui::Button(label, ImVec2(110.f, 0.f));
        mark(name);
        return b;
    };

    switch (d.kind) {
        case Dialog::Kind::SaveAs: {
            if (!d.replace.empty()) {
                widgets::wrapped(d.replace.filename().string() + " already exists in " +
                                 d.replace.parent_path().string() + ". Replace it?");
                if (button("Replace", "dialog Replace") || enter) {
                    out_.emplace_back(cmd::SaveAs{d.replace, true});
                }
                ImGui::SameLine();
                if (button("Cancel", "dialog Cancel") || escape) {
                    out_.emplace_back(cmd::CloseDialog{});
                }
                break;
            }
            widgets::wrapped(d.download ? std::string("The browser downloads the file (to its "
                                                      "downloads folder, or it asks where)")
                                        : "Folder: " + d.proposal.parent_path().string());
            ImGui::TextUnformatted("File name");
            ImGui::SetNextItemWidth(-1.f);
            if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
            const bool typedEnter =
                ImGui::InputText("##save name", saveName_.data(), saveName_.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue);
            mark("dialog file name");
            errorLine(d.error, s.view().theme);
            widgets::wrappedDisabled(d.download
                                         ? ".json is added when there is no extension."
                                         : "A name without a folder goes in the folder above; "
                                           ".json is added when there is no extension.");
            const std::filesystem::path typed(saveName_.data());
            const std::filesystem::path path =
                typed.is_absolute() ? typed : d.proposal.parent_path() / typed;
            if (button("Save", "dialog Save") || typedEnter || (enter && !typedEnter)) {
                out_.emplace_back(cmd::SaveAs{path, false});
            }
            ImGui::SameLine();
            if (button("Cancel", "dialog Cancel") || escape) {
                out_.emplace_back(cmd::CloseDialog{});
            }
            break;
        }
        case Dialog::Kind::NewScene: {
            widgets::wrapped(
                "An empty box. Restitution, friction and the stepping mode stay as "
                "they are now.");
            ImGui::SetNextItemWidth(150.f);
            // The width takes the keyboard at once, its text selected: typing replaces it, Tab
            // goes on to the height.
            if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
            ImGui::InputDouble("width (m)", &newWidth_, 0.0, 0.0, "%g",
                               ImGuiInputTextFlags_AutoSelectAll);
            mark("dialog width");
            ImGui::SetNextItemWidth(150.f);
            ImGui::InputDouble("height (m)", &newHeight_, 0.0, 0.0, "%g",
                               ImGuiInputTextFlags_AutoSelectAll);
            mark("dialog height");
            ImGui::SetNextItemWidth(150.f);
            ImGui::InputDouble("gravity (m/s\xc2\xb2, down; 0: none)", &newGravity_, 0.0, 0.0, "%g",
                               ImGuiInputTextFlags_AutoSelectAll);
            mark("dialog gravity");
            ImGui::Checkbox("walls around the box", &newWalls_);
            mark("dialog walls");
            errorLine(d.error, s.view().theme);
            if (button("Create", "dialog Create") || enter) {
                out_.emplace_back(cmd::NewScene{newWidth_, newHeight_, newGravity_, newWalls_});
            }
            ImGui::SameLine();
            if (button("Cancel", "dialog Cancel") || escape) {
                out_.emplace_back(cmd::CloseDialog{});
            }
            break;
        }
        case Dialog::Kind::Quit: {
            if (!d.unsaved) {
                // Nothing unsaved, but the run, its recordings and measurements go with the
                // program: Esc asks before they do.
                widgets::wrapped(
                    "Quit Particle Sandbox? The run, its recordings and "
                    "measurements end with it.");
                if (button("Quit", "dialog Quit") || enter) {
                    out_.emplace_back(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Quit});
                }
                ImGui::SameLine();
                if (button("Stay", "dialog Cancel") || escape) {
                    out_.emplace_back(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Cancel});
                }
                keysLine(s, "Enter: Quit, Esc: Stay");
                break;
            }
            widgets::wrapped("Save the changes to \"" + s.meta().name + "\" before quitting?");
            const SceneFile& f = s.sceneFile();
            widgets::wrappedDisabled(f.writable ? "Save writes " + f.path->string()
                                                : std::string("Save asks for a file name"));
            if (button("Save", "dialog Save") || enter) {
                out_.emplace_back(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Save});
            }
            ImGui::SameLine();
            if (button("Discard", "dialog Discard") ||
                (keys && ImGui::IsKeyPressed(SDL_SCANCODE_D, false))) {
                out_.emplace_back(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Discard});
            }
            ImGui::SameLine();
            if (button("Cancel", "dialog Cancel") || escape) {
                out_.emplace_back(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Cancel});
            }
            keysLine(s, "Enter: Save, D: Discard, Esc: Cancel");
            break;
        }
        case Dialog::Kind::None:
            break;
    }
    ImGui::EndPopup();
}

}  // namespace psb::app
