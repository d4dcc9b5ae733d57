#pragma once
// A world put in place (a scene opened, restarted or reverted; an undo): the parts that follow
// the world start over from it. The session makes one over its parts for whatever may put a
// world in place (the document's commands, undo); it holds nothing of its own.

namespace psb::app {

struct Document;
struct History;
struct Instruments;
class Monitor;
class Notices;
class SceneView;
class SimClock;
struct Tools;

struct StartOver {
    Tools& tools;
    SceneView& view;
    SimClock& clock;
    History& history;
    Monitor& monitor;
    Instruments& instruments;
    Notices& notices;

    /// `doc`'s world was put in place (a new scene, or an undo within the scene when `newScene`
    /// is false): the tools, the recorded past, the clock, the monitor and the instruments start
    /// over from it. A new scene stops a recording and keeps what it recorded, to export, and
    /// says so.
    void world(const Document& doc, bool newScene);
    /// `doc` holds a scene just opened: everything starts over from it, new particles and
    /// obstacles follow its scale, and the view fits its box.
    void scene(const Document& doc);
};

}  // namespace psb::app
