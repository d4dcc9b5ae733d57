#pragma once
// The on-screen control panel (Dear ImGui): a column at the left of the window, beside the box
// (view/box_area.hpp keeps it out of the box's area), with collapsible sections
//
//   Time       play / pause, one step, time speed, restart
//   Scene      presets with a line on each, new scene, title and description, the file with
//              Save, Save As and Revert, open with a path field, recent files
//   Physics    stepping mode (and why one is unavailable), restitution, friction, gravity, walls
//   Show       arrows, labels, momentum and centre of mass, trails, plots, speed histogram
//   Tools      what the left mouse does; what a launched particle is made of; obstacle sizes
//   Readouts   time, particles, energies, momentum, accuracy in words
//   Data       record the particles' paths and collisions; export or copy each table
//   Selected   the selected particle's values, editable in place
//   All particles   a table, for scenes of up to kTableMaxParticles
//   Engine     frame times, broadphase, threads, per-stage profile (closed at first)
//
// It only reads the session and returns Commands (the same ones keys make); the app applies them
// with Session::apply, so a button and its key are one path. Folded (button or key C), it is a
// narrow strip with one button that opens it again.
//
// The panel's pieces are in control_panel.cpp (the window, time, scene, show, tools), one file
// per section after that: section_scene_file.cpp (the scene's text and file),
// section_dialogs.cpp (Save As, New scene, the quit question), section_obstacles.cpp (the obstacle
// tools' sizes, removing an obstacle), section_physics.cpp, section_readouts.cpp (readouts,
// engine), section_data.cpp (recording, exports) and section_particles.cpp (selected, all
// particles); widgets.hpp holds the small widgets they share.

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "session/command.hpp"
#include "view/box_area.hpp"
#include "view/frame_view.hpp"
#include "view/soft_wrap.hpp"

namespace psb::app {

class Session;
struct CollisionCard;
struct CollisionCardText;

/// The panel's width open and folded, window points (pixels at a pixel ratio of 1); open, the
/// most (controlsOpenPoints).
inline constexpr float kControlsWidth = 310.f;
/// The least the open panel narrows to, points: its rows of buttons and its sliders with their
/// names still fit; its sentences wrap. No UI scale makes a window narrower than this
/// (session/view_options.hpp, mostUiScale).
inline constexpr float kControlsMinWidth = static_cast<float>(kPanelLeastPoints);
/// On a touch screen the least height of a button, a check box or a section header, window
/// points (CSS pixels in a page): a finger's target (about 7 mm on a phone or a tablet).
inline constexpr float kTouchTargetPoints = 40.f;
/// The most of the window's width the open panel takes as the UI grows: at 200 % in a
/// 1600-pixel window the full panel took 39 % of it, and beside the plots the box kept 510
/// pixels.
inline constexpr float kControlsMaxShare = 0.3f;
/// Folded, the strip holds the ">>" button (and a page's "?") inside kControlsFoldedPadding
/// either side: over 40 points wide, a finger's target on a touch screen (kTouchTargetPoints;
/// 44 points with 6 either side made a phone's 31 CSS pixels wide).
inline constexpr float kControlsFoldedWidth = 46.f;
inline constexpr float kControlsFoldedPadding = 2.f;

/// The open panel's width, points, in a window `windowPixels` wide at `pixelRatio` pixels per
/// point (the UI's scale): kControlsWidth at 100 %; as the scale grows, no more than
/// kControlsMaxShare of the window, but never narrower on screen than at 100 % (310 pixels)
/// nor than kControlsMinWidth points. At 200 % in 1600 pixels: 240 points, 480 pixels.
[[nodiscard]] inline float controlsOpenPoints(double windowPixels, double pixelRatio) {
    const double ratio = pixelRatio > 0.0 ? pixelRatio : 1.0;
    const double least = std::max<double>(kControlsMinWidth, kControlsWidth / ratio);
    return static_cast<float>(std::clamp(kControlsMaxShare * windowPixels / ratio,
                                         std::min<double>(least, kControlsWidth),
                                         static_cast<double>(kControlsWidth)));
}

/// The panel's width open and folded, pixels, at `pixelRatio` pixels per point in a window
/// `windowPixels` wide: what the view keeps free for it at the window's left.
[[nodiscard]] inline ControlsWidth controlsWidth(double pixelRatio, double windowPixels) {
    return {controlsOpenPoints(windowPixels, pixelRatio) * pixelRatio,
            kControlsFoldedWidth * pixelRatio, pixelRatio};
}

/// Scenes with more particles than this get no all-particles table.
inline constexpr std::size_t kTableMaxParticles = 60;

/// Where a control was drawn in the last frame, window points: for tests and scripted input
/// (--log-controls), which find a control by its name.
struct PanelItem {
    std::string name;
    float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
    unsigned id = 0;  ///< ImGui's identity of the item (ImGuiID), which its keyboard cursor holds
};

class ControlPanel {
  public:
    /// Builds the panel into the current ImGui frame (between GuiContext::beginFrame and
    /// endFrame) for a display `height` points high, `pixelRatio` pixels per point; returns what
    /// its controls asked for this frame.
    std::vector<Command> build(const Session& session, const FrameStats& stats, float height,
                               float pixelRatio);

    /// The named controls of the last build, in drawing order.
    [[nodiscard]] const std::vector<PanelItem>& items() const { return items_; }
    /// What the status lines of the last build said (where a file went), as (name, words).
    [[nodiscard]] const std::vector<std::pair<std::string, std::string>>& statusLines() const {
        return status_;
    }
    /// The item called `name` in the last build, or nullptr.
    [[nodiscard]] const PanelItem* item(const std::string& name) const;

    /// In a browser the user's files have no path the page can read: Open asks the browser's
    /// file chooser instead of reading the path field (the app asks, see takeUploadRequest),
    /// and recent files are not listed. Video recording (FFmpeg) is not there: no Video section.
    void setBrowser(bool on) { browser_ = on; }
    /// Whether Open was pressed in browser mode since the last call.
    [[nodiscard]] bool takeUploadRequest() { return std::exchange(uploadAsked_, false); }
    /// Whether the page's About was pressed (browser mode) since the last call.
    [[nodiscard]] bool takeAboutRequest() { return std::exchange(aboutAsked_, false); }
    /// A finger is on the panel (GuiContext::fingerOnPanel), its tap or press not yet done:
    /// nothing above what it came down on may change height until it lifts (the collision card
    /// growing a line moved "Add a random particle" under a tap meant for the panel). The card
    /// keeps the height it had when the finger came down (taller content is clipped, shorter
    /// is padded) until then. A mouse button held over the panel holds it too.
    void holdLayout(bool held) { fingerHeld_ = held; }

  private:
    /// A finger or a mouse button is down on the panel (holdLayout, or within the panel's
    /// window): what comes and goes above the controls keeps its room until the lift.
    [[nodiscard]] bool layoutHeld() const;
    /// On a touch screen the frame padding that makes a button, a check box, a field or a
    /// section header kTouchTargetPoints high at the UI's scale `scale` (the panel's and the
    /// dialogs' controls alike).
    [[nodiscard]] static ImVec2 touchPadding(float scale);
    /// Records the item just drawn as `name`; a status line with what it says.
    void mark(const std::string& name, std::string text = {});
    /// The page's About button (browser mode), `size` as ImGui::Button's.
    void aboutButton(const char* label, ImVec2 size);
    void time(const Session& s);
    void scene(const Session& s);
    /// The scene's title and description, editable (section_scene_file.cpp).
    void sceneText(const Session& s);
    /// The scene's file, unsaved changes, Save, Save As, Revert (section_scene_file.cpp).
    void sceneFile(const Session& s);
    /// The last open or save problem, in red (nothing when there is none).
    void fileError(const Session& s);
    /// The dialog the session has open, as a modal window (section_dialogs.cpp).
    void dialog(const Session& s);
    /// The open dialog's modal window (dialog() has its fields' first values).
    void modal(const Session& s);
    /// A dialog's line of `keys` (Enter, Esc), marked "dialog keys"; none on a touch screen.
    void keysLine(const Session& s, const char* keys);
    void physics(const Session& s);
    /// The stopwatch's row in the Time section.
    void stopwatch(const Session& s);
    void show(const Session& s, float pixelRatio);
    /// The Show section's UI scale and theme.
    void look(const Session& s);
    void tools(const Session& s, float pixelRatio);
    /// The obstacle tools' sizes and the selected obstacle's Delete button (section_obstacles.cpp).
    void obstacleTools(const Session& s);
    void readouts(const Session& s);
    /// The gas instruments' pressure plot, under the readouts (section_readouts.cpp).
    void pressurePlot(const Session& s);
    /// The last collision card, while it is shown (section_collision.cpp).
    void lastCollision(const Session& s);
    void card(const Session& s);
    /// The card's rows one above the other, where before and after do not fit side by side:
    /// each quantity's name, then its value before and after, each on a line.
    void stackedCard(const CollisionCardText& text);
    /// The momenta diagram under the card (view/momenta_diagram.hpp).
    /// `colours`: particle 1's, particle 2's and the total's arrows' (momentaColours).
    void momenta(const CollisionCard& card, const std::array<Color, 3>& colours);
    /// The values table's window, while shown (section_values.cpp), docked in its band at
    /// `pointPixels` pixels per point of the UI.
    void valuesWindow(const Session& s, float pointPixels);
    /// Recording, and the tables' Export and Copy buttons (section_data.cpp).
    void data(const Session& s);
    /// Video recording: format, area, Record / Stop, where the last one went (section_video.cpp).
    void video(const Session& s, const VideoStatus& status);
    void engine(const Session& s, const FrameStats& stats);
    void selected(const Session& s);
    /// The Selected particle section's content (section_particles.cpp).
    void selectedValues(const Session& s, const std::optional<Particle>& p);
    void allParticles(const Session& s);
    void launchPreview(const Session& s, float pixelRatio);

    std::vector<Command> out_;
    std::vector<PanelItem> items_;
    std::vector<std::pair<std::string, std::string>> status_;
    std::array<char, 512> path_{};
    bool pathFilled_ = false;
    bool browser_ = false;
    bool touch_ = false;       ///< the session's hands are on a touch screen (this build)
    float touchWidth_ = 0.f;   ///< on a touch screen, a small button's least width, points
    bool fingerHeld_ = false;  ///< holdLayout
    /// The card's height (points) while the layout is held, from the frame the hold began.
    std::optional<float> heldCardHeight_;
    /// Whether the Speed slider's "Reaching only" line had its room when the hold began.
    std::optional<bool> slowLineHeld_;
    bool uploadAsked_ = false;
    bool aboutAsked_ = false;
    /// The title and description while they are typed in (else the scene's).
    std::array<char, 128> title_{};
    std::array<char, 2048> description_{};
    bool titleActive_ = false, descriptionActive_ = false;
    /// The dialog's fields while it is open: the name to save as, the new scene's box.
    std::array<char, 512> saveName_{};
    double newWidth_ = 10.0, newHeight_ = 10.0, newGravity_ = 0.0;
    bool newWalls_ = true;
    int shownDialog_ = 0;  ///< the Dialog::Kind the fields were filled for
    int substeps_ = 4;
    /// The UI scale slider while it is held (percent): applied when let go.
    int scaleDraft_ = 100;
    bool scaleHeld_ = false;
    /// Where the UI scale's slider was when a new scale was set, window points from the top,
    /// and the scale it was drawn at: the panel scrolls to keep it there at the new scale.
    std::optional<std::pair<float, double>> keepScaleAt_;
    /// The Data section: the file name typed for Export, steps between trajectory samples.
    std::array<char, 512> exportName_{};
    int recordEvery_ = 0;
    /// The particle the Selected particle section last showed: a new selection scrolls the
    /// panel to the section once (it is below the fold of an 800-pixel window).
    ParticleId shownSelection_;
    /// The last collision card was shown last frame (turned on, its section opens).
    bool cardShown_ = false;
    /// The shown card's collision's time last frame (none: no collision on it), whether the
    /// card changed this frame (a collision, or R clearing it) and where its section's items
    /// end in items_: with the pointer elsewhere, the controls below the card stay put as it
    /// changes (keepAnchor).
    std::optional<double> cardSeen_;
    bool cardChanged_ = false;
    int cardSettling_ = 0;
    std::size_t afterCard_ = 0;
    /// What the pointer was over in the panel last frame (its name and top, window points) and
    /// the panel's scroll then: when the layout above it moves it on its own (a collision card
    /// that grows, a line that appears), the panel scrolls by as much, so that it stays under
    /// the pointer (keepAnchor). With the pointer elsewhere, the controls below the collision
    /// card shown whole, from the top down: the first of them still there stays put when the
    /// card changes.
    std::vector<std::pair<std::string, float>> anchors_;
    float anchorScroll_ = 0.f;
    float slack_ = 0.f;  ///< blank room at the panel's end that the anchored scroll needs
    void keepAnchor(std::size_t firstItem);
    /// The values table's cell being typed in (its particle and field) and its text.
    std::optional<std::pair<ParticleId, ParticleField>> valuesEditing_;
    std::array<char, 64> valuesText_{};
    /// The values window's size in points when its table was last laid out (its scroll starts
    /// over when that changes).
    std::pair<float, float> valuesLaidOut_{0.f, 0.f};
    /// The selected particle's table: each field's text while it is typed in.
    std::array<std::array<char, 40>, 8> fieldText_{};
    std::array<bool, 8> fieldActive_{};
    /// The scene's description is being edited (else shown wrapped), and its field is to take
    /// the keyboard.
    bool descriptionEditing_ = false, focusDescription_ = false;
    /// The description's field wraps its lines as they are typed (soft breaks); description_
    /// holds them while the field is open.
    SoftWrap descriptionWrap_;
    /// The particle the Selected particle fields were typed for (the selection may change
    /// before the typed text is applied).
    ParticleId fieldOwner_ = kNullParticle;
};

}  // namespace psb::app
