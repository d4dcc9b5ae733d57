#pragma once
// Undo and redo of the user's edits: a bounded history of the session's states.
//
// Each entry is the state just before one edit (a snapshot), with the edit's short label
// ("delete particle", "set restitution"). Undo puts the current state on the redo side and gives
// back the newest snapshot; redo does the reverse; a new edit forgets everything on the redo
// side. Snapshots are whole states, not inverse operations, so an entry undoes any edit alike
// (a deletion, a scene opened, a time speed changed) and nothing about an edit's inverse has to
// be kept right. A World copies cheaply (flat arrays); the exact mode's event state is dropped
// from snapshots (World::dropEventState: it is rebuilt from the particles at the next step, as
// after any edit), so a snapshot of n particles holds about 80 n bytes. The scene as loaded is
// shared by every snapshot of it and counted once.
//
// Time. A snapshot is the world as it was just before the edit, its clock included: undoing an
// edit made while running restores the world of that moment, so the simulated time goes back
// to it (the steps made since are undone with the edit).
//
// Coalescing (the rule). An edit of a continuous control is a label starting with "set " (a
// slider drag, repeated E, [ or ',' presses). Such an edit merges into the newest entry when
// that entry has the same label, nothing was undone or redone since, and the previous edit of
// it was at most `coalesceSeconds` before (on the session's frame clock): a whole drag, or a
// burst of presses, is one entry that undoes to the value before it. Every other edit is an
// entry of its own.
//
// Memory bound (the rule). After every change, the oldest entries are dropped while there are
// more than `maxEntries` or they hold more than `budgetBytes`; the newest entry is always kept,
// so the last edit stays undoable even when one snapshot alone exceeds the budget. With the
// defaults (1000 entries, 200 MB) a scene of 10^4 particles (about 0.8 MB a snapshot) keeps
// about 230 steps, and at least 100 steps are kept for scenes up to 2.5 * 10^4 particles.

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/world.hpp>

#include "session/document.hpp"
#include "session/interaction.hpp"

namespace psb::app {

/// What an undo restores: everything a user's edit can change in the session.
struct UndoState {
    World world;
    std::shared_ptr<const World> loaded;  ///< the scene as loaded (Reset's target)
    SceneInfo meta;                       ///< its name, description, bins
    ParticleId selection = kNullParticle;
    std::optional<std::size_t> selectedObstacle;  ///< index into world.obstacles()
    SpawnSettings spawn;
    double timeScale = 1.0;
    bool dirty = false;
    /// The scene's file: restored with an undo to another scene (within one scene, a save
    /// stays where it went).
    SceneFile file = {};
};

struct UndoSettings {
    std::size_t maxEntries = 1000;                 ///< undo and redo entries together
    std::size_t budgetBytes = 200u * 1000 * 1000;  ///< bytes the entries hold, together
    double coalesceSeconds = 1.0;                  ///< see "Coalescing" above
};

class UndoHistory {
  public:
    explicit UndoHistory(const UndoSettings& settings = {});

    /// Whether an edit `label` at `now` (seconds) would merge into the newest entry.
    [[nodiscard]] bool coalesces(const std::string& label, double now) const;
    /// The edit `label` was made at `now`; `before` is the state just before it. Merges into
    /// the newest entry when coalesces() (then `before` is not kept). Forgets the redo side.
    void record(const std::string& label, double now, UndoState before);

    struct Step {
        std::string label;  ///< the edit undone or redone
        UndoState state;    ///< the state to restore
    };
    /// Takes the newest entry; `current` becomes the next redo. nullopt when there is none.
    [[nodiscard]] std::optional<Step> undo(UndoState current);
    /// Takes the next redo; `current` becomes the newest entry. nullopt when there is none.
    [[nodiscard]] std::optional<Step> redo(UndoState current);

    [[nodiscard]] bool canUndo() const { return !undo_.empty(); }
    [[nodiscard]] bool canRedo() const { return !redo_.empty(); }
    /// The edit undo() would undo, redo() would redo; "" when none.
    [[nodiscard]] std::string undoLabel() const;
    [[nodiscard]] std::string redoLabel() const;
    [[nodiscard]] std::size_t undoCount() const { return undo_.size(); }
    [[nodiscard]] std::size_t redoCount() const { return redo_.size(); }
    /// Bytes the entries hold: their worlds' stateBytes, labels and names, and each distinct
    /// scene as loaded once.
    [[nodiscard]] std::size_t memoryBytes() const;
    void clear();

  private:
    struct Entry {
        std::string label;
        UndoState state;
        double time = 0.0;  ///< of the latest edit merged into it
        std::size_t bytes = 0;
    };
    [[nodiscard]] static Entry makeEntry(std::string label, double time, UndoState state);
    /// Undo (from undo_ to redo_) or redo (the other way).
    [[nodiscard]] std::optional<Step> move(std::deque<Entry>& from, std::deque<Entry>& to,
                                           UndoState current);
    void trim();

    UndoSettings settings_;
    std::deque<Entry> undo_;  ///< oldest first
    std::deque<Entry> redo_;  ///< farthest first; back() is the next redo
    std::size_t entryBytes_ = 0;
    bool mayCoalesce_ = false;  ///< no undo or redo since the newest entry was recorded
};

}  // namespace psb::app
