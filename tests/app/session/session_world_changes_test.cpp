// Every kind of user change, sent as the app sends it, while a ball slides down a ramp, another
// sleeps on the floor and a dropper releases balls, under gravity in the exact mode. The exact
// mode once crashed at the first change made while a ball slid on a slanted wall (the Ramp
// preset, T twice, Space, M: a segmentation fault).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <particle_sandbox/scene.hpp>

#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "world_checks.hpp"

namespace psb::app {
namespace {

namespace fs = std::filesystem;

using Change = std::function<void(Session&, const fs::path& dir)>;

class SessionWorldChanges : public TempDirTest,
                            public ::testing::WithParamInterface<std::tuple<const char*, Change>> {
  protected:
    SessionWorldChanges() : TempDirTest("psb-session-world-changes") {}

    /// The ramp scene that crashed (tests/core/scene/scene_corpus/good), with a ball on the floor
    /// and its dropper slowed to one ball every 2 s (the first at once, the next after the
    /// change).
    [[nodiscard]] Session session() const {
        Scene scene = test::corpusScene("ramp_with_dropper.json");
        scene.particles.push_back({.position = {3.5, 2.9}, .mass = 1.0, .radius = 0.1});
        scene.droppers.at(0).balls = 3;
        scene.droppers.at(0).interval = 2.0;
        SessionOptions o;
        o.saveTo = dir_ / "save.json";
        o.paused = false;
        return Session(makeWorld(scene), SceneInfo{.name = "ramp", .dt = scene.dt}, o);
    }

    /// `seconds` of real time at 60 frames a second; the pointer clock starts at `t0`.
    static void play(Session& s, double seconds, double t0) {
        const int frames = static_cast<int>(std::lround(seconds * 60.0));
        for (int k = 0; k < frames; ++k)
            s.update(1.0 / 60.0, t0 + k / 60.0, 1e9);
    }

    static void expectSound(const Session& s, const std::string& when) {
        test::expectInsideTheBox(s.world(), when);
    }
};

/// The ramp ball's id (the first particle of the scene).
ParticleId slider(const Session& s) {
    return s.world().ids()[0];
}

TEST_P(SessionWorldChanges, WhileABallSlidesLeaveTheWorldSound) {
    Session s = session();
    play(s, 1.2, 0.0);  // the ramp ball slides, the floor ball sleeps, one ball dropped
    ASSERT_EQ(s.world().solver().mode, StepMode::Exact);
    ASSERT_EQ(s.world().size(), 3u);
    std::get<1>(GetParam())(s, dir_);
    play(s, 2.0, 10.0);
    expectSound(s, std::get<0>(GetParam()));
}

std::vector<std::tuple<const char*, Change>> changes() {
    const auto at = [](const Session& s, ParticleId id) { return s.world().get(id).position; };
    return {
        {"Spawn", [](Session& s, const fs::path&) { s.apply(cmd::SpawnRandom{}); }},
        {"LaunchInEmptySpace",
         [](Session& s, const fs::path&) {
             drag(s, {3.0, 1.0}, {2.5, 0.8}, 5.0);
         }},
        {"FlingTheSlider",
         [at](Session& s, const fs::path&) {
             const Vec2 p = at(s, slider(s));
             drag(s, p, p + Vec2{0.3, -0.4}, 5.0);
         }},
        {"HoldAndDeleteTheSlider",
         [at](Session& s, const fs::path&) {
             s.apply(cmd::PointerDown{s.camera().worldToScreen(at(s, slider(s))), 5.0});
             s.update(1.0 / 60.0, 5.01, 1e9);
             s.apply(cmd::DeleteHeld{});
             s.apply(cmd::PointerUp{s.camera().worldToScreen({3.0, 1.0}), 5.1});
         }},
        {"DeleteFromThePanel",
         [](Session& s, const fs::path&) { s.apply(cmd::DeleteParticle{s.world().ids()[1]}); }},
        {"EditMass",
         [](Session& s, const fs::path&) {
             s.apply(cmd::EditParticle{slider(s), ParticleField::Mass, "4"});
         }},
        {"EditRadius",
         [](Session& s, const fs::path&) {
             s.apply(cmd::EditParticle{slider(s), ParticleField::Radius, "0.07"});
         }},
        {"EditVelocity",
         [](Session& s, const fs::path&) {
             s.apply(cmd::EditParticle{slider(s), ParticleField::Vx, "1.5"});
             s.apply(cmd::EditParticle{slider(s), ParticleField::Vy, "-2"});
         }},
        {"PlaceAPeg",
         [](Session& s, const fs::path&) {
             s.apply(cmd::SetTool{cmd::Tool::Peg});
             const Vec2 p = s.camera().worldToScreen({3.0, 1.5});
             s.apply(cmd::PointerDown{p, 5.0});
             s.apply(cmd::PointerUp{p, 5.05});
         }},
        {"DrawAWallUnderTheSlider",
         [at](Session& s, const fs::path&) {
             s.apply(cmd::SetTool{cmd::Tool::Wall});
             const Vec2 p = at(s, slider(s));
             drag(s, p + Vec2{-0.5, 0.6}, p + Vec2{0.5, 0.8}, 5.0);
         }},
        {"RemoveTheRamp", [](Session& s, const fs::path&) { s.apply(cmd::RemoveObstacle{0}); }},
        {"UndoAndRedo",
         [](Session& s, const fs::path&) {
             s.apply(cmd::SpawnRandom{});
             s.apply(cmd::Undo{});
             s.apply(cmd::Redo{});
             s.apply(cmd::Undo{});
         }},
        {"PauseStepBackAndPlay",
         [](Session& s, const fs::path&) {
             s.apply(cmd::TogglePause{});
             for (int k = 0; k < 20; ++k)
                 s.apply(cmd::StepBack{});
             s.apply(cmd::StepForward{});
             s.apply(cmd::TogglePause{});
         }},
        {"SwitchModesAndBack",
         [](Session& s, const fs::path&) {
             s.apply(cmd::SetMode{StepMode::Discrete});
             s.update(1.0 / 60.0, 5.0, 1e9);
             s.apply(cmd::SetMode{StepMode::Substep, 4});
             s.update(1.0 / 60.0, 5.02, 1e9);
             s.apply(cmd::SetMode{StepMode::Exact});
         }},
        {"ChangeTheLaws",
         [](Session& s, const fs::path&) {
             s.apply(cmd::SetFriction{0.7});
             s.apply(cmd::SetRestitution{0.9});
             s.apply(cmd::SetGravity{true, 20.0});
             s.apply(cmd::SetWalls{true});
         }},
        {"SaveAndOpenWhatWasSaved",
         [](Session& s, const fs::path& dir) {
             s.apply(cmd::SaveAs{dir / "sliding.json", true});
             s.apply(cmd::OpenFile{dir / "sliding.json"});
             if (s.paused()) s.apply(cmd::TogglePause{});
         }},
        {"Restart", [](Session& s, const fs::path&) { s.apply(cmd::Restart{}); }},
        {"Revert", [](Session& s, const fs::path&) { s.apply(cmd::Revert{}); }},
    };
}

std::string changeName(const ::testing::TestParamInfo<std::tuple<const char*, Change>>& p) {
    return std::get<0>(p.param);
}

INSTANTIATE_TEST_SUITE_P(Exact, SessionWorldChanges, ::testing::ValuesIn(changes()), changeName);

}  // namespace
}  // namespace psb::app
