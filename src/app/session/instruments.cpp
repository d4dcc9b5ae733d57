// The lab's instruments: the stopwatch's and the recording's commands, and how the recording
// and the collision card listen to the world's steps.

#include "session/instruments.hpp"

#include <algorithm>
#include <string>

#include "session/collision_feed.hpp"
#include "session/document.hpp"
#include "session/notices.hpp"
#include "session/scene_view.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"

namespace psb::app {

void Instruments::handle(const cmd::Stopwatch& c, Context& x) {
    using A = cmd::Stopwatch::Action;
    const double t = x.doc.world.time();
    A action = c.action;
    if (action == A::LapOrReset) action = stopwatch.running() ? A::Lap : A::Reset;
    switch (action) {
        case A::StartStop:
            if (stopwatch.running()) {
                stopwatch.stop(t);
                x.notices.say(fmt("Stopwatch stopped at %.3f s", stopwatch.reading(t)));
            } else {
                stopwatch.start(t);
                x.notices.say(x.clock.paused
                                  ? std::string("Stopwatch started: it runs with simulated "
                                                "time (") +
                                        x.notices.key("Space", "Play") + ")"
                                  : std::string("Stopwatch started"));
            }
            break;
        case A::Lap:
            if (!stopwatch.running()) return;
            stopwatch.lap(t);
            x.notices.say(fmt("Lap %zu: %.3f s", stopwatch.laps().size(), stopwatch.laps().back()));
            break;
        case A::Reset:
        case A::LapOrReset:
            if (!stopwatch.used()) return;
            stopwatch.reset();
            x.notices.say("Stopwatch reset");
            break;
    }
}

void Instruments::handle(const cmd::SetRecording& c, Context& x) {
    const World& world = x.doc.world;
    const std::optional<ParticleId> selected = x.tools.selection.id();
    const bool card = cardListens(x.view.options().collision, world);
    if (!c.on) {
        if (!data.recording()) return;
        data.stop();
        listen(x.doc, card, selected);
        const std::size_t hits = data.collisions().size();
        x.notices.say(
            fmt("Recording stopped: %zu samples, %zu collision%s (Data section: Export or Copy)",
                data.trajectory().samples().size(), hits, hits == 1 ? "" : "s"));
        return;
    }
    if (data.recording()) return;
    std::vector<ParticleId> ids;
    if (selected && world.contains(*selected)) {
        ids.push_back(*selected);
    } else if (world.size() > DataRecorder::kMaxAllParticles) {
        x.notices.say(fmt("Not recording: select a particle first (recording all %zu particles "
                          "is limited to %zu)",
                          world.size(), DataRecorder::kMaxAllParticles),
                      Notice::Level::Warning);
        return;
    } else {
        ids = world.ids();
        std::sort(ids.begin(), ids.end(),
                  [](ParticleId a, ParticleId b) { return a.slot < b.slot; });
    }
    if (ids.empty()) {
        x.notices.say("Not recording: the box is empty", Notice::Level::Warning);
        return;
    }
    data.start(world, ids, c.every > 0 ? c.every : data.every());
    listen(x.doc, card, selected);
    const std::string who =
        ids.size() == 1
            ? fmt("particle %llu", static_cast<unsigned long long>(particleNumber(ids[0])))
            : fmt("all %zu particles", ids.size());
    x.notices.say(fmt("Recording %s every %d step%s (%s)", who.c_str(), data.every(),
                      data.every() == 1 ? "" : "s",
                      x.notices.key("X stops", "Data: Stop recording")));
}

void Instruments::startOver(const World& world, bool newScene, const ObservablesSample& first) {
    lastCollision.clear();
    stopwatch.reset();
    if (!newScene) return;
    data.restartRun();
    // The run's first row: the world as it starts. The ruler's reading stays (a restart, a
    // revert, an undo) unless the box changed size; a scene opened lays it anew (StartOver).
    data.sample(first);
    ruler.keepIn(world.def().width, world.def().height);
}

void Instruments::listen(Document& doc, bool card, std::optional<ParticleId> selected) const {
    doc.listen(mergeWanted(data.collisionsWanted(), LastCollision::wanted(card, selected)));
}

void Instruments::shown(ShowOption option, bool on, Document& doc,
                        std::optional<ParticleId> selected) {
    if (option == ShowOption::Ruler && !on) ruler.letGo();
    if (option == ShowOption::Collision) {
        const bool card = cardListens(on, doc.world);
        if (!card) lastCollision.clear();
        listen(doc, card, selected);
    }
}

void Instruments::beforeStep(Document& doc, bool card, std::optional<ParticleId> selected) {
    listen(doc, card, selected);
    data.beforeStep(doc.world);
}

void Instruments::afterStep(Document& doc, bool card, std::optional<ParticleId> selected) {
    const std::vector<Collision> records = doc.heard();
    data.afterStep(doc.world, records);
    if (card) lastCollision.heard(records, doc.world, selected);
}

}  // namespace psb::app
