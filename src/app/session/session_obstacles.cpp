// The session's obstacle tools: Peg and Wall gestures, selecting and removing an obstacle, the
// tools' sizes. The press / drag / release rules are obstacle_tool.hpp's.

#include <cstdio>

#include "session/accuracy.hpp"
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

}  // namespace

std::optional<Obstacle> Session::obstaclePreview() const {
    if (obstacleTool_.active()) return obstacleTool_.preview(obstacleSizes_, world_.def());
    if (tool_ != cmd::Tool::Peg) return std::nullopt;
    const Vec2 at = pointerWorld();
    const WorldDef& d = world_.def();
    if (!(at.x() >= 0.0 && at.x() <= d.width && at.y() >= 0.0 && at.y() <= d.height)) {
        return std::nullopt;
    }
    return Obstacle::peg(at, obstacleSizes_.pegRadius);
}

bool Session::obstacleToolOn() const {
    return tool_ == cmd::Tool::Peg || tool_ == cmd::Tool::Wall;
}

void Session::obstaclePress() {
    obstacleTool_.press(
        tool_ == cmd::Tool::Peg ? ObstacleTool::Kind::Peg : ObstacleTool::Kind::Wall,
        pointerWorld());
}

void Session::obstacleRelease() {
    if (!obstacleTool_.active()) return;
    const ObstaclePlacement p = obstacleTool_.release(pointerWorld(), obstacleSizes_, world_.def(),
                                                      camera_.toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (!p.refusal.empty()) say(p.refusal, Notice::Level::Warning);
        return;
    }
    try {
        const std::size_t index = world_.addObstacle(*p.obstacle);
        selectedObstacle_.reset();
        obstaclesChanged();
        log("Added obstacle " + std::to_string(index) + ": " + describe(*p.obstacle));
        say(std::string(p.obstacle->isPeg() ? "Peg placed" : "Wall drawn") + " (Ctrl+Z undoes it)");
        userAction(p.obstacle->isPeg() ? "place peg" : "draw wall");
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        say(std::string("Obstacle refused: ") + e.what(), Notice::Level::Warning);
    }
}

void Session::obstaclePressToMove() {
    const Vec2 at = pointerWorld();
    if (world_.pick(at)) return;  // a particle: the click selects it
    if (const auto i = pickObstacle(world_.obstacles(), at, camera_.toWorld(kPickPixels))) {
        obstacleTool_.pressOn(*i, world_.obstacles()[*i], at);
        selectedObstacle_ = i;  // highlighted while it is dragged
    }
}

bool Session::obstacleMoveRelease() {
    if (!obstacleTool_.active()) return false;
    const std::size_t index = obstacleTool_.movedIndex();
    const ObstaclePlacement p = obstacleTool_.release(pointerWorld(), obstacleSizes_, world_.def(),
                                                      camera_.toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (p.refusal.empty()) return false;  // a click
        say(p.refusal, Notice::Level::Warning);
        return true;
    }
    if (index >= world_.obstacles().size()) return true;
    Obstacles moved = world_.obstacles();
    moved[index] = *p.obstacle;
    try {
        world_.setObstacles(std::move(moved));
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        say(std::string("Not moved: ") + e.what(), Notice::Level::Warning);
        return true;
    }
    selectedObstacle_ = index;
    selection_.clear();
    closeEdit();
    obstaclesChanged();
    log("Moved obstacle " + std::to_string(index) + ": " + describe(*p.obstacle));
    say(std::string("Moved the ") + obstacleNoun(*p.obstacle) + " (Ctrl+Z puts it back)");
    userAction(p.obstacle->isPeg() ? "move peg" : "move wall");
    return true;
}

bool Session::selectObstacleAt() {
    const auto index =
        pickObstacle(world_.obstacles(), pointerWorld(), camera_.toWorld(kPickPixels));
    if (!index) return false;
    selectedObstacle_ = index;
    const Obstacle& o = world_.obstacles()[*index];
    log("Selected obstacle " + std::to_string(*index) + ": " + describe(o));
    say(std::string("Selected a ") + obstacleNoun(o) + ": Delete or Backspace removes it");
    return true;
}

void Session::removeObstacle(std::size_t index) {
    if (index >= world_.obstacles().size()) {
        say("No obstacle " + std::to_string(index) + " to remove (there are " +
                std::to_string(world_.obstacles().size()) + ")",
            Notice::Level::Warning);
        return;
    }
    const Obstacle o = world_.obstacles()[index];
    world_.removeObstacle(index);
    if (selectedObstacle_ == index) {
        selectedObstacle_.reset();
    } else if (selectedObstacle_ && *selectedObstacle_ > index) {
        --*selectedObstacle_;
    }
    obstaclesChanged();
    log("Removed obstacle " + std::to_string(index) + ": " + describe(o));
    say(std::string("Removed the ") + obstacleNoun(o) + " (Ctrl+Z brings it back)");
    userAction(o.isPeg() ? "remove peg" : "remove wall");
}

void Session::setObstacleSizes(const cmd::SetObstacleSizes& c) {
    const ObstacleSizes sizes{c.pegRadius, c.wallThickness};
    if (const std::string why = obstacleSizesRefusal(sizes, world_.def()); !why.empty()) {
        say(why, Notice::Level::Warning);
        return;
    }
    obstacleSizes_ = sizes;
}

void Session::obstaclesChanged() {
    exactRefusal_ = exactModeRefusal(world_);
}

}  // namespace psb::app
