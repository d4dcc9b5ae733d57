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

namespace psb::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRamp = R"({"version": 4,
  "world": {"width": 4, "height": 3, "walls": true, "gravity": [0, 9.81], "restitution": 0.4,
            "friction": 0.2},
  "solver": {"mode": "exact", "dt": 0.002},
  "obstacles": [{"type": "segment", "from": [0.0, 0.45], "to": [2.6, 1.3963], "thickness": 0.04}],
  "particles": [{"x": 0.3, "y": 0.3, "vx": 0, "vy": 0, "mass": 1, "radius": 0.1},
                {"x": 3.5, "y": 2.9, "vx": 0, "vy": 0, "mass": 1, "radius": 0.1}],
  "droppers": [{"x": 3.5, "y": 0.2, "balls": 3, "interval": 2.0, "radius": 0.05, "mass": 0.5}]})";

using Change = std::function<void(Session&, const fs::path& dir)>;

class SessionWorldChanges : public TempDirTest,
                            public ::testing::WithParamInterface<std::tuple<const char*, Change>> {
  protected:
    SessionWorldChanges() : TempDirTest("psb-session-world-changes") {}

    [[nodiscard]] Session session() const {
        SessionOptions o;
        o.saveTo = dir_ / "save.json";
        o.paused = false;
        return Session(makeWorld(parseScene(kRamp, "ramp.json")), "ramp", o);
    }

    /// `seconds` of real time at 60 frames a second; the pointer clock starts at `t0`.
    static void play(Session& s, double seconds, double t0) {
        const int frames = static_cast<int>(std::lround(seconds * 60.0));
        for (int k = 0; k < frames; ++k)
            s.update(1.0 / 60.0, t0 + k / 60.0, 1e9);
    }

    static void expectSound(const Session& s, const std::string& when) {
        const World& w = s.world();
        for (const ParticleId id : w.ids()) {
            const Particle p = w.get(id);
            ASSERT_TRUE(std::isfinite(p.position.x()) && std::isfinite(p.position.y()) &&
                        std::isfinite(p.velocity.x()) && std::isfinite(p.velocity.y()))
                << when;
            EXPECT_GE(p.position.x(), p.radius - 1e-9) << when;
            EXPECT_LE(p.position.x(), w.def().width - p.radius + 1e-9) << when;
            EXPECT_GE(p.position.y(), p.radius - 1e-9) << when;
            EXPECT_LE(p.position.y(), w.def().height - p.radius + 1e-9) << when;
        }
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
        {"Reset", [](Session& s, const fs::path&) { s.apply(cmd::Reset{}); }},
    };
}

std::string changeName(const ::testing::TestParamInfo<std::tuple<const char*, Change>>& p) {
    return std::get<0>(p.param);
}

INSTANTIATE_TEST_SUITE_P(Exact, SessionWorldChanges, ::testing::ValuesIn(changes()), changeName);

}  // namespace
}  // namespace psb::app
