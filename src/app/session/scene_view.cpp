// How the scene is seen: the camera (pan, zoom, the box fitted into the area the view lays out
// for it: box_area.hpp) and what is shown, with the toggles that change which area that is.

#include "session/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "session/document.hpp"
#include "session/instruments.hpp"
#include "session/notices.hpp"
#include "session/session_options.hpp"
#include "session/session_text.hpp"
#include "session/tools.hpp"

namespace psb::app {

namespace {

/// The share of its size the box gives up, at most, for the values table's band to show every
/// particle's row (SceneView::fit).
constexpr double kValuesRowsBoxShare = 2.0 / 3.0;

}  // namespace

SceneView::SceneView(const SessionOptions& options)
    : inPage_(options.inPage), layout_(options.layout), controls_(options.controls) {
    camera_.setViewport(options.viewportWidth, options.viewportHeight);
    options_.arrows = options.arrows;
}

bool SceneView::binsShown(const SceneInfo& meta) const {
    return meta.bins.has_value() && options_.bins;
}

bool SceneView::columnAsked(const SceneInfo& meta) const {
    return options_.plots || options_.speeds || options_.profile || binsShown(meta);
}

void SceneView::fit(const Document& doc, Notices& notices) {
    // The area the view left the box beside the panels as they are now.
    const BoxArea& a = layout_.area(controls_, columnAsked(doc.meta));
    const double w = doc.world.def().width, h = doc.world.def().height, margin = 10.0;
    // The values table docks where the box comes out largest: along the bottom with its rows,
    // with fewer rows (the rest scroll), or at the right. Among places within 2 % of the
    // largest the first is kept: a band of rows reads best; and one that shows every
    // particle's row is kept at some cost (kValuesRowsBoxShare).
    std::vector<ValuesDock> docks;
    if (options_.values) {
        docks.push_back({false, a.valuesBand});
        for (double band = a.valuesBand - a.valuesRow;
             a.valuesRow > 0.0 && band >= a.valuesLeast - a.valuesRow / 2.0; band -= a.valuesRow) {
            docks.push_back({false, band});
        }
        if (a.valuesColumn > 0.0) docks.push_back({true, a.valuesColumn});
    }
    if (docks.empty()) docks.push_back({});
    const auto fitWith = [&](const ValuesDock& d) {
        // The table's column takes the side column's place (its charts fold away).
        double right = d.right ? d.size : a.right;
        const double bottom = a.bottom + (d.right ? 0.0 : d.size);
        if (a.spareColumn > 0.0 && !d.right) {
            // A box that the window's height limits may leave width to spare: when it leaves
            // the inspector's whole column, the box moves left, keeps its size, and the
            // inspector (bottom right, on a click) does not cover it. Less room would only move
            // the box off centre and still leave it covered.
            camera_.fit(w, h, margin, a.top, bottom, right, a.left);
            const double spare =
                camera_.viewportWidth() - a.left - right - camera_.toScreen(w) - 2.0 * margin;
            if (spare >= a.spareColumn) right += a.spareColumn;
        }
        camera_.fit(w, h, margin, a.top, bottom, right, a.left);
        // The zoom the area itself allows: the camera gives up insets in a window too small
        // for them (the box then runs under a panel), which must not make a place look good.
        const double usableW = camera_.viewportWidth() - a.left - right - 2.0 * margin;
        const double usableH = camera_.viewportHeight() - a.top - bottom - 2.0 * margin;
        return std::max(0.0, std::min(usableW / w, usableH / h));
    };
    std::vector<double> zooms;
    for (const ValuesDock& d : docks)
        zooms.push_back(fitWith(d));
    // A band that shows every particle's row (as many as the full band holds) is kept over a
    // shorter one unless the box would lose more than a third of its size for it: a lesson's
    // two balls and their total behind a scroll bar, for a box 5 % larger, read worse.
    const auto rowsOf = [&](const ValuesDock& d) {
        return a.valuesRow > 0.0 ? std::floor((d.size - a.valuesLeast) / a.valuesRow + 1e-6) + 1.0
                                 : 0.0;
    };
    const double wanted =
        std::min(std::max(static_cast<double>(doc.world.size()), 1.0), rowsOf(docks[0]));
    const auto showsAll = [&](const ValuesDock& d) {
        return !options_.values || d.right || a.valuesRow <= 0.0 || rowsOf(d) >= wanted;
    };
    double best = *std::max_element(zooms.begin(), zooms.end());
    double bestShowingAll = 0.0;
    for (std::size_t k = 0; k < docks.size(); ++k)
        if (showsAll(docks[k])) bestShowingAll = std::max(bestShowingAll, zooms[k]);
    const bool keepRows = bestShowingAll >= kValuesRowsBoxShare * best;
    if (keepRows) best = bestShowingAll;
    std::size_t chosen = 0;
    while (zooms[chosen] < 0.98 * best || (keepRows && !showsAll(docks[chosen])))
        ++chosen;
    valuesDock_ = options_.values ? docks[chosen] : ValuesDock{};
    fitWith(docks[chosen]);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    notices.log(fmt("View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px", camera_.zoom(),
                    topLeft.x(), topLeft.y()));
    fitted_ = true;
}

void SceneView::handle(const cmd::Resize& c, Context& x) {
    const bool sized = c.width != camera_.viewportWidth() || c.height != camera_.viewportHeight();
    if (!sized && c.layout == layout_) return;
    // A window made too narrow for the box beside the open control panel folds it (C opens it
    // again, over the box).
    const bool fold = controls_ && layout_.controlsFit && !c.layout.controlsFit;
    layout_ = c.layout;
    if (fold) {
        controls_ = false;
        x.notices.say(
            "The control panel folded: the window leaves the box no room beside it (C or >> "
            "opens it over the box)");
    }
    // A fitted view stays fitted; a view the user moved keeps its centre where it was.
    const Vec2 centre =
        camera_.screenToWorld(Vec2(camera_.viewportWidth() / 2.0, camera_.viewportHeight() / 2.0));
    camera_.setViewport(c.width, c.height);
    if (fitted_) {
        fit(x.doc, x.notices);
    } else if (sized) {
        camera_.set(camera_.zoom(), centre - Vec2(c.width / 2.0, c.height / 2.0) / camera_.zoom());
    }
}

void SceneView::startOver(const World& world) {
    options_.arrowSeconds = arrowSecondsFor(world);
    options_.arrowScaleSet = false;
}

void SceneView::drag(const Vec2& pixels, const WorldDef& box) {
    camera_.panPixels(pixels);
    camera_.keepNear(box.width, box.height);
    fitted_ = false;
}

void SceneView::afterCameraMove(Tools& tools) {
    fitted_ = false;
    if (tools.hand.mode() != Interaction::Mode::Idle) {
        tools.hand.moveTo(tools.pointerWorld(camera_), tools.pointerTime);
    }
}

void SceneView::handle(const cmd::Pan& c, Context& x) {
    camera_.panPixels(c.pixels);
    camera_.keepNear(x.doc.world.def().width, x.doc.world.def().height);
    afterCameraMove(x.tools);
}

void SceneView::handle(const cmd::Zoom& c, Context& x) {
    camera_.zoomAbout(c.screen, c.factor);
    x.notices.log(
        fmt("Zoom %.4f px/m about [%.0f, %.0f]", camera_.zoom(), c.screen.x(), c.screen.y()));
    afterCameraMove(x.tools);
}

void SceneView::handle(const cmd::Fit&, Context& x) {
    fit(x.doc, x.notices);
    afterCameraMove(x.tools);
    fitted_ = true;
}

void SceneView::handle(const cmd::ToggleHelp&, Context&) {
    const int pages = layout_.helpPages;
    if (!help_) {
        help_ = true;
        helpPage_ = 0;
    } else if (static_cast<int>(helpPage_) + 1 < pages) {
        ++helpPage_;
    } else {
        help_ = false;
    }
}

void SceneView::handle(const cmd::SetShow& c, Context& x) {
    bool& flag = options_.flag(c.option);
    if (flag == c.on) return;
    flag = c.on;
    x.notices.say(showMessage(c.option, c.on));
    x.instruments.shown(c.option, c.on, x.doc, x.tools.selection.id());
    // The side column's panels and the values table's band change what the box is fitted
    // beside.
    using O = cmd::ShowOption;
    if (fitted_ && (c.option == O::Plots || c.option == O::Speeds || c.option == O::Profile ||
                    c.option == O::Bins || c.option == O::Values)) {
        fit(x.doc, x.notices);
    }
}

void SceneView::handle(const cmd::SetArrowScale& c, Context& x) {
    if (!(c.seconds >= kMinArrowSeconds && c.seconds <= kMaxArrowSeconds)) {
        x.notices.say(fmt("The arrow scale must be %g s to %g s of motion, got %g",
                          kMinArrowSeconds, kMaxArrowSeconds, c.seconds),
                      Notice::Level::Warning);
        return;
    }
    options_.arrowSeconds = c.seconds;
    options_.arrowScaleSet = true;
    x.notices.add({Notice::Level::Info,
                   fmt("Arrows: %.3g s of motion, kept until a scene opens", c.seconds), true,
                   !c.continues, "arrow scale"});
}

void SceneView::handle(const cmd::SetUiScale& c, Context& x) {
    if (!(c.scale >= kMinUiScale && c.scale <= kMaxUiScale)) {
        x.notices.say(fmt("The UI scale must be %.0f %% to %.0f %%, got %g %%", 100.0 * kMinUiScale,
                          100.0 * kMaxUiScale, 100.0 * c.scale),
                      Notice::Level::Warning);
        return;
    }
    if (c.scale == options_.uiScale && c.automatic == options_.uiScaleAutomatic) return;
    const bool said = c.scale != options_.uiScale || !c.automatic;
    options_.uiScale = c.scale;
    options_.uiScaleAutomatic = c.automatic;
    // The automatic scale follows the window by itself: a resize says nothing.
    if (said) {
        x.notices.add({Notice::Level::Info,
                       fmt("UI scale %.0f %%%s", 100.0 * c.scale,
                           c.automatic ? (inPage_ ? " (automatic: by the page's height)"
                                                  : " (automatic: by the window's "
                                                    "height; Ctrl+0)")
                           : inPage_   ? " (Show: Auto makes it automatic)"
                                       : " (Ctrl+0: automatic)"),
                       true, true, "ui scale"});
    }
}

void SceneView::handle(const cmd::SetTheme& c, Context& x) {
    if (c.theme == options_.theme) return;
    options_.theme = c.theme;
    // The browser keeps Ctrl+T for a new tab.
    const char* key = inPage_ ? "" : "; Ctrl+T";
    x.notices.say(c.theme == Theme::Light
                      ? fmt("Theme: light (high contrast, for projectors%s)", key)
                      : fmt("Theme: dark%s", inPage_ ? "" : " (Ctrl+T)"));
}

void SceneView::handle(const cmd::SetTrails& c, Context& x) {
    const auto mode = static_cast<TrailMode>(std::clamp(c.mode, 0, 2));
    if (mode == options_.trails) return;
    options_.trails = mode;
    x.notices.say(std::string("Trails: ") + toString(options_.trails));
}

void SceneView::handle(const cmd::ToggleControls&, Context& x) {
    controls_ = !controls_;
    if (controls_ && !layout_.controlsFit) {
        x.notices.say("The control panel covers the box in this narrow window: C or << folds it");
    }
    if (fitted_) fit(x.doc, x.notices);
}

std::string SceneView::overlayFlags() const {
    std::string f;
    const auto add = [&f](const std::string& s) { f += (f.empty() ? "" : " ") + s; };
    if (options_.momentum) add("V");
    if (options_.trails != TrailMode::Off) add(std::string("L:") + toString(options_.trails));
    if (options_.plots) add("K");
    if (options_.speeds) add("D");
    return f;
}

}  // namespace psb::app
