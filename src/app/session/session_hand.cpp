// The session's hand: pointer presses, moves and releases turned into grabs, flings, launches,
// clicks and pans (the rules are interaction.hpp's and obstacle_tool.hpp's), deleting, random
// spawns and what new particles are made of. The hand says what the user meant; the handlers
// here make the change.

#include <algorithm>
#include <cstdio>

#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

void Session::handle(const cmd::PointerDown& c) {
    tools_.pointer = c.screen;
    tools_.pointerTime = c.time;
    // The ruler's ends and edge come first, whatever the tool: they are what is under the hand.
    if (view_.options().ruler) {
        if (const auto part = instruments_.ruler.partAt(c.screen, view_.camera())) {
            instruments_.ruler.take(*part, pointerWorld());
            return;
        }
    }
    if (tools_.tool == cmd::Tool::Pan) {
        tools_.panFrom = c.screen;
        return;
    }
    if (tools_.tool == cmd::Tool::Select) {
        obstaclePressToMove();  // on an obstacle: a drag moves it
        return;                 // the release selects
    }
    if (obstacleToolOn()) {
        obstaclePress();
        return;
    }
    World& world = doc_.world;
    const auto grabbed =
        tools_.hand.press(world, pointerWorld(), c.time, tools_.tool == cmd::Tool::Fling);
    tools_.pausedFlingTold = false;
    if (grabbed) {
        world.setKinematic(*grabbed, true);  // the hand moves it, not the steps
        const Particle p = world.get(*grabbed);
        notices_.log(fmt("Grabbed particle at [%.2f, %.2f]", p.position.x(), p.position.y()));
        // The energy is measured from the grab; a click that only selects changes nothing.
        monitor_.resetEnergy(world);
    }
}

void Session::handle(const cmd::PointerMove& c) {
    if (tools_.panFrom) {
        view_.drag(c.screen - *tools_.panFrom, doc_.world.def());
        tools_.panFrom = c.screen;
    }
    tools_.pointer = c.screen;
    tools_.pointerTime = c.time;
    if (instruments_.ruler.held()) {
        instruments_.ruler.moveTo(pointerWorld());
        return;
    }
    tools_.obstacle.moveTo(pointerWorld());
    tools_.hand.moveTo(pointerWorld(), c.time);
    // Paused, a flung particle stays where it is let go until time runs: its speed is kept for
    // then, which the drag says (the particle would seem to have been dropped at rest).
    if (clock_.paused && !tools_.pausedFlingTold &&
        tools_.hand.mode() == Interaction::Mode::Holding && tools_.hand.dragged(launchSettings())) {
        tools_.pausedFlingTold = true;
        notices_.add({Notice::Level::Info,
                      "Paused: let go and the particle keeps its speed (its arrow) until "
                      "Space sets time running",
                      true, false});
    }
}

void Session::handle(const cmd::PointerUp& c) {
    tools_.pointer = c.screen;
    tools_.pointerTime = c.time;
    if (instruments_.ruler.held()) {
        instruments_.ruler.moveTo(pointerWorld());
        instruments_.ruler.letGo();
        notices_.log(fmt("Ruler: %s, %.1f degrees from the horizontal",
                         quantity(instruments_.ruler.length(), "m").c_str(),
                         instruments_.ruler.slopeDegrees()));
        return;
    }
    if (tools_.tool == cmd::Tool::Pan) {
        tools_.panFrom.reset();
        return;
    }
    if (tools_.tool == cmd::Tool::Select) {
        if (obstacleMoveRelease()) return;  // moved, or the move refused; else a click
        ReleaseResult r;
        r.kind = ReleaseResult::Kind::Clicked;
        if (const auto id = doc_.world.pick(pointerWorld())) r.id = *id;
        click(r);
        return;
    }
    if (obstacleToolOn()) {
        obstacleRelease();
        return;
    }
    World& world = doc_.world;
    ReleaseResult r = tools_.hand.release(world, pointerWorld(), c.time, tools_.spawn,
                                          launchSettings(), view_.options().arrowSeconds);
    using K = ReleaseResult::Kind;
    if (r.letGo) {
        world.setPosition(r.id, r.position);
        world.setVelocity(r.id, r.velocity);
        world.setKinematic(r.id, false);
    }
    if (r.kind == K::Launched) r.id = world.add(r.launch);
    const std::string at = fmt("at [%.2f, %.2f]", r.position.x(), r.position.y());
    const std::string v = fmt("with velocity [%.2f, %.2f] m/s", r.velocity.x(), r.velocity.y());
    if (r.kind == K::Flung) notices_.log("Released particle " + at + " " + v);
    if (r.kind == K::Flung && clock_.paused) {
        notices_.say(r.velocity.norm() > 0.0
                         ? fmt("Flung at %s while paused: Space sets it moving",
                               quantity(r.velocity.norm(), "m/s").c_str())
                         : std::string("Let go at rest (the hand had stopped)"));
    }
    if (r.kind == K::Launched) notices_.log("Launched particle " + at + " " + v);
    if ((r.kind == K::Flung || r.kind == K::Launched) && r.capped) {
        notices_.say(fmt("Speed capped at %.3g m/s (%g box widths per second)", r.velocity.norm(),
                         kMaxLaunchBoxesPerSecond));
    }
    if (r.kind == K::Refused) notices_.say(r.message);
    if (r.kind == K::Clicked) click(r);
    if (r.kind == K::Flung) edit_.userAction("fling particle");
    if (r.kind == K::Launched) edit_.userAction("launch particle");
}

void Session::click(const ReleaseResult& r) {
    Tools& t = tools_;
    if (!r.id.isNull()) {
        if (t.prompt.target() != r.id) t.closePrompt();
        t.selectedObstacle.reset();
        t.selection.select(r.id);
        std::string line = selectionLogLine(doc_.world.get(r.id));
        notices_.log(line.substr(4));  // without its "[I] "
    } else if (selectObstacleAt()) {
        t.selection.clear();
        t.closePrompt();
    } else if (t.selection.id() || t.selectedObstacle) {
        t.selection.clear();
        t.selectedObstacle.reset();
        t.closePrompt();
        notices_.say("Selection cleared");
    }
}

void Session::handle(const cmd::DeleteHeld&) {
    const Interaction& hand = tools_.hand;
    if (hand.mode() == Interaction::Mode::Holding && doc_.world.contains(hand.held())) {
        handle(cmd::DeleteParticle{hand.held()});
    } else if (const auto id = tools_.selection.id();
               id && hand.mode() == Interaction::Mode::Idle && doc_.world.contains(*id)) {
        handle(cmd::DeleteParticle{*id});
    } else if (tools_.selectedObstacle) {
        removeObstacle(*tools_.selectedObstacle);
    }
}

void Session::handle(const cmd::DeleteParticle& c) {
    if (!doc_.world.contains(c.id)) return;
    if (tools_.hand.mode() != Interaction::Mode::Idle && tools_.hand.held() == c.id) {
        tools_.hand.reset();
    }
    const Particle p = doc_.world.get(c.id);
    doc_.world.remove(c.id);
    notices_.log(deletionLogLine(p).substr(4));
    notices_.add({Notice::Level::Info, "Deleted a particle", true, false});
    edit_.userAction("delete particle");
    checkSelection();
}

void Session::holdParticle(double now) {
    // Through the timeline's setters, so that a past frame replays the hand's moves.
    if (const auto h = tools_.hand.hold(doc_.world, now, launchSettings())) {
        history_.timeline.setPosition(doc_.world, h->id, h->position);
        history_.timeline.setVelocity(doc_.world, h->id, h->velocity);
    }
}

void Session::checkSelection() {
    if (tools_.selection.forgetIfGone(doc_.world)) {
        tools_.closePrompt();
        notices_.say("Selection cleared: the particle was deleted");
    }
}

void Session::handle(const cmd::SetTool& c) {
    Tools& t = tools_;
    t.tool = c.toggle && t.tool == c.tool ? cmd::Tool::Fling : c.tool;
    t.panFrom.reset();
    t.obstacle.reset();
    static const char* const kTools[] = {"Left mouse: fling particles, launch on empty space",
                                         "Left mouse: launch new particles",
                                         "Left mouse: select particles and obstacles",
                                         "Left mouse: move the view",
                                         "Left mouse: a click places a peg",
                                         "Left mouse: a drag draws a wall"};
    notices_.say(kTools[static_cast<int>(t.tool)]);
}

void Session::handle(const cmd::SpawnRandom&) {
    const WorldDef& d = doc_.world.def();
    const SpawnSettings& spawn = tools_.spawn;
    std::mt19937& rng = tools_.rng;
    // The original: mass a random integer 3..20 kg with its radius, 2.5 cm per kg at its scale of
    // 1 px = 1 cm (here 0.3..2 times the scene's typical particle), somewhere in the upper part
    // of the box, colour channels 100..255, velocity components up to 5 px per frame at 60
    // frames per second (3 m/s), scaled with the box.
    std::uniform_int_distribution<int> sizeDist(3, 20), channel(100, 255);
    const double size = sizeDist(rng) / 10.0;
    const double mass = size * spawn.typicalMass, radius = size * spawn.typicalRadius;
    std::uniform_real_distribution<double> x(radius, std::max(radius, d.width - radius));
    std::uniform_real_distribution<double> y(radius, std::max(radius, d.height / 2.0));
    const double vmax = 3.0 * std::min(d.width, d.height) / 7.0;
    std::uniform_real_distribution<double> v(-vmax, vmax);
    const Vec2 want(x(rng), y(rng));
    const auto spot = findFreeSpot(doc_.world, want, radius);
    if (!spot) {
        notices_.say("No room for a new particle");
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
    doc_.world.add(def);
    edit_.userAction("spawn particle");
    notices_.log(
        fmt("Spawned particle at [%.2f, %.2f] with velocity [%.2f, %.2f] m/s and mass %.3g kg",
            spot->x(), spot->y(), def.velocity.x(), def.velocity.y(), mass));
}

void Session::handle(const cmd::ChangeSpawnMass& c) {
    SpawnSettings& spawn = tools_.spawn;
    const double before = spawn.mass();
    spawn.changeSize(c.direction < 0 ? -1 : 1);
    if (spawn.mass() != before) edit_.remember("set new particle size");
    notices_.add({Notice::Level::Info,
                  fmt("New particles: %.3g kg, radius %.3g m (%.1f x the scene's typical)",
                      spawn.mass(), spawn.radius(), spawn.size),
                  true, false});
}

void Session::handle(const cmd::SetDiscsTurn& c) {
    if (tools_.spawn.turn == c.on) return;
    tools_.spawn.turn = c.on;
    edit_.remember(c.on ? "let new particles turn" : "give new particles fixed rotation");
    notices_.say(c.on ? "New particles turn: friction spins them, and they roll"
                      : "New particles have fixed rotation: they slide without turning");
}

void Session::handle(const cmd::SetLaunchBody& c) {
    const WorldDef& d = doc_.world.def();
    SpawnSettings& spawn = tools_.spawn;
    if (!(c.mass >= kMinLaunchMass && c.mass <= kMaxLaunchMass)) {
        notices_.say(fmt("Launch mass must be between %g and %g kg, got %g", kMinLaunchMass,
                         kMaxLaunchMass, c.mass),
                     Notice::Level::Warning);
        return;
    }
    const double maxRadius = 0.5 * std::min(d.width, d.height);
    if (!(c.radius >= 0.0 && c.radius <= maxRadius)) {
        notices_.say(fmt("Launch radius must be above 0 and at most half the box (%.3g m), got %g",
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
        edit_.remember("set new particles");
    }
    notices_.log(fmt("New particles: %g kg, radius %g m%s", spawn.mass(), spawn.radius(),
                     spawn.fixedRadius ? "" : " (from the mass)"));
}

}  // namespace psb::app
