// The session's hand: pointer presses, moves and releases turned into grabs, flings, launches,
// clicks and pans (the rules are interaction.hpp's and obstacle_tool.hpp's).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>

#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/stopwatch.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// The hand.

void Session::pointerDown(const cmd::PointerDown& c) {
    pointer_ = c.screen;
    pointerTime_ = c.time;
    if (tool_ == cmd::Tool::Pan) {
        panFrom_ = c.screen;
        return;
    }
    if (tool_ == cmd::Tool::Select) {
        obstaclePressToMove();  // on an obstacle: a drag moves it
        return;                 // the release selects
    }
    if (obstacleToolOn()) {
        obstaclePress();
        return;
    }
    interaction_.press(world_, pointerWorld(), c.time, tool_ == cmd::Tool::Fling);
    if (interaction_.mode() == Interaction::Mode::Holding) {
        const Particle p = world_.get(interaction_.held());
        log(fmt("Grabbed particle at [%.2f, %.2f]", p.position.x(), p.position.y()));
        // The energy is measured from the grab; a click that only selects changes nothing.
        accuracy_.resetReference(monitoredEnergy(world_));
    }
}

void Session::pointerMove(const cmd::PointerMove& c) {
    if (panFrom_) {
        camera_.panPixels(c.screen - *panFrom_);
        camera_.keepNear(world_.def().width, world_.def().height);
        panFrom_ = c.screen;
        fitted_ = false;
    }
    pointer_ = c.screen;
    pointerTime_ = c.time;
    obstacleTool_.moveTo(pointerWorld());
    interaction_.moveTo(pointerWorld(), c.time);
}

void Session::pointerUp(const cmd::PointerUp& c) {
    pointer_ = c.screen;
    pointerTime_ = c.time;
    if (tool_ == cmd::Tool::Pan) {
        panFrom_.reset();
        return;
    }
    if (tool_ == cmd::Tool::Select) {
        if (obstacleMoveRelease()) return;  // moved, or the move refused; else a click
        ReleaseResult r;
        r.kind = ReleaseResult::Kind::Clicked;
        if (const auto id = world_.pick(pointerWorld())) r.id = *id;
        click(r);
        return;
    }
    if (obstacleToolOn()) {
        obstacleRelease();
        return;
    }
    const ReleaseResult r = interaction_.release(world_, pointerWorld(), c.time, spawn_,
                                                 launchSettings(), view_.arrowSeconds);
    using K = ReleaseResult::Kind;
    const std::string at = fmt("at [%.2f, %.2f]", r.position.x(), r.position.y());
    const std::string v = fmt("with velocity [%.2f, %.2f] m/s", r.velocity.x(), r.velocity.y());
    if (r.kind == K::Flung) log("Released particle " + at + " " + v);
    if (r.kind == K::Launched) log("Launched particle " + at + " " + v);
    if ((r.kind == K::Flung || r.kind == K::Launched) && r.capped) {
        say(fmt("Speed capped at %.3g m/s (%g box widths per second)", r.velocity.norm(),
                kMaxLaunchBoxesPerSecond));
    }
    if (r.kind == K::Refused) say(r.message);
    if (r.kind == K::Clicked) click(r);
    if (r.kind == K::Flung) userAction("fling particle");
    if (r.kind == K::Launched) userAction("launch particle");
}

void Session::click(const ReleaseResult& r) {
    if (!r.id.isNull()) {
        if (prompt_.target() != r.id) closeEdit();
        selectedObstacle_.reset();
        selection_.select(r.id);
        std::string line = selectionLogLine(world_.get(r.id));
        log(line.substr(4));  // without its "[I] "
    } else if (selectObstacleAt()) {
        selection_.clear();
        closeEdit();
    } else if (selection_.id() || selectedObstacle_) {
        selection_.clear();
        selectedObstacle_.reset();
        closeEdit();
        say("Selection cleared");
    }
}

void Session::deleteHeld() {
    if (const auto p = interaction_.deleteHeld(world_)) {
        log(deletionLogLine(*p).substr(4));
        notices_.push_back({Notice::Level::Info, "Deleted a particle", true, false});
        userAction("delete particle");
        checkSelection();
    } else if (selectedObstacle_) {
        removeObstacle(*selectedObstacle_);
    }
}

void Session::deleteParticle(ParticleId id) {
    if (!world_.contains(id)) return;
    if (interaction_.mode() != Interaction::Mode::Idle && interaction_.held() == id) {
        interaction_.reset();
    }
    const Particle p = world_.get(id);
    world_.remove(id);
    log(deletionLogLine(p).substr(4));
    notices_.push_back({Notice::Level::Info, "Deleted a particle", true, false});
    userAction("delete particle");
    checkSelection();
}

void Session::checkSelection() {
    if (selection_.forgetIfGone(world_)) {
        closeEdit();
        say("Selection cleared: the particle was deleted");
    }
}

}  // namespace psb::app
