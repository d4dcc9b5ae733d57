// What the tools answer and follow beyond their commands: what a launch would give, the
// selection, the held particle shown at the hand, and a new scene or an undo.

#include "session/tools.hpp"

#include "session/notices.hpp"
#include "session/timeline.hpp"
#include "session/undo_history.hpp"

namespace psb::app {

void Tools::followScene(const World& world) {
    psb::app::followScene(spawn, world);
    obstacleSizes = obstacleSizesFor(spawn.typicalRadius);
}

void Tools::restore(const UndoState& state, const World& world) {
    spawn = state.spawn;
    if (!state.selection.isNull() && world.contains(state.selection)) {
        selection.select(state.selection);
    }
    if (state.selectedObstacle && *state.selectedObstacle < world.obstacles().size()) {
        selectedObstacle = state.selectedObstacle;
    }
}

LaunchSettings Tools::launchSettings(const Camera& camera, const WorldDef& box) {
    LaunchSettings s;
    s.window = 0.1;
    // A hand that moved less than 4 pixels in the last 100 ms was holding still.
    s.minDistance = camera.toWorld(4.0);
    s.maxSpeed = maxLaunchSpeed(box);
    return s;
}

CappedVelocity Tools::launchPreview(const Camera& camera, const WorldDef& box,
                                    double arrowSeconds) const {
    if (hand.mode() != Interaction::Mode::Launching) return {};
    return hand.launchVelocityNow(launchSettings(camera, box), arrowSeconds);
}

std::optional<Particle> Tools::selected(const World& world) const {
    if (const auto id = selection.id(); id && world.contains(*id)) return world.get(*id);
    return std::nullopt;
}

ParticleId Tools::trailParticle(const World& world) const {
    if (const auto id = selection.id(); id && world.contains(*id)) return *id;
    return holding() ? hand.held() : kNullParticle;
}

void Tools::hold(World& world, Timeline& timeline, double now, const Camera& camera) const {
    if (const auto h = hand.hold(world, now, launchSettings(camera, world.def()))) {
        timeline.setPosition(world, h->id, h->position);
        timeline.setVelocity(world, h->id, h->velocity);
    }
}

void Tools::checkSelection(const World& world, Notices& notices) {
    if (selection.forgetIfGone(world)) {
        closePrompt();
        notices.say("Selection cleared: the particle was deleted");
    }
}

}  // namespace psb::app
