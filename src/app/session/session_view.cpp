// The session's view: the box fitted into the area the view lays out for it (box_area.hpp),
// and the toggles that change which area that is.

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

void Session::fit() {
    // The area the view left the box beside the panels as they are now.
    const BoxArea& a = layout_.area(showControls_, columnAsked());
    const double w = world_.def().width, h = world_.def().height, margin = 10.0;
    double right = a.right;
    if (a.spareColumn > 0.0) {
        // A box that the window's height limits may leave width to spare: when it leaves the
        // inspector's whole column, the box moves left, keeps its size, and the inspector
        // (bottom right, on a click) does not cover it. Less room would only move the box off
        // centre and still leave it covered.
        camera_.fit(w, h, margin, a.top, a.bottom, right, a.left);
        const double spare =
            camera_.viewportWidth() - a.left - right - camera_.toScreen(w) - 2.0 * margin;
        if (spare >= a.spareColumn) right += a.spareColumn;
    }
    camera_.fit(w, h, margin, a.top, a.bottom, right, a.left);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    char buf[160];
    std::snprintf(buf, sizeof buf, "View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px",
                  camera_.zoom(), topLeft.x(), topLeft.y());
    log(buf);
    fitted_ = true;
}

void Session::resize(const cmd::Resize& c) {
    const bool sized = c.width != camera_.viewportWidth() || c.height != camera_.viewportHeight();
    if (!sized && c.layout == layout_) return;
    layout_ = c.layout;
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

void Session::togglePanel(bool& flag, const char* on, const char* off) {
    flag = !flag;
    say(flag ? on : off);
    // The panel column sits beside the box: a fitted view makes room for it (or takes it back).
    if (fitted_) fit();
}

}  // namespace psb::app
