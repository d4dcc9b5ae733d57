// The undo history on its own: undo and redo give back the states recorded, a new edit forgets
// the redo side, continuous controls coalesce by the documented rule, and the entries stay
// within their count and memory bounds.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <particle_sandbox/world.hpp>

#include "session/same_world.hpp"
#include "session/undo_history.hpp"

namespace psb::app {
namespace {

World crowd(int n, StepMode mode = StepMode::Discrete) {
    WorldDef def;
    def.width = def.height = 2.0 * n;
    World w(def, {.mode = mode});
    w.setThreads(1);
    for (int k = 0; k < n; ++k) {
        w.add({.position = {1.0 + 2.0 * (k % n), 1.0 + 2.0 * (k / n)},
               .velocity = {0.5, -0.25 * (k % 3)},
               .mass = 1.0,
               .radius = 0.4});
    }
    return w;
}

/// A state told apart by its time speed (and a world of `n` particles).
UndoState state(double tag, int n = 3) {
    UndoState s{crowd(n),      nullptr,      SceneInfo{.name = "scene", .dt = 1.0 / 60.0},
                kNullParticle, std::nullopt, {},
                tag,           false};
    return s;
}

TEST(UndoHistory, UndoGivesBackTheStateBeforeTheEditAndRedoTheStateAfter) {
    UndoHistory h;
    EXPECT_FALSE(h.canUndo());
    EXPECT_FALSE(h.undo(state(0)).has_value());
    h.record("spawn particle", 0.0, state(1));
    h.record("delete particle", 5.0, state(2));
    EXPECT_EQ(h.undoLabel(), "delete particle");
    auto u = h.undo(state(3));  // 3: the state now
    ASSERT_TRUE(u);
    EXPECT_EQ(u->label, "delete particle");
    EXPECT_EQ(u->state.timeScale, 2.0);
    EXPECT_TRUE(h.canRedo());
    EXPECT_EQ(h.redoLabel(), "delete particle");
    EXPECT_EQ(h.undoLabel(), "spawn particle");
    auto r = h.redo(state(2));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->state.timeScale, 3.0);
    EXPECT_FALSE(h.canRedo());
    EXPECT_EQ(h.undo(state(3))->state.timeScale, 2.0);
    EXPECT_EQ(h.undo(state(2))->state.timeScale, 1.0);
    EXPECT_FALSE(h.canUndo());
    EXPECT_EQ(h.redoCount(), 2u);
}

TEST(UndoHistory, ANewEditForgetsTheRedoSide) {
    UndoHistory h;
    h.record("spawn particle", 0.0, state(1));
    h.record("spawn particle", 0.1, state(2));
    ASSERT_TRUE(h.undo(state(3)));
    ASSERT_TRUE(h.canRedo());
    h.record("switch gravity", 0.2, state(2));
    EXPECT_FALSE(h.canRedo());
    EXPECT_EQ(h.redoLabel(), "");
    EXPECT_EQ(h.undoCount(), 2u);
}

TEST(UndoHistory, TheWorldIsKeptBitForBit) {
    UndoHistory h;
    World w = crowd(50);
    for (int k = 0; k < 7; ++k)
        w.step(0.01);
    UndoState s{
        w,   nullptr, SceneInfo{.name = "scene", .dt = 1.0 / 60.0}, kNullParticle, std::nullopt, {},
        1.0, true};
    h.record("edit particle", 0.0, s);
    const auto u = h.undo(state(0));
    ASSERT_TRUE(u);
    EXPECT_TRUE(identical(u->state.world, w));
    EXPECT_TRUE(u->state.dirty);
}

TEST(UndoHistory, ContinuousControlsCoalesceWithinTheWindow) {
    UndoHistory h({.coalesceSeconds = 1.0});
    h.record("set restitution", 0.0, state(1));
    EXPECT_TRUE(h.coalesces("set restitution", 0.5));
    h.record("set restitution", 0.5, state(2));
    h.record("set restitution", 1.4, state(3));  // 0.9 s after the last: still the same drag
    EXPECT_EQ(h.undoCount(), 1u);
    h.record("set restitution", 2.5, state(4));  // 1.1 s later: a new entry
    EXPECT_EQ(h.undoCount(), 2u);
    h.record("set gravity", 2.6, state(5));  // another control
    h.record("set restitution", 2.7, state(6));
    EXPECT_EQ(h.undoCount(), 4u);
    // The merged entry undoes to the value before the whole drag.
    ASSERT_TRUE(h.undo(state(9)));
    ASSERT_TRUE(h.undo(state(6)));
    ASSERT_TRUE(h.undo(state(5)));
    EXPECT_EQ(h.undo(state(4))->state.timeScale, 1.0);
}

TEST(UndoHistory, OnlyContinuousControlsCoalesceAndNotAcrossAnUndo) {
    UndoHistory h;
    h.record("spawn particle", 0.0, state(1));
    EXPECT_FALSE(h.coalesces("spawn particle", 0.1));  // two spawns are two edits
    h.record("spawn particle", 0.1, state(2));
    EXPECT_EQ(h.undoCount(), 2u);
    h.record("set time speed", 0.2, state(3));
    ASSERT_TRUE(h.undo(state(4)));
    h.record("set restitution", 0.3, state(3));
    h.record("set new particle mass", 0.35, state(3));
    ASSERT_TRUE(h.undo(state(4)));
    // The newest entry ("set restitution") was there before the undo: a new press starts anew.
    EXPECT_FALSE(h.coalesces("set restitution", 0.4));
    EXPECT_FALSE(h.coalesces("set restitution", -1.0));  // a clock that went back
}

TEST(UndoHistory, KeepsAtMostMaxEntriesDroppingTheOldest) {
    UndoHistory h({.maxEntries = 100});
    for (int k = 0; k < 150; ++k)
        h.record("spawn particle", k, state(k));
    EXPECT_EQ(h.undoCount(), 100u);
    double last = -1.0;
    for (int k = 0; k < 100; ++k) {
        const auto u = h.undo(state(-1));
        ASSERT_TRUE(u);
        last = u->state.timeScale;
    }
    EXPECT_EQ(last, 50.0);  // 0..49 were dropped
    EXPECT_FALSE(h.canUndo());
    EXPECT_EQ(h.redoCount(), 100u);
}

TEST(UndoHistory, AHundredStepsOfTenThousandParticlesFitTheDefaultBudget) {
    UndoHistory h;
    const UndoState s = state(0, 10000);
    for (int k = 0; k < 120; ++k)
        h.record("delete particle", k, s);
    EXPECT_EQ(h.undoCount(), 120u);
    EXPECT_LE(h.memoryBytes(), UndoSettings{}.budgetBytes);
    EXPECT_GE(h.memoryBytes(), 120 * World(s.world).stateBytes());
}

TEST(UndoHistory, StaysWithinItsMemoryBudgetAndKeepsTheNewestEntry) {
    const UndoState big = state(0, 10000);
    const std::size_t one = big.world.stateBytes();
    UndoHistory h({.budgetBytes = 5 * one});
    for (int k = 0; k < 20; ++k) {
        h.record("spawn particle", k, big);
        EXPECT_LE(h.memoryBytes(), 5 * one) << "after " << k + 1;
    }
    EXPECT_GE(h.undoCount(), 3u);
    EXPECT_LE(h.undoCount(), 5u);
    // One snapshot larger than the whole budget: the last edit stays undoable.
    UndoHistory tiny({.budgetBytes = 1000});
    tiny.record("spawn particle", 0.0, big);
    tiny.record("spawn particle", 1.0, big);
    EXPECT_EQ(tiny.undoCount(), 1u);
    ASSERT_TRUE(tiny.undo(state(1)));
    EXPECT_EQ(tiny.redoCount(), 1u);
}

TEST(UndoHistory, TheSceneAsLoadedIsCountedOnceAndTheExactEventStateNotAtAll) {
    auto loaded = std::make_shared<const World>(crowd(2000));
    World exact = crowd(2000, StepMode::Exact);
    for (int k = 0; k < 3; ++k)
        exact.step(0.01);
    ASSERT_GT(exact.stateBytes(), crowd(2000).stateBytes());  // it holds event state
    UndoHistory h;
    for (int k = 0; k < 10; ++k) {
        h.record("spawn particle", k,
                 UndoState{exact,
                           loaded,
                           SceneInfo{.name = "s", .dt = 1.0 / 60.0},
                           kNullParticle,
                           std::nullopt,
                           {},
                           1.0,
                           true});
    }
    const std::size_t perEntry = crowd(2000).stateBytes();
    // Each entry also counts its own record (the World object, the labels): not the event
    // state, which for 2000 particles is hundreds of kilobytes.
    EXPECT_LE(h.memoryBytes(), 11 * perEntry + 10 * (sizeof(UndoState) + 1024));
    // The snapshot still is the world, bit for bit.
    EXPECT_TRUE(identical(h.undo(state(0))->state.world, exact));
}

TEST(UndoHistory, RefusesSettingsThatCannotWork) {
    EXPECT_THROW(UndoHistory({.maxEntries = 0}), std::invalid_argument);
    EXPECT_THROW(UndoHistory({.coalesceSeconds = -1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace psb::app
