// How the scene is seen: the camera (pan, zoom, the box fitted into the area the view lays out
// for it: box_area.hpp) and what is shown, with the toggles that change which area that is.

#include "session/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "session/document.hpp"
#include "session/instruments.hpp"
#include "session/notices.hpp"
#include "session/session_options.hpp"
#include "session/session_text.hpp"
#include "session/tools.hpp"

namespace psb::app {

namespace {

/// The share of its size (its zoom) the box keeps of what it has beside the control panel, the
/// HUD and the messages alone, when the values table or the side column's charts are shown
/// (SceneView::fit): at 200 % in 1600 x 1000 the ramp's box was 200 pixels high under the
/// table's three rows, the momentum lesson's 205 beside the plots.
constexpr double kBoxKeeps = 0.6;
/// ...unless its smaller side keeps this share of the window's smaller side, which is enough.
constexpr double kBoxEnough = 0.4;
/// Before anything is hidden (the side column's charts folded away, the values table in a
/// column at the right, narrower than its columns), the box gives up to this share of its size:
/// at 200 % in 1600 x 1000 the momentum lesson's plots folded away and its table, at the right,
/// showed x, y and vx only, for a box 1.1 times as large as the 512 x 205 that shows them all.
constexpr double kBoxKeepsBeforeHiding = 0.5;

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
    const bool asked = columnAsked(doc.meta);
    const double w = doc.world.def().width, h = doc.world.def().height, margin = 10.0;
    // The box fitted into `a` with the values table docked as `d` (size 0: not shown); returns
    // the zoom the area itself allows.
    const auto fitWith = [&](const BoxArea& a, const ValuesDock& d) {
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
    // The share the box keeps (kBoxKeeps) is of its size beside the control panel, the HUD and
    // the messages alone: neither the side column nor the values table.
    const BoxArea& bare = layout_.area(controls_, false);
    // ...or, where that share is more than a box needs (a tall window's square box beside the
    // plots), a smaller side of kBoxEnough of the window's.
    const double enough =
        kBoxEnough * std::min(camera_.viewportWidth(), camera_.viewportHeight()) / std::min(w, h);
    const double share = std::min(kBoxKeeps * fitWith(bare, {}), enough);
    // The side column's charts folded away: the box's area loses the column and the HUD's band
    // keeps the line that says so.
    BoxArea folded = bare;
    folded.top = std::max(bare.top, bare.foldedTop);
    // A choice: the area, the table's dock, whether the charts fold, the zoom it gives.
    struct Choice {
        const BoxArea* area;
        ValuesDock dock;
        bool fold = false;
        double zoom = 0.0;
        bool below = false;  ///< the charts in a band under the box
        /// Something asked for is not seen whole: the charts fold away, or the table's column
        /// is narrower than its columns.
        bool hides = false;
    };
    std::vector<Choice> tried;
    const auto tryBands = [&](const BoxArea& a, bool fold) {
        if (!options_.values) {
            tried.push_back({&a, {}, fold, fitWith(a, {}), false, fold});
            return;
        }
        // The band with its rows, then with a row fewer each time (the others scroll), down to
        // one.
        tried.push_back(
            {&a, {false, a.valuesBand}, fold, fitWith(a, {false, a.valuesBand}), false, fold});
        // A band that holds fewer rows than the table has hides some (they scroll).
        const double rows = static_cast<double>(doc.world.size());
        for (double band = a.valuesBand - a.valuesRow, fewer = 1.0;
             a.valuesRow > 0.0 && band >= a.valuesLeast - a.valuesRow / 2.0;
             band -= a.valuesRow, fewer += 1.0) {
            tried.push_back({&a,
                             {false, band},
                             fold,
                             fitWith(a, {false, band}),
                             false,
                             fold || a.valuesRows - fewer < rows});
        }
    };
    // What gives way, in order, until the box keeps its share: the values table's band its
    // rows (they scroll), then the side column its charts, then the table docks at the right in
    // the side column's place. Where nothing leaves it that share, the largest box wins.
    const BoxArea& a = layout_.area(controls_, asked);
    tryBands(a, false);
    // The charts in a band under the box (a wide, low box has the height to spare that a
    // column beside it would take from its width); the bins and the values table keep to the
    // column.
    BoxArea under = bare;
    under.bottom += bare.chartsBand;
    under.spareColumn = 0.0;
    const bool band = (options_.plots || options_.speeds) && !options_.values &&
                      !binsShown(doc.meta) && bare.chartsBand > 0.0;
    if (band) tried.push_back({&under, {}, false, fitWith(under, {}), true, false});
    if (asked) tryBands(folded, true);
    // At the right the table folds the charts asked for, whose note the HUD's band then holds.
    BoxArea besideColumn = a;
    if (asked) besideColumn.top = std::max(a.top, a.foldedTop);
    if (options_.values && a.valuesColumn > 0.0) {
        tried.push_back({&besideColumn,
                         {true, a.valuesColumn},
                         false,
                         fitWith(besideColumn, {true, a.valuesColumn}),
                         false,
                         asked || a.valuesColumn < a.valuesWidth});
    }
    // The first choice that keeps the box its share and hides nothing; else the largest that
    // hides nothing, where the box keeps kBoxKeepsBeforeHiding of its size; else the first that
    // keeps the box its share; else the largest box.
    const auto largest = [](const Choice& l, const Choice& r) { return l.zoom < r.zoom; };
    const auto keeps = [](const Choice& c, double least) { return c.zoom >= least * (1.0 - 1e-9); };
    std::vector<Choice> whole;
    std::copy_if(tried.begin(), tried.end(), std::back_inserter(whole),
                 [](const Choice& c) { return !c.hides; });
    const double bareZoom = fitWith(bare, {});
    const auto keeper =
        std::find_if(whole.begin(), whole.end(), [&](const Choice& c) { return keeps(c, share); });
    const auto best = std::max_element(whole.begin(), whole.end(), largest);
    const auto any =
        std::find_if(tried.begin(), tried.end(), [&](const Choice& c) { return keeps(c, share); });
    const Choice chosen =
        keeper != whole.end()                                                   ? *keeper
        : best != whole.end() && keeps(*best, kBoxKeepsBeforeHiding * bareZoom) ? *best
        : any != tried.end()                                                    ? *any
                             : *std::max_element(tried.begin(), tried.end(), largest);
    valuesDock_ = chosen.dock;
    columnFolded_ = chosen.fold;
    chartsBelow_ = chosen.below;
    fitWith(*chosen.area, chosen.dock);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    notices.log(fmt("View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px", camera_.zoom(),
                    topLeft.x(), topLeft.y()));
    fitted_ = true;
}

void SceneView::handle(const cmd::Resize& c, Context& x) {
    const bool sized = c.width != camera_.viewportWidth() || c.height != camera_.viewportHeight();
    if (!sized && c.layout == layout_) return;
    // A window made too narrow for the box beside the open control panel folds it (C opens it
    // again, over the box). A bigger UI scale in the same window (the panel's own slider, a
    // finger still on it) keeps it open where it is, over the box: folding it would take the
    // control away from under the hand that set it.
    const bool crowded = controls_ && layout_.controlsFit && !c.layout.controlsFit;
    layout_ = c.layout;
    if (crowded && sized) {
        controls_ = false;
        x.notices.say(std::string("The control panel folded: the window leaves the box no room "
                                  "beside it (") +
                      x.notices.key("C or >>", ">>") + " opens it over the box)");
    } else if (crowded) {
        x.notices.say(std::string("The control panel covers the box at this scale: ") +
                      x.notices.key("C or <<", "<<") + " folds it");
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
    // The automatic scale follows the window by itself: a resize says nothing. The page's
    // browser keeps Ctrl+0 for its zoom; a touch screen has no keys: the panel's Auto.
    const bool keys = !inPage_ && !x.notices.touch;
    if (said) {
        // A window too narrow for the panel at the scale chosen: said where it is chosen.
        const std::string narrow =
            c.scale > options_.uiScaleMost
                ? fmt(", shown at %.0f %%, the most this %s's width allows",
                      100.0 * options_.uiScaleMost, inPage_ ? "page" : "window")
                : std::string();
        x.notices.add({Notice::Level::Info,
                       fmt("UI scale %.0f %%%s%s", 100.0 * c.scale, narrow.c_str(),
                           c.automatic ? (inPage_ ? " (automatic: by the page's height)"
                                          : keys  ? " (automatic: by the window's "
                                                    "height; Ctrl+0)"
                                                  : " (automatic: by the window's height)")
                           : keys      ? " (Ctrl+0: automatic)"
                                       : " (Show: Auto makes it automatic)"),
                       true, true, "ui scale"});
    }
}

void SceneView::handle(const cmd::FitUiScale& c, Context&) {
    // A resize says nothing: the panel says it beside the slider while the scale is held down.
    if (c.most >= kMinUiScale && c.most <= kMaxUiScale) options_.uiScaleMost = c.most;
}

void SceneView::handle(const cmd::SetTheme& c, Context& x) {
    if (c.theme == options_.theme) return;
    options_.theme = c.theme;
    // The browser keeps Ctrl+T for a new tab; a touch screen has no keys.
    const bool keys = !inPage_ && !x.notices.touch;
    x.notices.say(c.theme == Theme::Light ? fmt("Theme: light (high contrast, for projectors%s)",
                                                keys ? "; Ctrl+T" : "")
                                          : fmt("Theme: dark%s", keys ? " (Ctrl+T)" : ""));
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
        x.notices.say(std::string("The control panel covers the box in this narrow window: ") +
                      x.notices.key("C or <<", "<<") + " folds it");
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
