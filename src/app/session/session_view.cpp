// The session's view: the camera (pan, zoom, the box fitted into the area the view lays out
// for it: box_area.hpp) and what is shown, with the toggles that change which area that is.

#include <algorithm>
#include <cstdio>
#include <vector>

#include "session/session.hpp"
#include "session/session_text.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// The view.

bool Session::columnAsked() const {
    return view_.plots || view_.speeds || view_.profile || binsShown();
}

void Session::fit() {
    // The area the view left the box beside the panels as they are now.
    const BoxArea& a = layout_.area(showControls_, columnAsked());
    const double w = doc_.world.def().width, h = doc_.world.def().height, margin = 10.0;
    // The values table docks where the box comes out largest: along the bottom with its rows,
    // with fewer rows (the rest scroll), or at the right. Among places within 2 % of the
    // largest the first is kept: a band of rows reads best.
    std::vector<ValuesDock> docks;
    if (view_.values) {
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
    const double best = *std::max_element(zooms.begin(), zooms.end());
    std::size_t chosen = 0;
    while (zooms[chosen] < 0.98 * best)
        ++chosen;
    valuesDock_ = view_.values ? docks[chosen] : ValuesDock{};
    fitWith(docks[chosen]);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    notices_.log(fmt("View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px", camera_.zoom(),
                     topLeft.x(), topLeft.y()));
    fitted_ = true;
}

void Session::handle(const cmd::Resize& c) {
    const bool sized = c.width != camera_.viewportWidth() || c.height != camera_.viewportHeight();
    if (!sized && c.layout == layout_) return;
    // A window made too narrow for the box beside the open control panel folds it (C opens it
    // again, over the box).
    const bool fold = showControls_ && layout_.controlsFit && !c.layout.controlsFit;
    layout_ = c.layout;
    if (fold) {
        showControls_ = false;
        notices_.say(
            "The control panel folded: the window leaves the box no room beside it (C or >> "
            "opens it over the box)");
    }
    // A fitted view stays fitted; a view the user moved keeps its centre where it was.
    const Vec2 centre =
        camera_.screenToWorld(Vec2(camera_.viewportWidth() / 2.0, camera_.viewportHeight() / 2.0));
    camera_.setViewport(c.width, c.height);
    if (fitted_) {
        fit();
    } else if (sized) {
        camera_.set(camera_.zoom(), centre - Vec2(c.width / 2.0, c.height / 2.0) / camera_.zoom());
    }
}

void Session::afterCameraMove() {
    fitted_ = false;
    if (tools_.hand.mode() != Interaction::Mode::Idle) {
        tools_.hand.moveTo(pointerWorld(), tools_.pointerTime);
    }
}

void Session::handle(const cmd::Pan& c) {
    camera_.panPixels(c.pixels);
    camera_.keepNear(doc_.world.def().width, doc_.world.def().height);
    afterCameraMove();
}

void Session::handle(const cmd::Zoom& c) {
    camera_.zoomAbout(c.screen, c.factor);
    notices_.log(
        fmt("Zoom %.4f px/m about [%.0f, %.0f]", camera_.zoom(), c.screen.x(), c.screen.y()));
    afterCameraMove();
}

void Session::handle(const cmd::Fit&) {
    fit();
    afterCameraMove();
    fitted_ = true;
}

void Session::handle(const cmd::ToggleHelp&) {
    const int pages = layout_.helpPages;
    if (!showHelp_) {
        showHelp_ = true;
        helpPage_ = 0;
    } else if (static_cast<int>(helpPage_) + 1 < pages) {
        ++helpPage_;
    } else {
        showHelp_ = false;
    }
}

void Session::handle(const cmd::SetShow& c) {
    bool& flag = view_.flag(c.option);
    if (flag == c.on) return;
    flag = c.on;
    notices_.say(showMessage(c.option, c.on));
    if (c.option == cmd::ShowOption::Ruler && !c.on) ruler_.letGo();
    if (c.option == cmd::ShowOption::Collision) {
        // Hidden in a large scene, it stops listening, and a card kept would go stale.
        if (!LastCollision::listening(c.on, doc_.world.size())) lastCollision_.clear();
        listenForCollisions();
    }
    // The side column's panels and the values table's band change what the box is fitted
    // beside.
    using O = cmd::ShowOption;
    if (fitted_ && (c.option == O::Plots || c.option == O::Speeds || c.option == O::Profile ||
                    c.option == O::Bins || c.option == O::Values)) {
        fit();
    }
}

void Session::handle(const cmd::SetArrowScale& c) {
    if (!(c.seconds >= kMinArrowSeconds && c.seconds <= kMaxArrowSeconds)) {
        notices_.say(fmt("The arrow scale must be %g s to %g s of motion, got %g", kMinArrowSeconds,
                         kMaxArrowSeconds, c.seconds),
                     Notice::Level::Warning);
        return;
    }
    view_.arrowSeconds = c.seconds;
    view_.arrowScaleSet = true;
    notices_.add({Notice::Level::Info,
                  fmt("Arrows: %.3g s of motion, kept until a scene opens", c.seconds), true,
                  !c.continues, "arrow scale"});
}

void Session::handle(const cmd::SetUiScale& c) {
    if (!(c.scale >= kMinUiScale && c.scale <= kMaxUiScale)) {
        notices_.say(fmt("The UI scale must be %.0f %% to %.0f %%, got %g %%", 100.0 * kMinUiScale,
                         100.0 * kMaxUiScale, 100.0 * c.scale),
                     Notice::Level::Warning);
        return;
    }
    if (c.scale == view_.uiScale && c.automatic == view_.uiScaleAutomatic) return;
    const bool said = c.scale != view_.uiScale || !c.automatic;
    view_.uiScale = c.scale;
    view_.uiScaleAutomatic = c.automatic;
    // The automatic scale follows the window by itself: a resize says nothing.
    if (said) {
        notices_.add({Notice::Level::Info,
                      fmt("UI scale %.0f %%%s", 100.0 * c.scale,
                          c.automatic ? (options_.inPage ? " (automatic: by the page's height)"
                                                         : " (automatic: by the window's "
                                                           "height; Ctrl+0)")
                          : options_.inPage ? " (Show: Auto makes it automatic)"
                                            : " (Ctrl+0: automatic)"),
                      true, true, "ui scale"});
    }
}

void Session::handle(const cmd::SetTheme& c) {
    if (c.theme == view_.theme) return;
    view_.theme = c.theme;
    // The browser keeps Ctrl+T for a new tab.
    const char* key = options_.inPage ? "" : "; Ctrl+T";
    notices_.say(c.theme == Theme::Light
                     ? fmt("Theme: light (high contrast, for projectors%s)", key)
                     : fmt("Theme: dark%s", options_.inPage ? "" : " (Ctrl+T)"));
}

void Session::handle(const cmd::SetTrails& c) {
    const auto mode = static_cast<TrailMode>(std::clamp(c.mode, 0, 2));
    if (mode == view_.trails) return;
    view_.trails = mode;
    notices_.say(std::string("Trails: ") + toString(view_.trails));
}

void Session::handle(const cmd::ToggleControls&) {
    showControls_ = !showControls_;
    if (showControls_ && !layout_.controlsFit) {
        notices_.say("The control panel covers the box in this narrow window: C or << folds it");
    }
    if (fitted_) fit();
}

void Session::handle(const cmd::Screenshot&) {
    screenshotRequested_ = true;
}

std::string Session::overlayFlags() const {
    std::string f;
    const auto add = [&f](const std::string& s) { f += (f.empty() ? "" : " ") + s; };
    if (view_.momentum) add("V");
    if (view_.trails != TrailMode::Off) add(std::string("L:") + toString(view_.trails));
    if (view_.plots) add("K");
    if (view_.speeds) add("D");
    return f;
}

}  // namespace psb::app
