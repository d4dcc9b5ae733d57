#pragma once
/// \file
/// Which way y points in the numbers people read, type and export. The world's y points down
/// the screen from the box's top-left corner, as in scene files, the engine and particle-sim.
/// With y up (the app's "y up", on unless switched off) numbers count y upward from the box's
/// floor, and vy, py, impulses and turning upward and counterclockwise, as in school physics.
/// Scene files never change; a table exported with y up names its columns so (data_tables.hpp).

#include <particle_sandbox/math.hpp>

namespace psb {

struct Axes {
    bool yUp = false;
    /// The box's height, metres: y up counts from its floor.
    double height = 0.0;

    // Each conversion is its own inverse (a height's to rounding: h - (h - y)): the same call
    // turns a typed value into the world's.

    /// A height: from the box's floor with y up, from its top edge without.
    [[nodiscard]] double y(double worldY) const { return yUp ? height - worldY : worldY; }
    /// The y component of a vector (velocity, momentum, impulse, acceleration).
    [[nodiscard]] double up(double worldComponent) const {
        return yUp ? 0.0 - worldComponent : worldComponent;  // 0 stays +0
    }
    [[nodiscard]] Vec2 point(const Vec2& p) const { return {p.x(), y(p.y())}; }
    [[nodiscard]] Vec2 vector(const Vec2& v) const { return {v.x(), up(v.y())}; }
    /// An angular velocity or spin: positive turns +x toward the shown +y (counterclockwise on
    /// screen with y up, clockwise without).
    [[nodiscard]] double spin(double worldOmega) const {
        return yUp ? 0.0 - worldOmega : worldOmega;
    }
    /// The angular momentum about the shown axes' origin (the box's bottom-left corner with y
    /// up), from `aboutTopLeft` (World's, about the top-left corner) and the total momentum's
    /// x component `px`: with y' = h − y and vy' = −vy, L' = −L − h px.
    [[nodiscard]] double angularMomentum(double aboutTopLeft, double px) const {
        return yUp ? 0.0 - aboutTopLeft - height * px : aboutTopLeft;
    }
};

}  // namespace psb
