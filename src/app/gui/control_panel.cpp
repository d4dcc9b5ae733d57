#include "gui/control_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>

#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

using widgets::tip;

namespace {

void copyPath(std::array<char, 512>& to, const std::filesystem::path& from) {
    const std::string s = from.string();
    const std::size_t n = std::min(s.size(), to.size() - 1);
    std::memcpy(to.data(), s.data(), n);
    to[n] = '\0';
}

}  // namespace

void ControlPanel::mark(const std::string& name, std::string text) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    items_.push_back({name, a.x, a.y, b.x, b.y, ImGui::GetItemID()});
    if (!text.empty()) status_.emplace_back(name, std::move(text));
}

const PanelItem* ControlPanel::item(const std::string& name) const {
    for (const PanelItem& i : items_) {
        if (i.name == name) return &i;
    }
    return nullptr;
}

std::vector<Command> ControlPanel::build(const Session& s, const FrameStats& stats, float height,
                                         float pixelRatio) {
    out_.clear();
    items_.clear();
    status_.clear();
    const bool open = s.controlsShown();
    // Opened in a window too narrow for the box beside it (a phone), the panel lies over the box
    // as a sheet across the whole width: the rest of the box beside a column would be a sliver.
    // As wide as the window and no wider: the UI's scale in use leaves it at least
    // kControlsMinWidth points (mostUiScale), so its close button is on screen.
    const float display = ImGui::GetIO().DisplaySize.x;
    const float width = !open ? kControlsFoldedWidth
                        : s.layout().controlsFit
                            ? controlsOpenPoints(display * pixelRatio, pixelRatio)
                            : display;
    ImGui::SetNextWindowPos(ImVec2(0.f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    // The panel is opaque: SDL's software renderer fills opaque rectangles several times faster
    // than blended ones (docs/app-design.md, "Frame time").
    ImGui::PushStyleColor(ImGuiCol_WindowBg, widgets::colour(palette(s.view().theme).controls));
    ImGui::PushStyleColor(ImGuiCol_MenuBarBg, widgets::colour(palette(s.view().theme).controls));
    if (!open) {
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding,
                            ImVec2(kControlsFoldedPadding, ImGui::GetStyle().WindowPadding.y));
    }
    // On a touch screen every button, box and section header is a finger's target: at least
    // kTouchTargetPoints high (window points, CSS pixels in a page), by its frame's padding.
    // Not while a finger is on the panel: the first finger a laptop's touch screen feels would
    // otherwise grow the panel between its coming down and the tap it makes as it lifts.
    if (!fingerHeld_) touch_ = s.touch();
    const float scale = static_cast<float>(s.view().uiScaleInUse());
    touchWidth_ = touch_ ? kTouchTargetPoints / scale : 0.f;
    if (touch_) ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, touchPadding(scale));
    // Open, its top line (About, <<) is a menu bar: it stays put while the rest scrolls, so the
    // panel folds from anywhere in it (a phone's sheet took six swipes back to its top).
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
        ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_NoBringToFrontOnFocus | (open ? ImGuiWindowFlags_MenuBar : 0);
    const bool shown = ImGui::Begin("Controls", nullptr, flags);
    // Every control a tab stop: Tab walks through buttons, boxes and sections too, not only
    // the fields ImGui 1.86 tabs through (GuiContext::tabOnward goes on from the cursor).
    ImGui::PushItemFlag(ImGuiItemFlags_Inputable, true);
    if (shown) {
        if (!open) {
            if (ImGui::Button(">>", ImVec2(-1.f, 0.f))) out_.emplace_back(cmd::ToggleControls{});
            mark("open panel");
            tip("Open the control panel (key C)");
            if (browser_) aboutButton("?", ImVec2(-1.f, 0.f));
        } else {
            if (ImGui::BeginMenuBar()) {
                ImGui::TextUnformatted("Controls");
                const float fold = ImGui::GetFrameHeight() * 1.4f;
                const float right = ImGui::GetWindowContentRegionMax().x;
                if (browser_) {
                    // The page's About is here, not floating over the canvas, where it covered
                    // readings (the momentum legend, a phone's Time).
                    ImGui::SetCursorPosX(right - fold - ImGui::CalcTextSize("About").x -
                                         2.f * ImGui::GetStyle().FramePadding.x -
                                         ImGui::GetStyle().ItemSpacing.x);
                    aboutButton("About", ImVec2(0.f, 0.f));
                }
                ImGui::SetCursorPosX(right - fold);
                if (ImGui::Button("<<", ImVec2(fold, 0.f))) {
                    out_.emplace_back(cmd::ToggleControls{});
                }
                mark("fold panel");
                tip(touch_ ? "Fold the panel away to give the box more room"
                           : "Fold the panel away to give the box more room (key C)");
                ImGui::EndMenuBar();
            }
            ImGui::TextDisabled("%s", s.meta().name.c_str());
            const std::size_t firstItem = items_.size();
            time(s);
            scene(s);
            physics(s);
            show(s, pixelRatio);
            lastCollision(s);
            tools(s, pixelRatio);
            readouts(s);
            data(s);
            if (!browser_) video(s, stats.video);
            selected(s);
            allParticles(s);
            engine(s, stats);
            keepAnchor(firstItem);
        }
    }
    ImGui::PopItemFlag();
    ImGui::End();
    if (touch_) ImGui::PopStyleVar();
    if (!open) ImGui::PopStyleVar();
    ImGui::PopStyleColor(2);
    launchPreview(s, pixelRatio);
    valuesWindow(s, pixelRatio);
    dialog(s);
    return std::move(out_);
}

bool ControlPanel::layoutHeld() const {
    return fingerHeld_ ||
           (ImGui::IsAnyMouseDown() && ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows));
}

ImVec2 ControlPanel::touchPadding(float scale) {
    const ImVec2 pad = ImGui::GetStyle().FramePadding;
    return ImVec2(
        std::max(pad.x, 6.f),
        std::max(pad.y, std::ceil(kTouchTargetPoints / scale - ImGui::GetFontSize()) / 2.f));
}

void ControlPanel::keepAnchor(std::size_t firstItem) {
    ImGuiWindow* w = ImGui::GetCurrentWindow();
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 mouse = io.MousePos;
    const bool over = ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem) &&
                      mouse.x >= w->Pos.x && mouse.x < w->Pos.x + w->Size.x;
    // Only while the layout moves on its own: not while the user scrolls (wheel, bar, finger)
    // or holds a control, nor when the panel itself asked for a scroll this frame. With the
    // pointer elsewhere (in the box), when the collision card changes: after R and the next
    // collision the card, shrinking and growing again, scrolled a panel left at the Data
    // section to the card.
    const bool still =
        w->Scroll.y == anchorScroll_ && w->ScrollTarget.y == FLT_MAX && io.MouseWheel == 0.f &&
        (over ? !ImGui::IsAnyMouseDown() && !ImGui::IsAnyItemActive() : cardChanged_);
    float moved = 0.f;
    if (still) {
        bool found = false;
        for (const auto& [name, y] : anchors_) {
            for (std::size_t i = firstItem; i < items_.size() && !found; ++i) {
                if (items_[i].name == name) {
                    moved = items_[i].y0 - y;
                    found = true;
                }
            }
            if (found) break;
        }
        if (moved != 0.f) ImGui::SetScrollY(w->Scroll.y + moved);
    }
    // Moved back next frame, the same control is under the pointer.
    std::optional<std::vector<std::pair<std::string, float>>> kept;
    if (moved != 0.f) kept = anchors_;
    anchors_.clear();
    anchorScroll_ = w->Scroll.y + moved;
    // A panel that was not full cannot scroll by what it grew: blank room at its end, as much
    // as the scroll needs, kept while the scroll needs it (the user scrolling up gives it back).
    const float content = w->DC.CursorMaxPos.y - w->DC.CursorStartPos.y;
    // (The inner rectangle: the pinned top line takes its height off what the panel shows.)
    const float shown = w->InnerRect.GetHeight() - 2.f * ImGui::GetStyle().WindowPadding.y;
    const float reach = std::max(0.f, content - shown);
    // Only an anchor's move makes room: content that went away under a scroll nobody anchored
    // (the card gone at a restart) lets the scroll come back within what is left, or the panel
    // shows blank room where it was.
    const float needed = std::max(0.f, anchorScroll_ - reach);
    slack_ = moved > 0.f ? needed : std::min(slack_, needed);
    if (slack_ > 0.f) ImGui::Dummy(ImVec2(1.f, slack_ + 2.f));
    if (kept) {
        anchors_ = std::move(*kept);
        return;
    }
    if (!over) {
        // The pointer elsewhere: the first control below the card shown whole stays put when
        // the card changes, or the next one where it went.
        const float top = w->InnerRect.Min.y, bottom = w->InnerRect.Max.y;
        for (std::size_t i = std::max(firstItem, afterCard_); i < items_.size(); ++i) {
            if (items_[i].y0 >= top && items_[i].y1 <= bottom)
                anchors_.emplace_back(items_[i].name, items_[i].y0);
        }
        return;
    }
    // The control under the pointer (the smallest, where one holds others), else the nearest
    // above or below it.
    const PanelItem* best = nullptr;
    float distance = FLT_MAX, area = FLT_MAX;
    for (std::size_t i = firstItem; i < items_.size(); ++i) {
        const PanelItem& it = items_[i];
        const float d = mouse.y < it.y0 ? it.y0 - mouse.y : mouse.y > it.y1 ? mouse.y - it.y1 : 0.f;
        const float a = (it.x1 - it.x0) * (it.y1 - it.y0);
        const bool inside = d == 0.f && mouse.x >= it.x0 && mouse.x < it.x1;
        const float rank = inside ? -1.f : d;
        if (rank < distance || (rank == distance && inside && a < area)) {
            distance = rank;
            area = a;
            best = &it;
        }
    }
    if (best) anchors_.emplace_back(best->name, best->y0 - moved);
}

void ControlPanel::aboutButton(const char* label, ImVec2 size) {
    if (ImGui::Button(label, size)) aboutAsked_ = true;
    mark("About");
    tip("What the page does differently from the desktop program, and how to use it on a touch "
        "screen");
}

void ControlPanel::time(const Session& s) {
    const bool open = ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Time");
    if (!open) return;
    if (widgets::stateButton("Play/Pause", s.paused() ? "Play" : "Pause", ImVec2(70.f, 0.f))) {
        out_.emplace_back(cmd::TogglePause{});
    }
    mark("Play/Pause");
    tip("Start or stop the clock (key Space)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!s.paused());
    if (ImGui::Button("Step")) out_.emplace_back(cmd::SingleStep{});
    mark("Step");
    ImGui::EndDisabled();
    tip("Advance one time step while paused (key N)");
    ImGui::SameLine();
    if (ImGui::Button("Restart")) out_.emplace_back(cmd::Restart{});
    mark("Restart");
    tip("Back to the set-up: every particle where it was when Play was last pressed after an "
        "edit, or as the scene opened (key R). The ruler keeps its reading; the stopwatch and the "
        "last collision card start over. Scene: Revert goes back to the file");

    // Undo and redo of edits; back and forward in time (while paused).
    ImGui::BeginDisabled(!s.canUndo());
    if (ImGui::Button("Undo")) out_.emplace_back(cmd::Undo{});
    mark("Undo");
    ImGui::EndDisabled();
    tip(s.canUndo() ? ("Undo: " + s.undoLabel() + " (Ctrl+Z)").c_str()
                    : "Nothing to undo yet (Ctrl+Z)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!s.canRedo());
    if (ImGui::Button("Redo")) out_.emplace_back(cmd::Redo{});
    mark("Redo");
    ImGui::EndDisabled();
    tip(s.canRedo() ? ("Redo: " + s.redoLabel() + " (Ctrl+Shift+Z)").c_str()
                    : "Nothing to redo (Ctrl+Shift+Z)");
    const TimelineView t = s.timeline();
    ImGui::SameLine();
    ImGui::BeginDisabled(!s.paused() || t.current <= t.earliest);
    if (ImGui::Button("< Back")) out_.emplace_back(cmd::StepBack{});
    mark("Step back");
    ImGui::EndDisabled();
    tip("While paused: one frame back in time (Shift+Left; PageUp: a second)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!t.viewingPast);
    if (ImGui::Button("Fwd >")) out_.emplace_back(cmd::StepForward{});
    mark("Step forward");
    ImGui::EndDisabled();
    tip("One frame forward again, towards the present (Shift+Right; PageDown: a second)");
    // Always there (greyed out until something is recorded), so that the rows below it do not
    // move as it comes and goes.
    const bool recorded = t.recorded();
    double at = t.current;
    bool dragging = false;
    const auto [from, to] = t.sliderRange();
    ImGui::BeginDisabled(!s.paused() || !recorded);
    if (widgets::slider("Replay", at, from, to, "%.2f s", dragging) && recorded) {
        out_.emplace_back(cmd::Seek{at});
    }
    mark("Replay");
    ImGui::EndDisabled();
    tip("While paused: drag back over the recorded past; Play continues from the time shown");

    double speed = s.timeScale();
    bool continues = false;
    if (widgets::slider("Speed", speed, Session::kMinTimeScale, Session::kMaxTimeScale, "x%.3g",
                        continues, ImGuiSliderFlags_Logarithmic)) {
        out_.emplace_back(cmd::SetTimeScale{speed});
    }
    mark("Speed");
    tip("Simulated seconds per real second: x1 is real time, x0.25 slow motion (keys , and .)");
    // Held (a finger or a button down on the panel, as the collision card): the line keeps the
    // room it had when the hold began, so that a finger dragging the Speed slider or reaching
    // for the stopwatch has nothing below it move as the line comes and goes. One that comes
    // during the hold is shown at the lift; one that goes leaves its room blank until then.
    const bool slow = !s.paused() && s.reachedTimeScale() < 0.95 * s.timeScale();
    if (!layoutHeld()) {
        slowLineHeld_.reset();
    } else if (!slowLineHeld_) {
        slowLineHeld_ = slow;
    }
    if (slowLineHeld_.value_or(slow)) {
        if (slow) {
            ImGui::TextColored(widgets::caution(s.view().theme),
                               "Reaching only x%.2g: too much to compute", s.reachedTimeScale());
        } else {
            ImGui::TextUnformatted(" ");
        }
        mark("Speed reached");
    }
    stopwatch(s);
}

void ControlPanel::stopwatch(const Session& s) {
    using A = cmd::Stopwatch::Action;
    const LabStopwatch& w = s.stopwatch();
    const double now = s.world().time();
    ImGui::TextUnformatted("Stopwatch");
    ImGui::SameLine();
    if (widgets::smallStateButton("Stopwatch start", w.running() ? "Stop" : "Start", touchWidth_)) {
        out_.emplace_back(cmd::Stopwatch{A::StartStop});
    }
    mark("Stopwatch start");
    tip("Times simulated time: it stops while paused and reads the same at any speed (key U)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!w.running());
    if (widgets::smallButton("Lap", touchWidth_)) out_.emplace_back(cmd::Stopwatch{A::Lap});
    mark("Stopwatch lap");
    ImGui::EndDisabled();
    tip("A split time, while it runs (Shift+U)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!w.used());
    if (widgets::smallButton("Reset", touchWidth_)) out_.emplace_back(cmd::Stopwatch{A::Reset});
    mark("Stopwatch reset");
    ImGui::EndDisabled();
    tip("Back to zero (Shift+U while stopped)");
    if (w.used()) {
        ImGui::SameLine();
        if (w.beforeStart(now)) {
            ImGui::TextColored(widgets::caution(s.view().theme), "before its start");
        } else {
            ImGui::Text("%.3f s", w.reading(now));
        }
        mark("Stopwatch reading");
    }
}

void ControlPanel::scene(const Session& s) {
    const bool open = ImGui::CollapsingHeader("Scene");
    mark("section Scene");
    if (!open) return;
    ImGui::TextUnformatted("Presets");
    const float listHeight = ImGui::GetTextLineHeightWithSpacing() * 9.f;
    // With a mouse the presets are a list of their own, scrolled by the wheel. On a touch screen
    // they are rows of the panel, each a finger's target: a list within the panel took the
    // finger's scroll for itself, and its rows were a line high.
    const float rowHeight = touch_ ? touchWidth_ : 0.f;
    if (touch_) ImGui::PushStyleVar(ImGuiStyleVar_SelectableTextAlign, ImVec2(0.f, 0.5f));
    if (touch_ || ImGui::BeginChild("presets", ImVec2(0.f, listHeight), true)) {
        const auto& presets = s.presets();
        // The preset the scene came from, by its file (a saved copy keeps the preset's name
        // but is the user's file).
        const std::optional<std::filesystem::path>& from = s.sceneFile().path;
        for (std::size_t k = 0; k < presets.size(); ++k) {
            const SceneListing& p = presets[k];
            ImGui::PushID(static_cast<int>(k));
            std::error_code ec;
            const bool current =
                from && *from == std::filesystem::absolute(p.file, ec).lexically_normal();
            if (ImGui::Selectable(p.name.c_str(), current, 0, ImVec2(0.f, rowHeight))) {
                out_.emplace_back(cmd::OpenPreset{static_cast<int>(k)});
            }
            mark("preset " + p.name);
            const std::string key = k < 9 ? " (key " + std::to_string(k + 1) + ")" : "";
            const std::string about = p.description.empty() ? p.summary : p.description + key;
            tip(about.c_str());
            widgets::wrappedDisabled("  " + p.summary);
            tip(about.c_str());
            ImGui::PopID();
        }
    }
    if (touch_) {
        ImGui::PopStyleVar();
    } else {
        ImGui::EndChild();
    }

    if (ImGui::Button("New scene...")) out_.emplace_back(cmd::AskNewScene{});
    mark("New scene");
    // The browser keeps Ctrl+N (a new window), Ctrl+T (a tab) and Ctrl+plus, minus, 0 (its
    // zoom): the page's tips name no key that never reaches it.
    tip(browser_ ? "Start from an empty box: its size, gravity and walls in a dialog"
                 : "Start from an empty box: its size, gravity and walls in a dialog (Ctrl+N)");
    sceneText(s);
    sceneFile(s);

    if (browser_) {
        if (ImGui::Button("Open a scene file...")) uploadAsked_ = true;
        mark("Open");
        tip("Open a scene file (JSON) from this device, with the browser's file chooser");
        fileError(s);
        return;
    }
    if (!pathFilled_) {
        copyPath(path_, s.lastSave() ? *s.lastSave() : std::filesystem::path("my-scene.json"));
        pathFilled_ = true;
    }
    ImGui::TextUnformatted("Open a scene file");
    ImGui::SetNextItemWidth(-60.f);
    ImGui::InputText("##path", path_.data(), path_.size());
    mark("path");
    tip("A scene file's path (JSON), absolute or from the folder the program started in");
    ImGui::SameLine();
    if (ImGui::Button("Open"))
        out_.emplace_back(cmd::OpenFile{std::filesystem::path(path_.data())});
    mark("Open");
    tip("Open the scene file named on the left");
    fileError(s);
    // One line whether or not there are any, so that opening the first file does not move the
    // controls below (a click aimed at one would land on another).
    const auto& recent = s.recentFiles();
    ImGui::BeginDisabled(recent.empty());
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Recent files").x -
                            2.f * ImGui::GetStyle().ItemInnerSpacing.x);
    if (ImGui::BeginCombo("Recent files", recent.empty() ? "(none yet)" : "open again...")) {
        for (const auto& f : recent) {
            if (ImGui::Selectable(f.filename().string().c_str())) {
                copyPath(path_, f);
                out_.emplace_back(cmd::OpenFile{f});
            }
            tip(f.string().c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    mark("Recent files");
}

void ControlPanel::fileError(const Session& s) {
    if (s.fileError().empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, widgets::problem(s.view().theme));
    ImGui::TextWrapped("%s", s.fileError().c_str());
    ImGui::PopStyleColor();
}

void ControlPanel::show(const Session& s, float pixelRatio) {
    const bool open = ImGui::CollapsingHeader("Show", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Show");
    if (!open) return;
    const ViewOptions& v = s.view();
    const auto box = [this](const char* label, bool on, cmd::ShowOption option, const char* help) {
        bool value = on;
        // A label that would run past where the panel clips its content goes on two lines,
        // broken at its middle space.
        std::string shown = label;
        const float clip = ImGui::GetWindowContentRegionMax().x +
                           ImGui::GetStyle().WindowPadding.x / 2.f - ImGui::GetCursorPosX();
        if (widgets::checkWidth(label) > clip) {
            const std::size_t middle = shown.size() / 2;
            const std::size_t before = shown.rfind(' ', middle), after = shown.find(' ', middle);
            const std::size_t at = before == std::string::npos         ? after
                                   : after == std::string::npos        ? before
                                   : middle - before <= after - middle ? before
                                                                       : after;
            if (at != std::string::npos) shown[at] = '\n';
        }
        shown += "###";
        shown += label;
        if (ImGui::Checkbox(shown.c_str(), &value)) out_.emplace_back(cmd::SetShow{option, value});
        mark(label);
        tip(help);
    };
    // Each row's boxes at fixed fractions of the panel where they fit there, else wrapped
    // (widgets::besideIfRoom): at 200 % the panel is narrower in points than at 100 %.
    const float row = ImGui::GetContentRegionAvail().x;
    const auto next = [row](float fraction, const char* label) {
        widgets::besideIfRoom(row * fraction, widgets::checkWidth(label));
    };
    box("Velocity arrows", v.arrows, cmd::ShowOption::Arrows,
        "An arrow from each moving particle to where it will be a moment later (key A)");
    next(0.55f, "Labels");
    box("Labels", v.labels, cmd::ShowOption::Labels,
        "Velocity, momentum and mass written beside each particle (key S)");
    next(0.8f, "y up");
    box("y up", v.yUp, cmd::ShowOption::YUp,
        "Numbers count y upward from the box's floor, vy and momentum up and turning "
        "counterclockwise positive, as in school physics; unticked, y counts down from the "
        "box's top edge, as scene files and the screen do. Kept between runs");
    double arrow = v.arrowSeconds;
    bool dragging = false;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    if (widgets::slider("Arrow scale", arrow, kMinArrowSeconds, kMaxArrowSeconds, "%.3g s",
                        dragging, ImGuiSliderFlags_Logarithmic)) {
        out_.emplace_back(cmd::SetArrowScale{arrow, dragging});
    }
    mark("Arrow scale");
    tip("Each arrow reaches where its particle will be after this much time (and a launch's "
        "drag gives that speed). A scene chooses it when it opens, so that arrows do not hide "
        "the particles, and it does not change by itself after that; set it here");
    box("Momentum and centre of mass", v.momentum, cmd::ShowOption::Momentum,
        "Momentum arrows m v, the total momentum and the centre of mass with its path (key V)");
    box("Plots", v.plots, cmd::ShowOption::Plots,
        "Energy, momentum and the collision rate against time, beside the box (key K)");
    // Beside Plots where the panel is wide enough for both.
    next(0.55f, "Speed histogram");
    box("Speed histogram", v.speeds, cmd::ShowOption::Speeds,
        "How many particles move at each speed, against the Maxwell-Boltzmann curve of a gas "
        "(key D)");
    // Three to a row, two on the next (where the panel is wide enough): the Show section stays
    // short enough that Tools is in an 800-pixel window's first screen.
    box("Values table", v.values, cmd::ShowOption::Values,
        "Every particle's signed position, velocity, momentum and energy, with the totals, in a "
        "window; position, velocity and mass can be typed in (key I)");
    next(0.47f, "Spin");
    box("Spin", v.spin, cmd::ShowOption::Spin,
        "A contrasting quarter of each disc that turns, turning with it: a rolling ball's goes "
        "round, a sliding one's does not. Particles with fixed "
        "rotation have none, and nothing turns without friction or a spin given by hand");
    next(0.74f, "Grid");
    box("Grid", v.grid, cmd::ShowOption::Grid,
        "Lines across the box at a round number of metres, labelled along its top and left "
        "edges (Shift+G)");
    box("Last collision card", v.collision, cmd::ShowOption::Collision,
        "The selected particle's last collision (with none selected, the last between two "
        "particles): velocities, momenta and energy just before and just after, and the momenta "
        "diagram (key J)");
    next(0.64f, "Ruler");
    box("Ruler", v.ruler, cmd::ShowOption::Ruler,
        "A ruler over the box: drag its ends (or its edge to move it) to measure a distance in "
        "metres and a slope in degrees (key Q)");
    if (s.meta().bins) {
        box("Bin counts against the bell curve", v.bins, cmd::ShowOption::Bins,
            "How many balls landed in each bin, against the binomial distribution and the "
            "normal curve the board should give, and whether the difference is more than "
            "chance");
    }
    if (sideColumnFolded(s, controlsWidth(pixelRatio, ImGui::GetIO().DisplaySize.x * pixelRatio))) {
        widgets::wrappedColored(widgets::caution(s.view().theme),
                                "Folded away: the window leaves the charts no room beside the "
                                "box (fold this panel with C, or widen the window)");
    }
    int trails = static_cast<int>(v.trails);
    ImGui::SetNextItemWidth(130.f);
    if (ImGui::Combo("Trails", &trails, "off\0selected particle\0all particles\0")) {
        out_.emplace_back(cmd::SetTrails{trails});
    }
    mark("Trails");
    tip("Draw the path each particle has taken (key L cycles)");
    widgets::sameLineIfRoom(widgets::checkWidth("Light"), 2.f * ImGui::GetStyle().ItemSpacing.x);
    bool light = v.theme == Theme::Light;
    if (ImGui::Checkbox("Light", &light)) {
        out_.emplace_back(cmd::SetTheme{light ? Theme::Light : Theme::Dark});
    }
    mark("theme Light");
    tip(browser_ ? "The light, high-contrast theme for a projector: white background, dark text, "
                   "colours colour-blind viewers tell apart; unticked, light text on black. Kept "
                   "between visits"
                 : "The light, high-contrast theme for a projector: white background, dark text, "
                   "colours colour-blind viewers tell apart; unticked, light text on black (Ctrl+T "
                   "switches). Kept between runs");
    if (ImGui::Button("Fit view")) out_.emplace_back(cmd::Fit{});
    mark("Fit view");
    tip("Zoom and pan so the whole box is in view (key F; the wheel zooms, the right button "
        "pans)");
    ImGui::SameLine();
    if (ImGui::Button("Screenshot")) out_.emplace_back(cmd::Screenshot{});
    mark("Screenshot");
    tip("Save the window as a PNG picture (key F12); the message says where");
    ImGui::SameLine();
    if (ImGui::Button("Keys")) out_.emplace_back(cmd::ToggleHelp{});
    mark("Keys");
    tip("Show every key and where its control is here (key H; Esc closes it)");
    look(s);
}

void ControlPanel::look(const Session& s) {
    const ViewOptions& v = s.view();
    // The scale is applied when the slider is let go: the panel grows under the pointer.
    int percent = scaleHeld_ ? scaleDraft_ : static_cast<int>(std::lround(100.0 * v.uiScale));
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
    if (widgets::sliderInt("UI scale", percent, static_cast<int>(100 * kMinUiScale),
                           static_cast<int>(100 * kMaxUiScale), "%d %%",
                           ImGuiSliderFlags_AlwaysClamp)) {
        scaleDraft_ = percent;
    }
    scaleHeld_ = ImGui::IsItemActive();
    // The panel grows or shrinks about the slider: at the new scale it is scrolled so that the
    // slider stays under the finger (or pointer) that set it, not pushed off the screen.
    const float at = ImGui::GetItemRectMin().y;
    // The panel's points are the scale in use (no more than the window allows).
    const double inUse = v.uiScaleInUse();
    if (keepScaleAt_ && keepScaleAt_->second != inUse) {
        const float target = keepScaleAt_->first / static_cast<float>(inUse);
        ImGui::SetScrollY(ImGui::GetScrollY() + (at - target));
        keepScaleAt_.reset();
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        out_.emplace_back(cmd::SetUiScale{scaleDraft_ / 100.0, false});
        if (std::min(scaleDraft_ / 100.0, v.uiScaleMost) != inUse) {
            keepScaleAt_ = std::pair{at * static_cast<float>(inUse), inUse};
        }
    }
    mark("UI scale");
    const std::string most =
        fmt(". This %s's width allows at most %.0f %%: the panel and its close button stay on "
            "screen",
            browser_ ? "page" : "window", 100.0 * v.uiScaleMost);
    tip(((browser_ ? std::string("The panel, the HUD, the labels and the charts together, 75 % to "
                                 "300 %, the text drawn at its size. Kept between visits")
                   : std::string("The panel, the HUD, the labels and the charts together, 75 % to "
                                 "300 %, the text drawn at its size (Ctrl+plus, Ctrl+minus). Kept "
                                 "between runs")) +
         most)
            .c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(v.uiScaleAutomatic);
    if (ImGui::Button("Auto")) out_.emplace_back(cmd::SetUiScale{v.uiScale, true});
    ImGui::EndDisabled();
    mark("UI scale auto");
    tip(v.uiScaleAutomatic ? "Automatic now: the scale follows the window's height (100 % up to "
                             "899 points, 150 % at 1080)"
        : browser_         ? "Back to the automatic scale, which follows the window's height"
                           : "Back to the automatic scale, which follows the window's height "
                             "(Ctrl+0)");
    // A scale chosen above what the window allows (a phone held upright): said where it is
    // chosen, and kept for a wider window.
    if (v.uiScale > v.uiScaleMost) {
        widgets::wrappedColored(
            widgets::caution(v.theme),
            fmt("Shown at %.0f %%, the most this %s's width allows (%.0f %% is kept for a wider "
                "one)",
                100.0 * v.uiScaleMost, browser_ ? "page" : "window", 100.0 * v.uiScale));
        mark("UI scale most");
    }
}

void ControlPanel::tools(const Session& s, float) {
    const bool open = ImGui::CollapsingHeader("Tools");
    mark("section Tools");
    if (!open) return;
    if (ImGui::Button("Add a random particle")) out_.emplace_back(cmd::SpawnRandom{});
    mark("Add a random particle");
    tip("A particle of random size, colour and velocity somewhere free in the upper half (key M)");
    // A tablet has no mouse: what a finger in the box does (the words elsewhere are a touch
    // screen's too, Notices::key).
    ImGui::TextUnformatted(s.touch() ? "A finger in the box:" : "Left mouse button:");
    const auto radio = [&](const char* label, cmd::Tool t, const char* help) {
        if (ImGui::RadioButton(label, s.tool() == t)) out_.emplace_back(cmd::SetTool{t});
        mark(std::string("tool ") + label);
        tip(help);
    };
    radio("Fling", cmd::Tool::Fling,
          "Drag a particle and let go to throw it; drag on empty space to launch a new one");
    ImGui::SameLine();
    radio("Launch", cmd::Tool::Launch,
          "Every drag launches a new particle: the line you drag is its velocity arrow");
    radio("Select", cmd::Tool::Select,
          "Click a particle to see and edit its values below; drag a wall or peg to move it");
    ImGui::SameLine();
    radio("Pan", cmd::Tool::Pan, "Drag to move the view (the right button always pans)");
    radio("Peg", cmd::Tool::Peg,
          "Click in the box to place a peg: a fixed disc particles bounce off (key B)");
    ImGui::SameLine();
    radio("Wall", cmd::Tool::Wall,
          "Drag in the box to draw a wall from where you press to where you let go (key W)");
    obstacleTools(s);

    const SpawnSettings& sp = s.spawn();
    ImGui::TextUnformatted("New particles:");
    double mass = sp.mass();
    double radius = sp.radius();
    bool autoRadius = !sp.fixedRadius.has_value();
    const Color c = sp.color();
    float colour[3] = {c.r / 255.f, c.g / 255.f, c.b / 255.f};
    bool autoColour = !sp.fixedColor.has_value();
    bool changed = false;
    ImGui::SetNextItemWidth(widgets::fieldWidth(120.f, "mass (kg)"));
    changed |=
        ImGui::InputDouble("mass (kg)", &mass, 0.0, 0.0, "%.3g", ImGuiInputTextFlags_AutoSelectAll);
    mark("launch mass");
    tip("The mass of launched particles ([ and ] make them a tenth of the scene's typical particle "
        "smaller or bigger)");
    ImGui::BeginDisabled(autoRadius);
    ImGui::SetNextItemWidth(widgets::fieldWidth(120.f, "radius (m)"));
    changed |= ImGui::InputDouble("radius (m)", &radius, 0.0, 0.0, "%.3g",
                                  ImGuiInputTextFlags_AutoSelectAll);
    mark("launch radius");
    ImGui::EndDisabled();
    tip("The radius of launched particles; untick 'auto' to choose it");
    widgets::sameLineIfRoom(widgets::checkWidth("auto"));
    changed |= ImGui::Checkbox("auto", &autoRadius);
    mark("auto radius");
    tip("Auto: the radius grows with the mass, at the scene's scale");
    ImGui::BeginDisabled(autoColour);
    changed |= ImGui::ColorEdit3("colour", colour, ImGuiColorEditFlags_NoInputs);
    mark("launch colour");
    ImGui::EndDisabled();
    tip("The colour of launched particles");
    ImGui::SameLine();
    changed |= ImGui::Checkbox("auto##colour", &autoColour);
    mark("auto colour");
    tip("Auto: a colour from the mass, light blue for light, pink for heavy");
    // A radius being typed passes through 0 ("0.2"): nothing is sent until it is positive (0
    // would mean "from the mass", and would grey the field out under the typing hand).
    if (!autoRadius && !(radius > 0.0)) changed = false;
    if (changed) {
        cmd::SetLaunchBody b;
        b.mass = mass;
        b.radius = autoRadius ? 0.0 : radius;
        if (!autoColour) {
            const auto ch = [](float f) {
                return static_cast<std::uint8_t>(std::clamp(std::lround(f * 255.f), 0L, 255L));
            };
            b.color = Color{ch(colour[0]), ch(colour[1]), ch(colour[2])};
        }
        out_.emplace_back(b);
    }
    if (s.interaction().mode() == Interaction::Mode::Launching) {
        const CappedVelocity v = s.launchPreview();
        // In m/s, as the particle's vx and vy are: one unit for one quantity.
        ImGui::Text("Launching at %s%s", quantity(v.velocity.norm(), "m/s", false).c_str(),
                    v.capped ? " (the most allowed)" : "");
    }
}

void ControlPanel::launchPreview(const Session& s, float pixelRatio) {
    // A disc at the cursor the size and colour of the particle a launch would make.
    const bool launchTool = s.tool() == cmd::Tool::Launch || s.tool() == cmd::Tool::Fling;
    if (!launchTool || ImGui::GetIO().WantCaptureMouse ||
        s.interaction().mode() != Interaction::Mode::Idle || !ImGui::IsMousePosValid()) {
        return;
    }
    const ImVec2 m = ImGui::GetMousePos();
    const Vec2 world = s.camera().screenToWorld(Vec2(m.x * pixelRatio, m.y * pixelRatio));
    if (s.tool() == cmd::Tool::Fling && s.world().pick(world)) return;  // it would grab
    const WorldDef& box = s.world().def();
    const bool outside =
        world.x() < 0.0 || world.y() < 0.0 || world.x() > box.width || world.y() > box.height;
    if (box.walls && outside) return;  // no particle is made out there
    const float r = static_cast<float>(s.camera().toScreen(s.spawn().radius())) / pixelRatio;
    if (!(r >= 1.f) || r > 4000.f) return;
    const Color c = s.spawn().color();
    ImGui::GetBackgroundDrawList()->AddCircle(m, r, IM_COL32(c.r, c.g, c.b, 200), 0, 1.5f);
}

}  // namespace psb::app
