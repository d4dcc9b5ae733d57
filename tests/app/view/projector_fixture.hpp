#pragma once
// The projector of the lessons' trials: UI scale 200 % in a 1600 x 1000 window beside the open
// control panel, and lesson 1's world; any other window and scale for the rules that hold from
// 100 % at 800 x 600 up. Shared by the frame's layout and readings tests.

#include <initializer_list>
#include <utility>

#include <particle_sandbox/world.hpp>

#include "session/session.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"

namespace psb::app::test {

/// The control panel's width at 200 %, as the app measures it: 30 % of the window's 1600
/// pixels (gui/control_panel.hpp, controlsOpenPoints).
inline const ControlsWidth kProjector{480.0, 88.0, 2.0};

/// Lesson 1's world: a 10 m x 4 m box, two balls of 1 and 3 kg closing at 3 m/s.
inline World lessonWorld() {
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    World w(def);
    w.add({.position = Vec2(2.0, 2.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.25});
    w.add({.position = Vec2(7.0, 2.0), .velocity = Vec2(-1.0, 0.0), .mass = 3.0, .radius = 0.35});
    return w;
}

/// The control panel's width at 100 %.
inline const ControlsWidth kDesk{310.0, 44.0, 1.0};

/// `world` paused in a `width` × `height` window beside the control panel `controls` wide (its
/// pointPixels the UI's scale), laid out as the app lays it out, with `shown` turned on.
inline Session inWindow(World world, std::initializer_list<ShowOption> shown, int width, int height,
                        const ControlsWidth& controls) {
    const FixedMeasure font(controls.pointPixels);
    SessionOptions o;
    o.paused = true;
    o.viewportWidth = width;
    o.viewportHeight = height;
    o.layout = windowLayout(font, width, height, controls);
    o.controls = o.layout.controlsFit;
    Session s(std::move(world), SceneInfo{.name = "lesson", .dt = 1.0 / 60.0}, o);
    for (const ShowOption option : shown)
        s.apply(cmd::SetShow{option, true});
    return s;
}

/// `world` paused on the projector, laid out as the app lays it out, with `shown` turned on.
inline Session onTheProjector(World world, std::initializer_list<ShowOption> shown) {
    return inWindow(std::move(world), shown, 1600, 1000, kProjector);
}

}  // namespace psb::app::test
