// The session's obstacle tools: Peg and Wall gestures, selecting and removing an obstacle, the
// tools' sizes. The press / drag / release rules are obstacle_tool.hpp's.

#include <cstdio>

#include "session/session.hpp"
#include "session/units.hpp"

namespace psb::app {

namespace {

/// A drag shorter than this on screen is a click, not a wall; the pick's reach around an
/// obstacle. Pixels.
constexpr double kMinWallPixels = 4.0;
constexpr double kPickPixels = 4.0;

std::string describe(const Obstacle& o) {
    char buf[160];
    if (o.isPeg()) {
        std::snprintf(buf, sizeof buf, "peg at [%.3g, %.3g] m, radius %s", o.a.x(), o.a.y(),
                      quantity(o.radius, "m").c_str());
    } else {
        std::snprintf(buf, sizeof buf, "wall from [%.3g, %.3g] to [%.3g, %.3g] m, %s thick",
                      o.a.x(), o.a.y(), o.b.x(), o.b.y(), quantity(o.thickness(), "m").c_str());
    }
    return buf;
}

/// Why `o` may not go where it is: it would overlap a particle (a peg placed on one, a wall drawn
/// or moved through one), which would then pass out through it as the steps push them apart.
/// Empty when it keeps clear of every particle.
std::string overlapRefusal(const World& world, const Obstacle& o, const char* doing) {
    const ParticleArrays& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!o.clears(Vec2(p.x[i], p.y[i]), p.radius[i])) {
            return std::string(doing) + ": the " + obstacleNoun(o) +
                   " would overlap a particle; put it where no particle is";
        }
    }
    return {};
}

}  // namespace

std::optional<Obstacle> Session::obstaclePreview() const {
    if (tools_.obstacle.active())
        return tools_.obstacle.preview(tools_.obstacleSizes, doc_.world.def());
    if (tools_.tool != cmd::Tool::Peg) return std::nullopt;
    const Vec2 at = pointerWorld();
    const WorldDef& d = doc_.world.def();
    if (!(at.x() >= 0.0 && at.x() <= d.width && at.y() >= 0.0 && at.y() <= d.height)) {
        return std::nullopt;
    }
    return Obstacle::peg(at, tools_.obstacleSizes.pegRadius);
}

bool Session::obstacleToolOn() const {
    return tools_.tool == cmd::Tool::Peg || tools_.tool == cmd::Tool::Wall;
}

void Session::obstaclePress() {
    tools_.obstacle.press(
        tools_.tool == cmd::Tool::Peg ? ObstacleTool::Kind::Peg : ObstacleTool::Kind::Wall,
        pointerWorld());
}

void Session::obstacleRelease() {
    if (!tools_.obstacle.active()) return;
    const ObstaclePlacement p =
        tools_.obstacle.release(pointerWorld(), tools_.obstacleSizes, doc_.world.def(),
                                view_.camera().toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (!p.refusal.empty()) notices_.say(p.refusal, Notice::Level::Warning);
        return;
    }
    if (const std::string why = overlapRefusal(doc_.world, *p.obstacle, "Not placed");
        !why.empty()) {
        notices_.say(why, Notice::Level::Warning);
        return;
    }
    try {
        const std::size_t index = doc_.world.addObstacle(*p.obstacle);
        tools_.selectedObstacle.reset();
        notices_.log("Added obstacle " + std::to_string(index) + ": " + describe(*p.obstacle));
        notices_.say(std::string(p.obstacle->isPeg() ? "Peg placed" : "Wall drawn") +
                     " (Ctrl+Z undoes it)");
        edit_.userAction(p.obstacle->isPeg() ? "place peg" : "draw wall");
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        notices_.say(std::string("Obstacle refused: ") + e.what(), Notice::Level::Warning);
    }
}

void Session::obstaclePressToMove() {
    const Vec2 at = pointerWorld();
    if (doc_.world.pick(at)) return;  // a particle: the click selects it
    if (const auto i =
            pickObstacle(doc_.world.obstacles(), at, view_.camera().toWorld(kPickPixels))) {
        tools_.obstacle.pressOn(*i, doc_.world.obstacles()[*i], at);
        tools_.selectedObstacle = i;  // highlighted while it is dragged
    }
}

bool Session::obstacleMoveRelease() {
    if (!tools_.obstacle.active()) return false;
    const std::size_t index = tools_.obstacle.movedIndex();
    const ObstaclePlacement p =
        tools_.obstacle.release(pointerWorld(), tools_.obstacleSizes, doc_.world.def(),
                                view_.camera().toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (p.refusal.empty()) return false;  // a click
        notices_.say(p.refusal, Notice::Level::Warning);
        return true;
    }
    if (index >= doc_.world.obstacles().size()) return true;
    if (const std::string why = overlapRefusal(doc_.world, *p.obstacle, "Not moved");
        !why.empty()) {
        notices_.say(why, Notice::Level::Warning);
        return true;
    }
    Obstacles moved = doc_.world.obstacles();
    moved[index] = *p.obstacle;
    try {
        doc_.world.setObstacles(std::move(moved));
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        notices_.say(std::string("Not moved: ") + e.what(), Notice::Level::Warning);
        return true;
    }
    tools_.selectedObstacle = index;
    tools_.selection.clear();
    tools_.closePrompt();
    notices_.log("Moved obstacle " + std::to_string(index) + ": " + describe(*p.obstacle));
    notices_.say(std::string("Moved the ") + obstacleNoun(*p.obstacle) + " (Ctrl+Z puts it back)");
    edit_.userAction(p.obstacle->isPeg() ? "move peg" : "move wall");
    return true;
}

bool Session::selectObstacleAt() {
    const auto index =
        pickObstacle(doc_.world.obstacles(), pointerWorld(), view_.camera().toWorld(kPickPixels));
    if (!index) return false;
    tools_.selectedObstacle = index;
    const Obstacle& o = doc_.world.obstacles()[*index];
    notices_.log("Selected obstacle " + std::to_string(*index) + ": " + describe(o));
    notices_.say(std::string("Selected a ") + obstacleNoun(o) + ": Delete or Backspace removes it");
    return true;
}

void Session::removeObstacle(std::size_t index) {
    if (index >= doc_.world.obstacles().size()) {
        notices_.say("No obstacle " + std::to_string(index) + " to remove (there are " +
                         std::to_string(doc_.world.obstacles().size()) + ")",
                     Notice::Level::Warning);
        return;
    }
    const Obstacle o = doc_.world.obstacles()[index];
    doc_.world.removeObstacle(index);
    if (tools_.selectedObstacle == index) {
        tools_.selectedObstacle.reset();
    } else if (tools_.selectedObstacle && *tools_.selectedObstacle > index) {
        --*tools_.selectedObstacle;
    }
    notices_.log("Removed obstacle " + std::to_string(index) + ": " + describe(o));
    notices_.say(std::string("Removed the ") + obstacleNoun(o) + " (Ctrl+Z brings it back)");
    edit_.userAction(o.isPeg() ? "remove peg" : "remove wall");
}

void Session::handle(const cmd::RemoveObstacle& c) {
    removeObstacle(c.index);
}

void Session::handle(const cmd::SetObstacleSizes& c) {
    const ObstacleSizes sizes{c.pegRadius, c.wallThickness};
    if (const std::string why = obstacleSizesRefusal(sizes, doc_.world.def()); !why.empty()) {
        notices_.say(why, Notice::Level::Warning);
        return;
    }
    tools_.obstacleSizes = sizes;
}

}  // namespace psb::app
