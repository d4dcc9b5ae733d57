// The run's series and the recording of trajectories and collisions (data_recorder.hpp),
// without a session.

#include <gtest/gtest.h>

#include "session/collision_feed.hpp"
#include "session/data_recorder.hpp"

namespace psb::app {
namespace {

ObservablesSample at(double time, std::uint64_t collisions) {
    ObservablesSample s;
    s.time = time;
    s.collisions = collisions;
    return s;
}

TEST(DataRecorder, TheRunSeriesKeepsItsStartAndThinsWhenFull) {
    DataRecorder d;
    for (std::size_t k = 0; k <= DataRecorder::kMaxRunSamples + 10; ++k) {
        ObservablesSample s = at(static_cast<double>(k), 3 * k);
        s.collisionRate = 3.0;  // over the monitor's window (monitor.hpp)
        d.sample(s);
    }
    const std::vector<ObservablesSample>& run = d.run();
    ASSERT_LT(run.size(), DataRecorder::kMaxRunSamples);
    EXPECT_GT(run.size(), DataRecorder::kMaxRunSamples / 2 - 10);
    EXPECT_EQ(run.front().time, 0.0) << "t = 0 is kept";
    EXPECT_EQ(run[1].time, 2.0);
    for (std::size_t k = 1; k < run.size(); ++k) {
        EXPECT_LT(run[k - 1].time, run[k].time);
        EXPECT_EQ(run[k].collisionRate, 3.0) << "a kept sample's rate over its window stands";
    }
}

TEST(DataRecorder, ASampleAtTheSameTimeIsSkippedAndAnEarlierOneCutsTheFuture) {
    DataRecorder d;
    d.sample(at(0.0, 0));
    d.sample(at(1.0, 10));
    d.sample(at(1.0, 10));
    d.sample(at(2.0, 30));
    ASSERT_EQ(d.run().size(), 3u);
    EXPECT_EQ(d.run()[2].time, 2.0);
    d.sample(at(1.5, 40));  // an undo to 1.5 s
    ASSERT_EQ(d.run().size(), 3u);
    EXPECT_EQ(d.run()[2].time, 1.5);
}

TEST(DataRecorder, RecordsTheChosenParticlesCollisionsFromWhatTheWorldHeard) {
    WorldDef def;
    def.width = def.height = 10.0;
    World w(def);
    const ParticleId a = w.add({.position = Vec2(5.0, 5.0), .velocity = Vec2(3.0, 0.0)});
    w.add({.position = Vec2(2.0, 2.0), .velocity = Vec2(-3.0, 0.0)});
    DataRecorder d;
    d.start(w, {a}, 2);
    ASSERT_TRUE(d.collisionsWanted());
    EXPECT_EQ(d.collisionsWanted()->chosen(), std::vector<ParticleId>{a});
    // The world records every collision (another instrument wants them all): the recorder
    // keeps only its particle's.
    listen(w, mergeWanted(d.collisionsWanted(), CollisionLog()));
    for (int k = 0; k < 200; ++k) {
        d.beforeStep(w);
        w.step(0.01);
        d.afterStep(w, heard(w));
    }
    EXPECT_EQ(d.trajectory().samples().size(), 101u) << "t = 0 and every second step";
    ASSERT_EQ(d.collisions().size(), 1u) << "it reaches the right wall at 4/3 s";
    EXPECT_EQ(d.collisions()[0].wall(), WallSide::Right);
    d.stop();
    EXPECT_FALSE(d.collisionsWanted());
    d.beforeStep(w);
    w.step(0.01);
    d.afterStep(w, {});
    EXPECT_EQ(d.trajectory().samples().size(), 101u);
}

TEST(DataRecorder, AStoppedRecordingStaysWholeWhenTheRunGoesBack) {
    // The lesson: record, run, stop, step back to the impact and run on. The run's series
    // follows the world back; the stopped recording keeps every sample it took.
    WorldDef def;
    def.width = def.height = 10.0;
    World w(def);
    w.add({.position = Vec2(5.0, 5.0), .velocity = Vec2(1.0, 0.0)});
    DataRecorder d;
    d.start(w, w.ids(), 1);
    for (int k = 0; k < 100; ++k) {
        d.beforeStep(w);
        w.step(0.01);
        d.afterStep(w, {});
        d.sample(at(w.time(), 0));
    }
    d.stop();
    ASSERT_EQ(d.trajectory().samples().size(), 101u);
    ASSERT_EQ(d.run().size(), 100u);
    d.sample(at(0.5, 0));  // a past frame carried on from
    EXPECT_EQ(d.trajectory().samples().size(), 101u) << "the stopped recording is whole";
    EXPECT_NEAR(d.trajectory().samples().back().time, 1.0, 1e-9);
    EXPECT_NEAR(d.run().back().time, 0.5, 1e-9) << "the plots' series follows the world";
    d.start(w, w.ids(), 1);  // a new recording starts anew
    EXPECT_EQ(d.trajectory().samples().size(), 1u);
}

}  // namespace
}  // namespace psb::app
