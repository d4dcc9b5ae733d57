// The hand: pointer presses, moves and releases turned into grabs, flings, launches, clicks
// and pans (the rules are interaction.hpp's and obstacle_tool.hpp's), deleting, random spawns
// and what new particles are made of. The hand says what the user meant; the handlers here
// have the document make the change.

#include <algorithm>
#include <cstdio>

#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/lab_ruler.hpp"
#include "session/monitor.hpp"
#include "session/notices.hpp"
#include "session/scene_view.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"
#include "session/units.hpp"

namespace psb::app {

void Tools::handle(const cmd::PointerDown& c, Context& x) {
    pointer = c.screen;
    pointerTime = c.time;
    pointerIn = true;
    // The ruler's ends and edge come first, whatever the tool: they are what is under the hand.
    if (x.view.options().ruler) {
        if (const auto part = x.ruler.partAt(c.screen, x.view.camera())) {
            x.ruler.take(*part, pointerWorld(x.view.camera()));
            return;
        }
    }
    if (tool == cmd::Tool::Pan) {
        panFrom = c.screen;
        return;
    }
    if (tool == cmd::Tool::Select) {
        obstaclePressToMove(x);  // on an obstacle: a drag moves it
        return;                  // the release selects
    }
    if (obstacleToolOn()) {
        obstaclePress(x);
        return;
    }
    World& world = x.doc.world;
    const auto grabbed =
        hand.press(world, pointerWorld(x.view.camera()), c.time, tool == cmd::Tool::Fling);
    pausedFlingTold = false;
    if (grabbed) {
        world.setKinematic(*grabbed, true);  // the hand moves it, not the steps
        const Particle p = world.get(*grabbed);
        const Vec2 at = x.view.axes(world.def()).point(p.position);
        x.notices.log(fmt("Grabbed particle at [%.2f, %.2f]", at.x(), at.y()));
        // The energy is measured from the grab; a click that only selects changes nothing.
        x.monitor.resetEnergy(world);
    }
}

void Tools::handle(const cmd::PointerMove& c, Context& x) {
    if (panFrom) {
        x.view.drag(c.screen - *panFrom, x.doc.world.def());
        panFrom = c.screen;
    }
    pointer = c.screen;
    pointerTime = c.time;
    pointerIn = true;
    if (x.ruler.held()) {
        x.ruler.moveTo(pointerWorld(x.view.camera()));
        return;
    }
    obstacle.moveTo(pointerWorld(x.view.camera()));
    hand.moveTo(pointerWorld(x.view.camera()), c.time);
    // Paused, a flung particle stays where it is let go until time runs: its speed is kept for
    // then, which the drag says (the particle would seem to have been dropped at rest).
    if (x.clock.paused && !pausedFlingTold && hand.mode() == Interaction::Mode::Holding &&
        hand.dragged(launchSettings(x.view.camera(), x.doc.world.def()))) {
        pausedFlingTold = true;
        x.notices.add({Notice::Level::Info,
                       std::string("Paused: let go moving and the particle takes the hand's "
                                   "speed (its arrow), let go still and it keeps its own, until ") +
                           x.notices.key("Space", "Play") + " sets time running",
                       true, false});
    }
}

void Tools::handle(const cmd::PointerLeave&, Context&) {
    // Where a lifted finger was means nothing: no shade of a peg stays there.
    pointerIn = false;
}

void Tools::handle(const cmd::PointerUp& c, Context& x) {
    pointer = c.screen;
    pointerTime = c.time;
    if (x.ruler.held()) {
        x.ruler.moveTo(pointerWorld(x.view.camera()));
        x.ruler.letGo();
        x.notices.log(fmt("Ruler: %s, %.1f degrees from the horizontal",
                          quantity(x.ruler.length(), "m").c_str(), x.ruler.slopeDegrees()));
        return;
    }
    if (tool == cmd::Tool::Pan) {
        panFrom.reset();
        return;
    }
    if (tool == cmd::Tool::Select) {
        if (obstacleMoveRelease(x)) return;  // moved, or the move refused; else a click
        if (c.pinch) return;                 // a pinch begins: no click
        ReleaseResult r;
        r.kind = ReleaseResult::Kind::Clicked;
        if (const auto id = x.doc.world.pick(pointerWorld(x.view.camera()))) r.id = *id;
        click(r, x);
        return;
    }
    if (obstacleToolOn()) {
        obstacleRelease(x);
        return;
    }
    World& world = x.doc.world;
    ReleaseResult r = hand.release(world, pointerWorld(x.view.camera()), c.time, spawn,
                                   launchSettings(x.view.camera(), x.doc.world.def()),
                                   x.view.options().arrowSeconds);
    using K = ReleaseResult::Kind;
    if (c.pinch && (r.kind == K::Clicked || r.kind == K::Launched || r.kind == K::Refused)) {
        // A pinch begins: no click selects or clears, nothing is launched; a particle the first
        // finger held goes back to moving as it did.
        if (r.letGo) {
            world.setPosition(r.id, r.position);
            world.setVelocity(r.id, r.velocity);
            world.setKinematic(r.id, false);
        }
        return;
    }
    // Paused, a particle moved and put down (the hand stopped) keeps the velocity it had: the
    // student moved it, and a fling (let go moving) is how to give it another. Running, a hand
    // that stopped holds it still, as a hand catching a ball does.
    const bool putDown = r.kind == K::Flung && x.clock.paused && r.handStopped;
    if (putDown) r.velocity = r.velocityBefore;
    if (r.letGo) {
        world.setPosition(r.id, r.position);
        world.setVelocity(r.id, r.velocity);
        world.setKinematic(r.id, false);
    }
    if (r.kind == K::Launched) r.id = world.add(r.launch);
    // In the axes the window shows, as every number it shows.
    const Axes axes = x.view.axes(world.def());
    const Vec2 shownAt = axes.point(r.position), shownV = axes.vector(r.velocity);
    const std::string at = fmt("at [%.2f, %.2f]", shownAt.x(), shownAt.y());
    const std::string v = fmt("with velocity [%.2f, %.2f] m/s", shownV.x(), shownV.y());
    if (r.kind == K::Flung) x.notices.log("Released particle " + at + " " + v);
    // Speeds in m/s, as the panel's vx and vy beside it: one unit for one quantity.
    if (putDown) {
        x.notices.say(r.velocity.norm() > 0.0
                          ? fmt("Moved while paused: it keeps its speed, %s (let go moving to "
                                "fling it)",
                                quantity(r.velocity.norm(), "m/s", false).c_str())
                          : std::string("Moved while paused: still at rest (let go moving to "
                                        "fling it)"));
    } else if (r.kind == K::Flung && x.clock.paused) {
        x.notices.say(fmt("Flung at %s while paused: %s sets it moving",
                          quantity(r.velocity.norm(), "m/s", false).c_str(),
                          x.notices.key("Space", "Play")));
    }
    if (r.kind == K::Launched) x.notices.log("Launched particle " + at + " " + v);
    if ((r.kind == K::Flung || r.kind == K::Launched) && r.capped) {
        x.notices.say(fmt("Speed capped at %.3g m/s (%g box widths per second)", r.velocity.norm(),
                          kMaxLaunchBoxesPerSecond));
    }
    if (r.kind == K::Refused) x.notices.say(r.message);
    if (r.kind == K::Clicked) click(r, x);
    if (r.kind == K::Flung) x.edit.userAction("fling particle");
    if (r.kind == K::Launched) x.edit.userAction("launch particle");
}

void Tools::click(const ReleaseResult& r, Context& x) {
    if (!r.id.isNull()) {
        if (prompt.target() != r.id) closePrompt();
        selectedObstacle.reset();
        selection.select(r.id);
        std::string line = selectionLogLine(x.doc.world.get(r.id), x.view.axes(x.doc.world.def()));
        x.notices.log(line.substr(4));  // without its "[I] "
    } else if (selectObstacleAt(x)) {
        selection.clear();
        closePrompt();
    } else if (selection.id() || selectedObstacle) {
        selection.clear();
        selectedObstacle.reset();
        closePrompt();
        x.notices.say("Selection cleared");
    }
}

void Tools::handle(const cmd::DeleteHeld&, Context& x) {
    if (hand.mode() == Interaction::Mode::Holding && x.doc.world.contains(hand.held())) {
        handle(cmd::DeleteParticle{hand.held()}, x);
    } else if (const auto id = selection.id();
               id && hand.mode() == Interaction::Mode::Idle && x.doc.world.contains(*id)) {
        handle(cmd::DeleteParticle{*id}, x);
    } else if (selectedObstacle) {
        removeObstacle(*selectedObstacle, x);
    }
}

void Tools::handle(const cmd::DeleteParticle& c, Context& x) {
    if (!x.doc.world.contains(c.id)) return;
    if (hand.mode() != Interaction::Mode::Idle && hand.held() == c.id) {
        hand.reset();
    }
    const Particle p = x.doc.world.get(c.id);
    x.doc.world.remove(c.id);
    x.notices.log(deletionLogLine(p, x.view.axes(x.doc.world.def())).substr(4));
    x.notices.add({Notice::Level::Info, "Deleted a particle", true, false});
    x.edit.userAction("delete particle");
    checkSelection(x.doc.world, x.notices);
}

void Tools::handle(const cmd::SetTool& c, Context& x) {
    tool = c.toggle && tool == c.tool ? cmd::Tool::Fling : c.tool;
    panFrom.reset();
    obstacle.reset();
    static const char* const kTools[] = {"Left mouse: fling particles, launch on empty space",
                                         "Left mouse: launch new particles",
                                         "Left mouse: select particles and obstacles",
                                         "Left mouse: move the view",
                                         "Left mouse: a click places a peg",
                                         "Left mouse: a drag draws a wall"};
    x.notices.say(kTools[static_cast<int>(tool)]);
}

void Tools::handle(const cmd::SpawnRandom&, Context& x) {
    const WorldDef& d = x.doc.world.def();
    // The original: mass a random integer 3..20 kg with its radius, 2.5 cm per kg at its scale of
    // 1 px = 1 cm (here 0.3..2 times the scene's typical particle), somewhere in the upper part
    // of the box, colour channels 100..255, velocity components up to 5 px per frame at 60
    // frames per second (3 m/s), scaled with the box.
    std::uniform_int_distribution<int> sizeDist(3, 20), channel(100, 255);
    const double size = sizeDist(rng) / 10.0;
    const double mass = size * spawn.typicalMass, radius = size * spawn.typicalRadius;
    std::uniform_real_distribution<double> atX(radius, std::max(radius, d.width - radius));
    std::uniform_real_distribution<double> atY(radius, std::max(radius, d.height / 2.0));
    const double vmax = 3.0 * std::min(d.width, d.height) / 7.0;
    std::uniform_real_distribution<double> v(-vmax, vmax);
    const Vec2 want(atX(rng), atY(rng));
    const auto spot = findFreeSpot(x.doc.world, want, radius);
    if (!spot) {
        x.notices.say("No room for a new particle");
        return;
    }
    ParticleDef def;
    def.position = *spot;
    def.velocity = {v(rng), v(rng)};
    def.mass = mass;
    def.radius = radius;
    def.color = {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
                 static_cast<std::uint8_t>(channel(rng))};
    def.fixedRotation = !spawn.turn;
    x.doc.world.add(def);
    x.edit.userAction("spawn particle");
    const Axes axes = x.view.axes(d);
    const Vec2 at = axes.point(*spot), velocity = axes.vector(def.velocity);
    x.notices.log(
        fmt("Spawned particle at [%.2f, %.2f] with velocity [%.2f, %.2f] m/s and mass %.3g kg",
            at.x(), at.y(), velocity.x(), velocity.y(), mass));
}

void Tools::handle(const cmd::ChangeSpawnMass& c, Context& x) {
    const double before = spawn.mass();
    spawn.changeSize(c.direction < 0 ? -1 : 1);
    if (spawn.mass() != before) x.edit.remember("set new particle size");
    x.notices.add({Notice::Level::Info,
                   fmt("New particles: %.3g kg, radius %.3g m (%.1f x the scene's typical)",
                       spawn.mass(), spawn.radius(), spawn.size),
                   true, false});
}

void Tools::handle(const cmd::SetDiscsTurn& c, Context& x) {
    if (spawn.turn == c.on) return;
    spawn.turn = c.on;
    x.edit.remember(c.on ? "let new particles turn" : "give new particles fixed rotation");
    x.notices.say(c.on ? "New particles turn: friction spins them, and they roll"
                       : "New particles have fixed rotation: they slide without turning");
}

void Tools::handle(const cmd::SetLaunchBody& c, Context& x) {
    const WorldDef& d = x.doc.world.def();
    if (!(c.mass >= kMinLaunchMass && c.mass <= kMaxLaunchMass)) {
        x.notices.say(fmt("Launch mass must be between %g and %g kg, got %g", kMinLaunchMass,
                          kMaxLaunchMass, c.mass),
                      Notice::Level::Warning);
        return;
    }
    const double maxRadius = 0.5 * std::min(d.width, d.height);
    if (!(c.radius >= 0.0 && c.radius <= maxRadius)) {
        x.notices.say(fmt("Launch radius must be above 0 and at most half the box (%.3g m), got %g",
                          maxRadius, c.radius),
                      Notice::Level::Warning);
        return;
    }
    const SpawnSettings before = spawn;
    // The mass the panel shows is sent back with every change of the others: it stays the
    // scene's rule until it is changed.
    if (c.mass != spawn.mass()) spawn.fixedMass = c.mass;
    spawn.fixedRadius = c.radius > 0.0 ? std::optional<double>(c.radius) : std::nullopt;
    spawn.fixedColor = c.color;
    if (spawn.mass() != before.mass() || spawn.radius() != before.radius() ||
        spawn.color() != before.color()) {
        x.edit.remember("set new particles");
    }
    x.notices.log(fmt("New particles: %g kg, radius %g m%s", spawn.mass(), spawn.radius(),
                      spawn.fixedRadius ? "" : " (from the mass)"));
}

}  // namespace psb::app
