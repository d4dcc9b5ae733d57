#pragma once
// What the session tests share: whether a notice said something, a drag with the left button in
// world metres, a window's layout with fixed bands in place of the view's, and a fixture with a
// session over the default scene (paused, seed 3) that saves into the test's own temporary
// directory.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/box_area.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "session/test_assets.hpp"
#include "temp_dir_test.hpp"

namespace psb::app {

/// Whether one of `notices` says `text`.
[[nodiscard]] inline bool said(const std::vector<Notice>& notices, const std::string& text) {
    return std::any_of(notices.begin(), notices.end(),
                       [&](const Notice& n) { return n.text.find(text) != std::string::npos; });
}

/// Ctrl+S, and Enter in the Save As dialog when it asks (the scene has no file yet): what a
/// user does to save at once.
inline void saveNow(Session& s) {
    s.apply(cmd::Save{});
    if (s.dialog().kind == Dialog::Kind::SaveAs) s.apply(cmd::SaveAs{s.dialog().proposal});
}

/// A drag with the left button from world point `from` to `to`: the press at `t0`, `moves`
/// moves `step` seconds apart, the release at `t0` + 0.1 s + `hold` (the hand held still).
inline void drag(Session& s, Vec2 from, Vec2 to, double t0, int moves = 10, double step = 0.01,
                 double hold = 0.0) {
    const Camera& c = s.camera();
    s.apply(cmd::PointerDown{c.worldToScreen(from), t0});
    for (int k = 1; k <= moves; ++k) {
        s.apply(cmd::PointerMove{c.worldToScreen(from + (to - from) * (k / double(moves))),
                                 t0 + step * k});
    }
    s.apply(cmd::PointerUp{c.worldToScreen(to), t0 + 0.1 + hold});
}

/// Fixed bands around the box, pixels, for a window's layout given without the view's fonts.
struct TestBands {
    double top = 0.0;
    double bottom = 0.0;
    double column = 0.0;  ///< the side column, kept free while a panel of it is asked for
    double controls = 0.0;
    double controlsFolded = 0.0;
    double inspector = 0.0;  ///< the inspector's column, kept free when the box can spare it
    int helpPages = 1;
};

/// The layout the view would send with `bands` around the box (view/box_area.hpp measures them).
[[nodiscard]] inline WindowLayout testLayout(const TestBands& bands) {
    const auto area = [&bands](double left, bool column) {
        return BoxArea{left, bands.top, column ? bands.column : 0.0, bands.bottom,
                       column ? 0.0 : bands.inspector};
    };
    WindowLayout l;
    l.controlsOpen = area(bands.controls, false);
    l.controlsFolded = area(bands.controlsFolded, false);
    l.controlsOpenColumn = area(bands.controls, true);
    l.controlsFoldedColumn = area(bands.controlsFolded, true);
    l.helpPages = bands.helpPages;
    return l;
}

/// The window a fixture's session is laid out in.
struct TestWindow {
    int width = 800;
    int height = 800;
    /// The side column as the view makes it in an 800-pixel window: 320 pixels and the margin.
    TestBands bands{.top = 110.0, .bottom = 44.0, .column = 328.0};
    bool presets = false;  ///< the app's presets, for OpenPreset
};

/// A session over the default scene in `window`, saving to dir_/save.json.
class SessionFixture : public TempDirTest {
  protected:
    SessionFixture(std::string prefix, TestWindow window)
        : TempDirTest(std::move(prefix)), window_(std::move(window)) {}

    [[nodiscard]] SessionOptions options() const {
        SessionOptions o;
        o.saveTo = dir_ / "save.json";
        o.seed = 3;
        o.paused = true;
        o.viewportWidth = window_.width;
        o.viewportHeight = window_.height;
        o.layout = layout();
        if (window_.presets) o.presets = testPresets();
        return o;
    }
    /// The window's layout (at any size: the bands are fixed).
    [[nodiscard]] WindowLayout layout() const { return testLayout(window_.bands); }
    [[nodiscard]] Session session() const {
        return Session(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                       options());
    }

    TestWindow window_;
};

}  // namespace psb::app
