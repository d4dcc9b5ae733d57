#pragma once
// The lab's instruments on the world, which measure it and never change it: the recording of
// the particles' paths and collisions with the run's series (data_recorder.hpp), the last
// collision card (last_collision.hpp), the stopwatch on simulated time (lab_stopwatch.hpp) and
// the ruler (lab_ruler.hpp). The recording and the card read the world's one collision log:
// before each step they have the world's owner (the document) record what they want together
// (collision_feed.hpp), after it each takes what it follows.

#include <optional>
#include <vector>

#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/command.hpp"
#include "session/data_recorder.hpp"
#include "session/lab_ruler.hpp"
#include "session/lab_stopwatch.hpp"
#include "session/last_collision.hpp"

namespace psb::app {

struct Document;
class Notices;
class SceneView;
class SimClock;
struct Tools;

struct Instruments {
    /// What the instruments' commands reach beyond them: the world they measure (through its
    /// owner, the document, which records the collisions they want), the particle selected (the
    /// tools), whether the card is shown (the view), whether time runs (the clock).
    struct Context {
        Document& doc;
        const Tools& tools;
        const SceneView& view;
        const SimClock& clock;
        Notices& notices;
    };
    /// U, Shift+U, the Time section's buttons.
    void handle(const cmd::Stopwatch& c, Context& x);
    /// X, the Data section's Record: the selected particle, or every one (up to a limit).
    void handle(const cmd::SetRecording& c, Context& x);

    /// A world put in place (`world`; a scene opened, an undo): the card and the stopwatch
    /// start over. A new scene (`newScene`: opened, restarted, reverted) starts the run's
    /// series over too, with `first` as its first row, stops a recording and keeps what it
    /// recorded, to export, and keeps the ruler where it is unless the box changed size (a
    /// scene opened lays it anew: StartOver::scene).
    void startOver(const World& world, bool newScene, const ObservablesSample& first);
    /// Whether the card follows the collisions of `world` (shown, or a world of few particles).
    [[nodiscard]] static bool cardListens(bool cardShown, const World& world) {
        return LastCollision::listening(cardShown, world.size());
    }
    /// Has the document's world record the collisions the instruments want now: the
    /// recording's, and the card's while it listens (`card`, following `selected`).
    void listen(Document& doc, bool card, std::optional<ParticleId> selected) const;
    /// A show option was switched: the ruler hidden lets go; the card hidden in a large scene
    /// stops listening, and a card kept would go stale.
    void shown(ShowOption option, bool on, Document& doc, std::optional<ParticleId> selected);

    /// Around one step of the document's world: before it, the world records what the
    /// instruments want (`card`: whether the card listens, as the step's start has it) and the
    /// recording drops what it held after the world's time; after it, the recording and the card
    /// take the step's collisions.
    void beforeStep(Document& doc, bool card, std::optional<ParticleId> selected);
    void afterStep(Document& doc, bool card, std::optional<ParticleId> selected);

    DataRecorder data;
    LastCollision lastCollision;
    LabStopwatch stopwatch;
    LabRuler ruler;
};

}  // namespace psb::app
