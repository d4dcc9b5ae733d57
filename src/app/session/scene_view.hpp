#pragma once
// How the session's scene is seen: the camera (the only place screen and world coordinates
// meet: camera.hpp), the box fitted into the area the view lays out for it (box_area.hpp), what
// is shown (view_options.hpp), the help and whether the control panel is open. Its commands
// move the camera, switch what is shown and fit the box again when that changes the area it
// has.

#include <cstddef>
#include <string>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/scene_info.hpp>
#include <particle_sandbox/world.hpp>

#include "session/box_area.hpp"
#include "session/camera.hpp"
#include "session/command.hpp"
#include "session/view_options.hpp"

namespace psb::app {

struct Document;
struct Instruments;
class Notices;
struct SessionOptions;
struct Tools;

class SceneView {
  public:
    explicit SceneView(const SessionOptions& options);

    /// What the view's commands reach beyond it: the box to fit (the document's world and its
    /// bins), the hand that follows the camera (the tools), and the instruments a show option
    /// switches (the ruler, the collision card).
    struct Context {
        Document& doc;
        Tools& tools;
        Instruments& instruments;
        Notices& notices;
    };
    void handle(const cmd::Pan& c, Context& x);
    void handle(const cmd::Zoom& c, Context& x);
    void handle(const cmd::Fit& c, Context& x);
    void handle(const cmd::Resize& c, Context& x);
    void handle(const cmd::ToggleHelp& c, Context& x);
    void handle(const cmd::SetShow& c, Context& x);
    void handle(const cmd::SetTrails& c, Context& x);
    void handle(const cmd::SetArrowScale& c, Context& x);
    void handle(const cmd::SetUiScale& c, Context& x);
    void handle(const cmd::FitUiScale& c, Context& x);
    void handle(const cmd::SetTheme& c, Context& x);
    void handle(const cmd::ToggleControls& c, Context& x);

    [[nodiscard]] const Camera& camera() const { return camera_; }
    [[nodiscard]] const ViewOptions& options() const { return options_; }
    /// The axes numbers are shown and typed in (the y up option, the box's height).
    [[nodiscard]] Axes axes(const WorldDef& def) const { return options_.axes(def); }
    [[nodiscard]] bool helpShown() const { return help_; }
    /// The page of the help shown (H turns the page, and closes it after the last).
    [[nodiscard]] std::size_t helpPage() const { return helpPage_; }
    /// The control panel is open (else folded to a strip).
    [[nodiscard]] bool controlsShown() const { return controls_; }
    /// Where the box may go in the window, as the app sent it last.
    [[nodiscard]] const WindowLayout& layout() const { return layout_; }
    /// Where the values table docks (I): where it left the box largest when the box was last
    /// fitted (BoxArea).
    [[nodiscard]] const ValuesDock& valuesDock() const { return valuesDock_; }
    /// The side column's charts are folded away so that the box keeps its share of the window
    /// (fit; the values table's dock at the right folds them as well: box_area.hpp's
    /// sideColumnFolded).
    [[nodiscard]] bool columnFolded() const { return columnFolded_; }
    /// The side column's charts go in a band under the box instead (fit: a column beside a
    /// wide, low box would leave it less than its share; BoxArea::chartsBand).
    [[nodiscard]] bool chartsBelow() const { return chartsBelow_; }
    /// The view is as Fit left it (a resize fits again).
    [[nodiscard]] bool fitted() const { return fitted_; }
    /// The bins panel is drawn: the scene (`meta`) has bins and the view shows them.
    [[nodiscard]] bool binsShown(const SceneInfo& meta) const;
    /// Whether a panel of the side column (plots, histograms, profile) is on.
    [[nodiscard]] bool columnAsked(const SceneInfo& meta) const;
    /// The overlays that are on, for the HUD ("V L:all K D"); empty when none.
    [[nodiscard]] std::string overlayFlags() const;

    /// Fits the document's box into the area the view left it beside the panels as they are,
    /// saying so in the log.
    void fit(const Document& doc, Notices& notices);
    /// A new scene, `world`: its arrows get their own scale.
    void startOver(const World& world);
    /// The Pan tool's drag: the world slides by `pixels`, the box kept near the window.
    void drag(const Vec2& pixels, const WorldDef& box);
    /// Shows `mode`'s trails (a scene that marks particles' trails opens with them shown).
    void showTrails(TrailMode mode) { options_.trails = mode; }
    /// Esc: closes the help.
    void closeHelp() { help_ = false; }

  private:
    /// The hand did not move but the world under it did: the held particle follows the cursor.
    void afterCameraMove(Tools& tools);

    bool inPage_ = false;  ///< SessionOptions::inPage: the messages name the page's keys
    Camera camera_;
    bool fitted_ = true;
    WindowLayout layout_;
    ValuesDock valuesDock_;
    bool columnFolded_ = false;
    bool chartsBelow_ = false;
    ViewOptions options_;
    bool help_ = false;
    std::size_t helpPage_ = 0;
    bool controls_ = true;
};

}  // namespace psb::app
