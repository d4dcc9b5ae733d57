// The session's view: the box fitted to the window beside the panels, the side column's
// folding, and the toggles that change what the box is fitted beside.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>

#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/stopwatch.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// The view.

bool Session::columnAsked() const {
    return view_.plots || view_.speeds || showProfile_ || binsShown();
}

bool Session::sideColumnFolded() const {
    const ViewInsets& in = options_.insets;
    const double scale = in.panelColumn / (kSideColumnMaxWidth + kPanelMargin);
    return columnAsked() &&
           !sideColumnFits(camera_.viewportWidth(), static_cast<int>(controlsInset()), scale);
}

void Session::fit() {
    const ViewInsets& in = options_.insets;
    // The momentum legend is three short lines: it does not cost the box a column.
    const bool column = columnAsked() && !sideColumnFolded();
    const double w = world_.def().width, h = world_.def().height, margin = 10.0;
    const double left = controlsInset();
    const double top =
        in.topFor ? std::max(in.top, in.topFor(camera_.viewportWidth() - static_cast<int>(left),
                                               sideColumnFolded()))
                  : in.top;
    double right = 0.0;
    if (column) {
        const double scale = in.panelColumn / (kSideColumnMaxWidth + kPanelMargin);
        right = std::min(in.panelColumn,
                         sideColumnWidth(camera_.viewportWidth(), static_cast<int>(left), scale) +
                             1.0 * kPanelMargin);
    } else {
        // A box that the window's height limits may leave width to spare: when it leaves the
        // inspector's whole column, the box moves left, keeps its size, and the inspector
        // (bottom right, on a click) does not cover it. Less room would only move the box off
        // centre and still leave it covered.
        camera_.fit(w, h, margin, top, in.bottom, 0.0, left);
        const double spare = camera_.viewportWidth() - left - camera_.toScreen(w) - 2.0 * margin;
        right = spare >= in.inspectorColumn ? in.inspectorColumn : 0.0;
    }
    camera_.fit(w, h, margin, top, in.bottom, right, left);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    char buf[160];
    std::snprintf(buf, sizeof buf, "View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px",
                  camera_.zoom(), topLeft.x(), topLeft.y());
    log(buf);
    fitted_ = true;
}

void Session::resize(int width, int height) {
    if (width == camera_.viewportWidth() && height == camera_.viewportHeight()) return;
    // A fitted view stays fitted; a view the user moved keeps its centre where it was.
    const Vec2 centre =
        camera_.screenToWorld(Vec2(camera_.viewportWidth() / 2.0, camera_.viewportHeight() / 2.0));
    camera_.setViewport(width, height);
    if (fitted_) {
        fit();
    } else {
        camera_.set(camera_.zoom(), centre - Vec2(width / 2.0, height / 2.0) / camera_.zoom());
    }
}

void Session::togglePanel(bool& flag, const char* on, const char* off) {
    flag = !flag;
    say(flag ? on : off);
    // The panel column sits beside the box: a fitted view makes room for it (or takes it back).
    if (fitted_) fit();
}

}  // namespace psb::app
