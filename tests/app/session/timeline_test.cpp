// Step back in time: every past frame rebuilt from the timeline is the state the world had
// then, bit for bit, and keeps stepping like it, in every mode and across user edits.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include <particle_sandbox/world.hpp>

#include "session/same_world.hpp"
#include "session/timeline.hpp"

namespace psb::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDt = 0.01;  ///< the frame length (the scene's dt) the gas is stepped by

World gas(StepMode mode, int n = 150) {
    WorldDef def;
    def.width = def.height = 40.0;
    def.restitution = 0.95;
    if (mode != StepMode::Exact) def.gravity = Vec2(0.0, 9.81);
    World w(def, {.mode = mode, .substeps = 4});
    w.setThreads(1);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(1.0, 39.0);
    std::normal_distribution<double> v(0.0, 5.0);
    for (int k = 0; k < n; ++k) {
        w.add({.position = {u(rng), u(rng)},
               .velocity = {v(rng), v(rng)},
               .mass = 1.0 + 0.01 * k,
               .radius = 0.4 + 0.003 * k});
    }
    return w;
}

/// One 60 Hz frame as the app runs it: the world is stepped by the scene's dt as often as the
/// accumulated time allows, each step reported, then the frame is recorded.
std::int64_t frame(World& world, Timeline& timeline, double& accumulator) {
    accumulator += 1.0 / 60.0;
    while (accumulator >= kDt) {
        world.step(kDt);
        timeline.stepped(kDt);
        accumulator -= kDt;
    }
    return timeline.record(world);
}

/// Runs `frames` frames the way the app does (a 60 Hz frame steps the world by the scene's dt
/// as often as the accumulated time allows), recording each, with the user's edits of
/// `edit(world, frame)` (which returns whether it changed anything). Keeps a copy of the world
/// at every frame as the reference.
template <typename Edit>
std::vector<World> run(World& world, Timeline& timeline, int frames, Edit edit) {
    std::vector<World> reference;
    const std::int64_t start = timeline.empty() ? 0 : timeline.lastFrame() + 1;
    double accumulator = 0.0;
    for (int f = 0; f < frames; ++f) {
        if (edit(world, f)) timeline.edited();
        EXPECT_EQ(frame(world, timeline, accumulator),
                  start + static_cast<std::int64_t>(reference.size()));
        reference.push_back(world);
    }
    return reference;
}

bool noEdits(World&, int) {
    return false;
}

// A user at work: launches, deletes, holds and drags a particle for a while, changes the
// bounce and the mode's settings.
bool userEdits(World& w, int f) {
    static ParticleId held;
    switch (f) {
        case 20:
            w.add({.position = {20.0, 5.0}, .velocity = {3.0, -2.0}, .mass = 4.0, .radius = 1.2});
            return true;
        case 45:
            return w.remove(w.ids()[7]);
        case 60:
            held = w.ids()[3];
            w.setKinematic(held, true);
            return true;
        case 61:
        case 62:
        case 63:
        case 64:
            w.setPosition(held, Vec2(10.0 + f - 60, 10.0));
            w.setVelocity(held, Vec2(60.0, 0.0));
            return true;
        case 65:
            w.setKinematic(held, false);
            return true;
        case 90:
            w.setRestitution(0.7);
            return true;
        default:
            return false;
    }
}

/// A budget of about 40 keyframes of `world`: keyframes ~0.27 s (16 frames) apart, so that
/// rebuilding a frame re-simulates up to 15 frames.
Timeline sparseTimeline(const World& world) {
    World probe = world;
    probe.step(kDt);  // the exact mode's event state exists after a step
    return Timeline({.horizonSeconds = 10.0, .budgetBytes = 40 * probe.stateBytes()});
}

class TimelineModes : public ::testing::TestWithParam<StepMode> {};

TEST_P(TimelineModes, EveryPastFrameIsRebuiltBitForBitSteppingBackOneByOne) {
    World world = gas(GetParam());
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 150, noEdits);
    ASSERT_EQ(timeline.firstFrame(), 0);
    ASSERT_EQ(timeline.lastFrame(), 149);
    EXPECT_GT(ref.back().counters().collisions, 300u);
    EXPECT_LT(timeline.keyframeCount(), 15u);
    std::size_t longestReplay = 0;
    for (std::int64_t f = timeline.lastFrame(); f >= timeline.firstFrame(); --f) {
        ASSERT_TRUE(identical(timeline.seek(f), ref[static_cast<std::size_t>(f)]))
            << "frame " << f << " in " << toString(GetParam());
        longestReplay = std::max(longestReplay, timeline.lastSeekReplayed());
    }
    EXPECT_GE(longestReplay, 10u) << "frames were re-simulated, not only copied";
}

TEST_P(TimelineModes, ARebuiltFrameStepsOnLikeTheWorldDid) {
    World world = gas(GetParam());
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 120, noEdits);
    for (std::int64_t f : {117, 64, 3}) {
        World a = timeline.seek(f);
        World b = ref[static_cast<std::size_t>(f)];
        for (int k = 0; k < 40; ++k) {
            a.step(kDt);
            b.step(kDt);
        }
        EXPECT_TRUE(identical(a, b)) << "frame " << f << " in " << toString(GetParam());
    }
}

TEST_P(TimelineModes, EditsBetweenFramesAreRecorded) {
    World world = gas(GetParam());
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 120, userEdits);
    EXPECT_EQ(timeline.unreportedChanges(), 0u);
    for (std::int64_t f = timeline.lastFrame(); f >= 0; f -= 1) {
        ASSERT_TRUE(identical(timeline.seek(f), ref[static_cast<std::size_t>(f)]))
            << "frame " << f << " in " << toString(GetParam());
    }
    EXPECT_EQ(timeline.seek(19).size(), 150u);
    EXPECT_EQ(timeline.seek(20).size(), 151u);
    EXPECT_EQ(timeline.seek(45).size(), 150u);
    EXPECT_EQ(timeline.seek(89).def().restitution, 0.95);
    EXPECT_EQ(timeline.seek(90).def().restitution, 0.7);
}

TEST_P(TimelineModes, ADragThroughTheTimelinesSettersIsReplayedWithoutKeyframes) {
    World world = gas(GetParam());
    Timeline timeline = sparseTimeline(world);
    const ParticleId held = world.ids()[3];
    std::vector<World> ref;
    double accumulator = 0.0;
    for (int f = 0; f < 120; ++f) {
        if (f == 10) timeline.setKinematic(world, held, true);
        accumulator += 1.0 / 60.0;
        while (accumulator >= kDt) {
            if (f >= 10 && f < 90) {  // the hand moves the held particle before every step
                const double t = world.time();
                timeline.setPosition(world, held, Vec2(20.0 + 8.0 * std::sin(3.0 * t), 20.0));
                timeline.setVelocity(world, held, Vec2(24.0 * std::cos(3.0 * t), 0.0));
            }
            world.step(kDt);
            timeline.stepped(kDt);
            accumulator -= kDt;
        }
        if (f == 90) {  // let go with a fling
            timeline.setKinematic(world, held, false);
            timeline.setVelocity(world, held, Vec2(0.0, -30.0));
        }
        timeline.record(world);
        ref.push_back(world);
    }
    EXPECT_EQ(timeline.unreportedChanges(), 0u);
    EXPECT_LE(timeline.keyframeCount(), 10u) << "the drag needed no keyframes";
    EXPECT_TRUE(ref[50].isKinematic(held));
    for (std::int64_t f = timeline.lastFrame(); f >= 0; --f) {
        ASSERT_TRUE(identical(timeline.seek(f), ref[static_cast<std::size_t>(f)]))
            << "frame " << f << " in " << toString(GetParam());
    }
}

INSTANTIATE_TEST_SUITE_P(AllModes, TimelineModes,
                         ::testing::Values(StepMode::Discrete, StepMode::Substep, StepMode::Exact),
                         [](const auto& p) { return std::string(toString(p.param)); });

TEST(Timeline, ScrubbingJumpsAnywhereAndForwardFromTheLastSeekReplaysOnlyTheGap) {
    World world = gas(StepMode::Exact);
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 200, noEdits);
    ASSERT_GT(timeline.keyframeSpacing(), 0.1) << "the small budget spaces keyframes apart";
    std::mt19937 rng(3);
    std::uniform_int_distribution<std::int64_t> any(0, 199);
    for (int k = 0; k < 20; ++k) {
        const std::int64_t f = any(rng);
        ASSERT_TRUE(identical(timeline.seek(f), ref[static_cast<std::size_t>(f)])) << f;
    }
    timeline.seek(100);
    timeline.seek(101);
    EXPECT_LE(timeline.lastSeekReplayed(), 1u);
    EXPECT_TRUE(identical(timeline.seek(101), ref[101]));
    EXPECT_EQ(timeline.lastSeekReplayed(), 0u);
}

TEST(Timeline, ThePausedUsersEditsReplaceTheLatestFrame) {
    World world = gas(StepMode::Discrete);
    Timeline timeline = sparseTimeline(world);
    std::vector<World> ref = run(world, timeline, 30, noEdits);
    // Paused: no steps, two edits in two frames, then an idle frame.
    world.setVelocity(world.ids()[0], Vec2(1.0, 2.0));
    timeline.edited();
    EXPECT_EQ(timeline.record(world), 29);
    world.remove(world.ids()[1]);
    timeline.edited();
    EXPECT_EQ(timeline.record(world), 29);
    EXPECT_EQ(timeline.record(world), 29);
    EXPECT_TRUE(identical(timeline.seek(29), world));
    EXPECT_TRUE(identical(timeline.seek(28), ref[28]));
    // Playing on from the edited state.
    const std::vector<World> more = run(world, timeline, 10, noEdits);
    EXPECT_EQ(timeline.lastFrame(), 39);
    EXPECT_TRUE(identical(timeline.seek(35), more[5]));
}

TEST(Timeline, ActingFromThePastDiscardsTheOldFuture) {
    World world = gas(StepMode::Exact);
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 80, noEdits);
    World resumed = timeline.seek(50);
    timeline.discardAfter(50);
    EXPECT_EQ(timeline.lastFrame(), 50);
    resumed.setVelocity(resumed.ids()[0], Vec2(-7.0, 0.0));
    timeline.edited();
    timeline.record(resumed);  // the paused edit replaces frame 50
    EXPECT_EQ(timeline.lastFrame(), 50);
    const std::vector<World> branch = run(resumed, timeline, 20, noEdits);
    EXPECT_EQ(timeline.lastFrame(), 70);
    EXPECT_EQ(timeline.unreportedChanges(), 0u);
    EXPECT_TRUE(identical(timeline.seek(70), branch.back()));
    EXPECT_TRUE(identical(timeline.seek(49), ref[49]));
    EXPECT_FALSE(identical(timeline.seek(60), ref[60]));  // the new future, not the old one
}

TEST(Timeline, AResetStartsANewHistory) {
    const World loaded = gas(StepMode::Exact);
    World world = loaded;
    Timeline timeline = sparseTimeline(world);
    run(world, timeline, 30, noEdits);
    world = loaded;  // R: the scene as loaded, at time 0
    timeline.edited();
    EXPECT_EQ(timeline.record(world), 30);
    EXPECT_EQ(timeline.firstFrame(), 30);
    EXPECT_EQ(timeline.coveredSeconds(), 0.0);
    const std::vector<World> after = run(world, timeline, 10, noEdits);
    EXPECT_EQ(timeline.lastFrame(), 40);
    EXPECT_TRUE(identical(timeline.seek(35), after[4]));
    EXPECT_THROW(timeline.seek(29), std::out_of_range);
    EXPECT_EQ(timeline.frameAt(0.0), 30);
}

TEST(Timeline, ADragWhilePausedChangesTheLatestFrame) {
    World world = gas(StepMode::Exact);
    Timeline timeline = sparseTimeline(world);
    const std::vector<World> ref = run(world, timeline, 20, noEdits);
    const ParticleId held = world.ids()[0];
    timeline.setKinematic(world, held, true);
    for (int k = 0; k < 5; ++k) {  // paused: no steps, the particle follows the hand
        timeline.setPosition(world, held, Vec2(5.0 + k, 5.0));
        EXPECT_EQ(timeline.record(world), 19);
    }
    EXPECT_TRUE(identical(timeline.seek(19), world));
    EXPECT_TRUE(identical(timeline.seek(18), ref[18]));
    EXPECT_THROW(timeline.setPosition(world, held, Vec2(kNaN, 0.0)), std::exception);
    EXPECT_EQ(timeline.record(world), 19);
    EXPECT_TRUE(identical(timeline.seek(19), world)) << "a refused edit is not logged";
}

TEST(Timeline, AChangeNobodyReportedIsStillRecordedRight) {
    World world = gas(StepMode::Discrete);
    Timeline timeline = sparseTimeline(world);
    std::vector<World> ref = run(world, timeline, 10, noEdits);
    world.step(kDt);  // not reported
    timeline.record(world);
    ref.push_back(world);
    world.add({.position = {5.0, 5.0}});  // not reported either
    world.step(kDt);
    timeline.stepped(kDt);
    timeline.record(world);
    ref.push_back(world);
    EXPECT_EQ(timeline.unreportedChanges(), 2u);
    for (std::int64_t f = 0; f <= timeline.lastFrame(); ++f) {
        EXPECT_TRUE(identical(timeline.seek(f), ref[static_cast<std::size_t>(f)])) << f;
    }
}

TEST(Timeline, KeepsTheHorizonWithinTheBudget) {
    // 10^3 particles: a keyframe is about 70 kB; 3 MB then holds ~40, spaced ~0.27 s apart.
    World world = gas(StepMode::Discrete, 1000);
    world.setBox(120.0, 120.0);
    const TimelineSettings s{.horizonSeconds = 10.0, .budgetBytes = 3u * 1000 * 1000};
    Timeline timeline(s);
    std::size_t peak = 0;
    double accumulator = 0.0;
    for (int f = 0; f < 60 * 25; ++f) {  // 25 s
        frame(world, timeline, accumulator);
        peak = std::max(peak, timeline.memoryBytes());
    }
    EXPECT_LE(peak, s.budgetBytes);
    EXPECT_GE(timeline.coveredSeconds(), s.horizonSeconds);
    EXPECT_LT(timeline.coveredSeconds(), s.horizonSeconds + timeline.keyframeSpacing() + 0.1);
    EXPECT_GT(timeline.keyframeCount(), 10u);
    EXPECT_GT(timeline.firstFrame(), 0);
    // And the oldest frame held is still exact: it is the world of that time.
    const World& oldest = timeline.seek(timeline.firstFrame());
    EXPECT_NEAR(oldest.time(), world.time() - timeline.coveredSeconds(), 1e-9);
}

TEST(Timeline, KeyframesAreATenthOfASecondApartWhenTheBudgetAllowsMore) {
    World world = gas(StepMode::Discrete);
    Timeline timeline;                   // 200 MB: room for a keyframe every frame
    run(world, timeline, 120, noEdits);  // 2 s
    EXPECT_EQ(timeline.keyframeSpacing(), 0.1);
    EXPECT_GE(timeline.keyframeCount(), 15u);
    EXPECT_LE(timeline.keyframeCount(), 21u);
    std::size_t longest = 0;
    for (std::int64_t f = timeline.lastFrame(); f >= 0; --f) {
        timeline.seek(f);
        longest = std::max(longest, timeline.lastSeekReplayed());
    }
    EXPECT_LE(longest, 6u);
}

TEST(Timeline, EditsEveryFrameShortenTheHistoryNotTheBudget) {
    World world = gas(StepMode::Discrete, 1000);
    world.setBox(120.0, 120.0);
    const TimelineSettings s{.horizonSeconds = 10.0, .budgetBytes = 3u * 1000 * 1000};
    Timeline timeline(s);
    const ParticleId held = world.ids()[0];
    world.setKinematic(held, true);
    for (int f = 0; f < 600; ++f) {  // a 10 s drag: every frame an edit
        world.setPosition(held, Vec2(20.0 + 0.1 * (f % 100), 20.0));
        timeline.edited();
        world.step(1.0 / 60.0);
        timeline.stepped(1.0 / 60.0);
        timeline.record(world);
        ASSERT_LE(timeline.memoryBytes(), s.budgetBytes) << "frame " << f;
    }
    EXPECT_LT(timeline.coveredSeconds(), s.horizonSeconds);
    EXPECT_GT(timeline.coveredSeconds(), 0.3);
}

TEST(Timeline, ATenSecondDragThroughTheSettersKeepsTheHorizon) {
    World world = gas(StepMode::Discrete, 1000);
    world.setBox(120.0, 120.0);
    const TimelineSettings s{.horizonSeconds = 10.0, .budgetBytes = 3u * 1000 * 1000};
    Timeline timeline(s);
    const ParticleId held = world.ids()[0];
    timeline.setKinematic(world, held, true);
    for (int f = 0; f < 720; ++f) {  // 12 s, the particle held and moved every step
        timeline.setPosition(world, held, Vec2(20.0 + 0.1 * (f % 100), 20.0));
        world.step(1.0 / 60.0);
        timeline.stepped(1.0 / 60.0);
        timeline.record(world);
        ASSERT_LE(timeline.memoryBytes(), s.budgetBytes) << "frame " << f;
    }
    EXPECT_GE(timeline.coveredSeconds(), s.horizonSeconds);
}

TEST(Timeline, RefusesWhatItDoesNotHold) {
    Timeline timeline;
    EXPECT_TRUE(timeline.empty());
    EXPECT_THROW(timeline.seek(0), std::out_of_range);
    EXPECT_THROW((void)timeline.frameAt(1.0), std::out_of_range);
    World world = gas(StepMode::Discrete, 10);
    run(world, timeline, 5, noEdits);
    EXPECT_THROW(timeline.seek(5), std::out_of_range);
    EXPECT_THROW(timeline.seek(-1), std::out_of_range);
    EXPECT_THROW(timeline.discardAfter(9), std::out_of_range);
    EXPECT_THROW(Timeline({.horizonSeconds = 0.0}), std::invalid_argument);
    EXPECT_THROW(Timeline({.minSpacingSeconds = -1.0}), std::invalid_argument);
    EXPECT_THROW(Timeline({.budgetBytes = 0}), std::invalid_argument);
    try {
        timeline.seek(7);
    } catch (const std::out_of_range& e) {
        EXPECT_STREQ(e.what(), "Timeline: frame 7 is not held (held: 0 to 4)");
    }
}

TEST(Timeline, FrameAtFindsTheFrameShownAtATime) {
    World world = gas(StepMode::Discrete, 10);
    Timeline timeline;
    run(world, timeline, 60, noEdits);
    EXPECT_EQ(timeline.frameAt(-5.0), 0);
    EXPECT_EQ(timeline.frameAt(1e9), 59);
    const double t = timeline.timeOf(30);
    EXPECT_EQ(timeline.frameAt(t), 30);
    EXPECT_EQ(timeline.frameAt(std::nextafter(t, 0.0)), 29);
}

}  // namespace
}  // namespace psb::app
