// The obstacle tools: Peg and Wall gestures, selecting, moving and removing an obstacle, the
// tools' sizes. The press / drag / release rules are obstacle_tool.hpp's.

#include <cstdio>

#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/notices.hpp"
#include "session/scene_view.hpp"
#include "session/tools.hpp"
#include "session/units.hpp"

namespace psb::app {

namespace {

/// A drag shorter than this on screen is a click, not a wall; the pick's reach around an
/// obstacle. Pixels.
constexpr double kMinWallPixels = 4.0;
constexpr double kPickPixels = 4.0;

/// `o` in `axes`, the window's.
std::string describe(const Obstacle& o, const Axes& axes) {
    const Vec2 a = axes.point(o.a), b = axes.point(o.b);
    char buf[160];
    if (o.isPeg()) {
        std::snprintf(buf, sizeof buf, "peg at [%.3g, %.3g] m, radius %s", a.x(), a.y(),
                      quantity(o.radius, "m").c_str());
    } else {
        std::snprintf(buf, sizeof buf, "wall from [%.3g, %.3g] to [%.3g, %.3g] m, %s thick", a.x(),
                      a.y(), b.x(), b.y(), quantity(o.thickness(), "m").c_str());
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

std::optional<Obstacle> Tools::obstaclePreview(const Camera& camera, const WorldDef& d) const {
    if (obstacle.active()) return obstacle.preview(obstacleSizes, d);
    if (tool != cmd::Tool::Peg || !pointerIn) return std::nullopt;
    const Vec2 at = pointerWorld(camera);
    if (!(at.x() >= 0.0 && at.x() <= d.width && at.y() >= 0.0 && at.y() <= d.height)) {
        return std::nullopt;
    }
    return Obstacle::peg(at, obstacleSizes.pegRadius);
}

void Tools::obstaclePress(Context& x) {
    obstacle.press(tool == cmd::Tool::Peg ? ObstacleTool::Kind::Peg : ObstacleTool::Kind::Wall,
                   pointerWorld(x.view.camera()));
}

void Tools::obstacleRelease(Context& x) {
    if (!obstacle.active()) return;
    const ObstaclePlacement p =
        obstacle.release(pointerWorld(x.view.camera()), obstacleSizes, x.doc.world.def(),
                         x.view.camera().toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (!p.refusal.empty()) x.notices.say(p.refusal, Notice::Level::Warning);
        return;
    }
    if (const std::string why = overlapRefusal(x.doc.world, *p.obstacle, "Not placed");
        !why.empty()) {
        x.notices.say(why, Notice::Level::Warning);
        return;
    }
    try {
        const std::size_t index = x.doc.world.addObstacle(*p.obstacle);
        selectedObstacle.reset();
        x.notices.log("Added obstacle " + std::to_string(index) + ": " +
                      describe(*p.obstacle, x.view.axes(x.doc.world.def())));
        x.notices.say(std::string(p.obstacle->isPeg() ? "Peg placed" : "Wall drawn") + " (" +
                      x.notices.undoKey() + " undoes it)");
        x.edit.userAction(p.obstacle->isPeg() ? "place peg" : "draw wall");
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        x.notices.say(std::string("Obstacle refused: ") + e.what(), Notice::Level::Warning);
    }
}

void Tools::obstaclePressToMove(Context& x) {
    const Vec2 at = pointerWorld(x.view.camera());
    if (x.doc.world.pick(at)) return;  // a particle: the click selects it
    if (const auto i =
            pickObstacle(x.doc.world.obstacles(), at, x.view.camera().toWorld(kPickPixels))) {
        obstacle.pressOn(*i, x.doc.world.obstacles()[*i], at);
        selectedObstacle = i;  // highlighted while it is dragged
    }
}

bool Tools::obstacleMoveRelease(Context& x) {
    if (!obstacle.active()) return false;
    const std::size_t index = obstacle.movedIndex();
    const ObstaclePlacement p =
        obstacle.release(pointerWorld(x.view.camera()), obstacleSizes, x.doc.world.def(),
                         x.view.camera().toWorld(kMinWallPixels));
    if (!p.obstacle) {
        if (p.refusal.empty()) return false;  // a click
        x.notices.say(p.refusal, Notice::Level::Warning);
        return true;
    }
    if (index >= x.doc.world.obstacles().size()) return true;
    if (const std::string why = overlapRefusal(x.doc.world, *p.obstacle, "Not moved");
        !why.empty()) {
        x.notices.say(why, Notice::Level::Warning);
        return true;
    }
    Obstacles moved = x.doc.world.obstacles();
    moved[index] = *p.obstacle;
    try {
        x.doc.world.setObstacles(std::move(moved));
    } catch (const std::exception& e) {  // InvalidArgument: what the world refuses
        x.notices.say(std::string("Not moved: ") + e.what(), Notice::Level::Warning);
        return true;
    }
    selectedObstacle = index;
    selection.clear();
    closePrompt();
    x.notices.log("Moved obstacle " + std::to_string(index) + ": " +
                  describe(*p.obstacle, x.view.axes(x.doc.world.def())));
    x.notices.say(std::string("Moved the ") + obstacleNoun(*p.obstacle) + " (" +
                  x.notices.undoKey() + " puts it back)");
    x.edit.userAction(p.obstacle->isPeg() ? "move peg" : "move wall");
    return true;
}

bool Tools::selectObstacleAt(Context& x) {
    const auto index = pickObstacle(x.doc.world.obstacles(), pointerWorld(x.view.camera()),
                                    x.view.camera().toWorld(kPickPixels));
    if (!index) return false;
    selectedObstacle = index;
    const Obstacle& o = x.doc.world.obstacles()[*index];
    x.notices.log("Selected obstacle " + std::to_string(*index) + ": " +
                  describe(o, x.view.axes(x.doc.world.def())));
    x.notices.say(std::string("Selected a ") + obstacleNoun(o) + ": " +
                  x.notices.key("Delete or Backspace",
                                o.isPeg() ? "Tools: Delete peg" : "Tools: Delete wall") +
                  " removes it");
    return true;
}

void Tools::removeObstacle(std::size_t index, Context& x) {
    if (index >= x.doc.world.obstacles().size()) {
        x.notices.say("No obstacle " + std::to_string(index) + " to remove (there are " +
                          std::to_string(x.doc.world.obstacles().size()) + ")",
                      Notice::Level::Warning);
        return;
    }
    const Obstacle o = x.doc.world.obstacles()[index];
    x.doc.world.removeObstacle(index);
    if (selectedObstacle == index) {
        selectedObstacle.reset();
    } else if (selectedObstacle && *selectedObstacle > index) {
        --*selectedObstacle;
    }
    x.notices.log("Removed obstacle " + std::to_string(index) + ": " +
                  describe(o, x.view.axes(x.doc.world.def())));
    x.notices.say(std::string("Removed the ") + obstacleNoun(o) + " (" + x.notices.undoKey() +
                  " brings it back)");
    x.edit.userAction(o.isPeg() ? "remove peg" : "remove wall");
}

void Tools::handle(const cmd::RemoveObstacle& c, Context& x) {
    removeObstacle(c.index, x);
}

void Tools::handle(const cmd::SetObstacleSizes& c, Context& x) {
    const ObstacleSizes sizes{c.pegRadius, c.wallThickness};
    if (const std::string why = obstacleSizesRefusal(sizes, x.doc.world.def()); !why.empty()) {
        x.notices.say(why, Notice::Level::Warning);
        return;
    }
    obstacleSizes = sizes;
}

}  // namespace psb::app
