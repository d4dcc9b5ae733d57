// particle-sim's runs and reports, checked against values worked out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <particle_sandbox/scene.hpp>

#include "cli_app.hpp"
#include "report.hpp"
#include "runner.hpp"

namespace psb::cli {
namespace {

RunReport run(std::string_view json, double duration, RunOptions o = {}) {
    o.duration = duration;
    World w;
    return runScene(parseScene(json, "test"), o, w);
}

TEST(Runner, OneParticleBouncingBetweenTwoWallsIsCountedExactly) {
    // A 10 m box, r = 1, 2 kg at x = 5 moving +4 m/s, dt = 0.25 s: 1 m per step, all exact in
    // binary. Steps 1-4 reach x = 9 (touching, no bounce); step 5 crosses to 10 and is clamped
    // to 9 with v = -4 (impulse 2 kg · 8 m/s = 16); steps 6-13 reach x = 1; step 14 crosses to
    // 0 and bounces (another 16); steps 15-16 reach x = 3.
    const RunReport r = run(R"({"version": 1, "world": {"width": 10, "height": 10},
        "solver": {"dt": 0.25},
        "particles": [{"x": 5, "y": 5, "vx": 4, "mass": 2, "radius": 1}]})",
                            4.0);
    EXPECT_EQ(r.steps, 16u);
    EXPECT_EQ(r.simTime, 4.0);
    EXPECT_EQ(r.particles, 1u);
    EXPECT_EQ(r.wallCollisions, 2u);
    EXPECT_EQ(r.wallImpulse, 32.0);
    EXPECT_EQ(r.collisions, 0u);
    EXPECT_EQ(r.maxOverlap, 0.0);
    EXPECT_EQ(r.kineticEnergyInitial, 16.0);  // ½ · 2 · 4²
    EXPECT_EQ(r.kineticEnergyFinal, 16.0);
    EXPECT_EQ(r.momentumInitial, Vec2(8.0, 0.0));
    EXPECT_EQ(r.momentumFinal, Vec2(8.0, 0.0));
    EXPECT_EQ(r.escaped, 0u);
}

TEST(Runner, MaxOverlapReportsAPairPlacedOverlappingInEveryMode) {
    // Two discs placed 0.5 m deep, at rest: nothing collides, the overlap is in the state.
    for (const char* mode : {"discrete", "substep", "exact"}) {
        const RunReport r = run(std::string(R"({"version": 1, "allow_overlaps": true,
            "world": {"width": 20, "height": 10},
            "solver": {"dt": 0.5, "mode": ")") +
                                    mode + R"("},
            "particles": [{"x": 5, "y": 5, "mass": 1, "radius": 1},
                          {"x": 6.5, "y": 5, "mass": 1, "radius": 1}]})",
                                1.0);
        EXPECT_EQ(r.collisions, 0u) << mode;
        EXPECT_GE(r.maxOverlap, 0.5) << mode;
        EXPECT_LE(r.maxOverlap, 0.5 + 1e-12) << mode;
    }
}

TEST(Runner, HeadOnEqualMassesCollideOnceAtTheOverlapDetectionSaw) {
    // Centres 4 m apart closing at 2 m/s, r = 1, dt = 0.5: touching (not overlapping) after
    // step 2, overlapping by 1 m after step 3, when the velocities swap. Momentum is zero
    // throughout, kinetic energy 2 · ½ · 1 · 1² = 1 J before and after.
    const RunReport r = run(R"({"version": 1, "world": {"width": 20, "height": 10},
        "solver": {"dt": 0.5},
        "particles": [{"x": 3, "y": 5, "vx": 1, "mass": 1, "radius": 1},
                      {"x": 7, "y": 5, "vx": -1, "mass": 1, "radius": 1}]})",
                            2.0);
    EXPECT_EQ(r.steps, 4u);
    EXPECT_EQ(r.collisions, 1u);
    EXPECT_EQ(r.maxOverlap, 1.0);
    EXPECT_EQ(r.wallCollisions, 0u);
    EXPECT_EQ(r.kineticEnergyInitial, 1.0);
    EXPECT_EQ(r.kineticEnergyFinal, 1.0);
    EXPECT_EQ(r.momentumFinal, Vec2(0.0, 0.0));
}

TEST(Runner, ParticlesLeavingAWalllessBoxAreCountedAsEscaped) {
    const RunReport r = run(R"({"version": 1, "world": {"width": 10, "height": 10, "walls": false},
        "solver": {"dt": 0.5},
        "particles": [{"x": 5, "y": 5, "vx": 4, "mass": 1, "radius": 1},
                      {"x": 5, "y": 2, "mass": 1, "radius": 1}]})",
                            2.0);
    EXPECT_EQ(r.escaped, 1u);  // x = 13 after 2 s
    EXPECT_EQ(r.wallCollisions, 0u);
}

TEST(Runner, OptionsOverrideTheScenesSolverBlock) {
    RunOptions o;
    o.mode = StepMode::Substep;
    o.dt = 0.125;
    o.substeps = 3;
    o.broadphase = BroadPhaseKind::AllPairs;
    o.threads = 2;
    const RunReport r = run(R"({"version": 1, "solver": {"dt": 0.5}})", 1.0, o);
    EXPECT_EQ(r.solver.mode, StepMode::Substep);
    EXPECT_EQ(r.dt, 0.125);
    EXPECT_EQ(r.solver.substeps, 3);
    EXPECT_EQ(r.broadphaseUsed, BroadPhaseKind::AllPairs);
    EXPECT_EQ(r.threads, 2);
    EXPECT_EQ(r.steps, 8u);
}

TEST(Runner, ObstaclePresetsRunWithEveryBallInTheBoxAndOutOfEveryObstacle) {
    const std::string dir = std::string(PSB_ASSETS_DIR) + "/scenes/";
    for (const char* name :
         {"09-galton-board.json", "10-funnel.json", "11-hourglass.json", "12-ramp.json",
          "13-basketball-and-tennis-ball.json", "14-bowling.json"}) {
        SCOPED_TRACE(name);
        const Scene scene = loadScene(dir + name);
        RunOptions o;
        o.duration = 1.0;
        World w;
        const RunReport r = runScene(scene, o, w);
        EXPECT_EQ(r.escaped, 0u);
        EXPECT_EQ(r.obstacles, scene.world.obstacles.size());
        EXPECT_EQ(r.particles, scene.particles.size());
        if (r.obstacles > 0) {
            EXPECT_GT(r.obstacleCollisions, 0u);
        }
        // No ball's centre ends inside an obstacle's solid.
        const ParticleArrays& p = w.particles();
        for (const Obstacle& ob : w.obstacles()) {
            for (std::size_t i = 0; i < p.size(); ++i) {
                const Vec2 c(p.x[i], p.y[i]);
                const Vec2 ab = ob.b - ob.a;
                const double t =
                    ob.isPeg() ? 0.0 : std::clamp((c - ob.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
                ASSERT_GE((c - (ob.a + t * ab)).norm(), ob.radius) << "ball " << i;
            }
        }
    }
}

TEST(Runner, ExactModeOnAnObstacleSceneRuns) {
    // A ball thrown at a peg: one rebound off it, counted as an obstacle collision.
    RunOptions o;
    o.mode = StepMode::Exact;
    const RunReport r = run(R"({"version": 2, "world": {"width": 10, "height": 10},
        "obstacles": [{"type": "peg", "x": 5, "y": 5, "radius": 1}],
        "particles": [{"x": 2, "y": 5, "vx": 1, "mass": 1, "radius": 0.5}]})",
                            2.0, o);
    EXPECT_EQ(r.solver.mode, StepMode::Exact);
    EXPECT_EQ(r.obstacleCollisions, 1u);
}

TEST(Runner, ExactModeWithGravityRuns) {
    RunOptions o;
    o.mode = StepMode::Exact;
    const RunReport r = run(R"({"version": 1, "world": {"width": 10, "height": 10,
        "gravity": [0, 9.81]}, "particles": [{"x": 5, "y": 4, "mass": 1, "radius": 1}]})",
                            1.0, o);
    EXPECT_EQ(r.solver.mode, StepMode::Exact);
    EXPECT_TRUE(r.gravity);
    // Dropped 5 m (centre at 4, floor contact at 9), it hits the floor after 1.01 s.
    EXPECT_EQ(r.wallCollisions, 0u);
    EXPECT_NEAR(r.potentialEnergyInitial, 9.81 * 6.0, 1e-12);
    EXPECT_NEAR(r.kineticEnergyFinal + r.potentialEnergyFinal, 9.81 * 6.0, 1e-10);
}

TEST(Runner, MaxLagSetsTheLongestLagOfTheMsdAndVacf) {
    // A periodic gas of 400 discs at 0.3: by default the lags reach 20 free times (about 17 s
    // here); --max-lag 40 takes them to 40 s, in steps of the state interval.
    const std::string scene = R"({"version": 6, "world": {"width": 1, "height": 1,
        "periodic": true}, "solver": {"mode": "exact", "dt": 0.1},
        "generate": {"count": 400, "packing_fraction": 0.3, "radius": 1, "temperature": 1,
                     "seed": 3}})";
    RunOptions o;
    o.observables = true;
    const RunReport plain = run(scene, 60.0, o);
    ASSERT_TRUE(plain.observables.has_value());
    ASSERT_FALSE(plain.observables->lagTime.empty());
    EXPECT_LT(plain.observables->lagTime.back(), 30.0);
    o.maxLag = 40.0;
    const RunReport longer = run(scene, 60.0, o);
    ASSERT_TRUE(longer.observables.has_value());
    const std::vector<double>& lags = longer.observables->lagTime;
    ASSERT_GE(lags.size(), 2u);
    EXPECT_NEAR(lags.back(), 40.0, lags[1] - lags[0]);
    EXPECT_EQ(longer.observables->vacf.size(), lags.size());
}

TEST(Report, ListsPotentialAndMechanicalEnergyOnlyWithGravity) {
    const RunReport r = run(R"({"version": 1, "world": {"width": 10, "height": 10,
        "gravity": [0, 2]}, "solver": {"dt": 0.25, "mode": "exact"},
        "particles": [{"x": 5, "y": 5, "mass": 3, "radius": 1}]})",
                            1.0);
    const auto j = nlohmann::json::parse(reportJson(r));
    // Height above the floor: 10 − 5 = 5 m, so m g h = 3 · 2 · 5 at the start; after 1 s of
    // free fall it is 1 m lower, and the 6 J it lost are kinetic.
    EXPECT_DOUBLE_EQ(j.at("potential_energy").at("initial"), 30.0);
    EXPECT_NEAR(j.at("potential_energy").at("final").get<double>(), 24.0, 1e-12);
    EXPECT_NEAR(j.at("kinetic_energy").at("final").get<double>(), 6.0, 1e-12);
    EXPECT_NEAR(j.at("mechanical_energy").at("final").get<double>(), 30.0, 1e-12);
    const auto none = nlohmann::json::parse(reportJson(run(R"({"version": 1})", 0.1)));
    EXPECT_FALSE(none.contains("potential_energy"));
    EXPECT_FALSE(none.contains("mechanical_energy"));
}

TEST(Report, ObservablesGiveTheWallsCollisionRateAsTheWallRebounds) {
    // One disc between two walls 10 m apart, at 2 m/s along x: a rebound every 4.5 s (it
    // travels 9 m between the walls, its radius being 0.5 m). With --observables the report
    // says how many rebounds a second the whole box's walls took, as the window does.
    const std::string scene = R"({"version": 6, "world": {"width": 10, "height": 10,
        "walls": true}, "solver": {"mode": "exact", "dt": 0.5},
        "particles": [{"x": 5, "y": 5, "vx": 2, "vy": 0, "mass": 1, "radius": 0.5}]})";
    RunOptions o;
    o.observables = true;
    const RunReport r = run(scene, 90.0, o);
    const auto j = nlohmann::json::parse(reportJson(r));
    ASSERT_TRUE(j.at("observables").contains("wall_collision_rate"));
    const double rate = j.at("observables").at("wall_collision_rate").at("value");
    EXPECT_NEAR(rate, 1.0 / 4.5, 0.03);
    EXPECT_EQ(r.wallCollisions, 20u);
    const auto periodic = nlohmann::json::parse(reportJson(run(R"({"version": 6, "world":
        {"width": 10, "height": 10, "periodic": true}, "solver": {"mode": "exact", "dt": 0.5},
        "particles": [{"x": 5, "y": 5, "vx": 2, "vy": 0, "mass": 1, "radius": 0.5}]})",
                                                               90.0, o)));
    EXPECT_FALSE(periodic.at("observables").contains("wall_collision_rate"));
}

TEST(Report, HasEveryFieldWithItsValue) {
    RunOptions o;
    o.threads = 3;
    const RunReport r = run(R"({"version": 1, "world": {"width": 10, "height": 10},
        "solver": {"dt": 0.25},
        "particles": [{"x": 5, "y": 5, "vx": 4, "mass": 2, "radius": 1}]})",
                            4.0, o);
    const auto j = nlohmann::json::parse(reportJson(r));
    EXPECT_EQ(j.at("mode"), "discrete");
    EXPECT_EQ(j.at("dt"), 0.25);
    EXPECT_EQ(j.at("substeps"), 1);
    EXPECT_EQ(j.at("broadphase"), "all-pairs");  // what auto resolves to in this build
    EXPECT_EQ(j.at("threads"), 3);
    EXPECT_EQ(j.at("particles"), 1);
    EXPECT_EQ(j.at("steps"), 16);
    EXPECT_EQ(j.at("sim_time"), 4.0);
    EXPECT_GE(j.at("wall_seconds").get<double>(), 0.0);
    EXPECT_EQ(j.at("collisions"), 0);
    EXPECT_EQ(j.at("wall_collisions"), 2);
    EXPECT_EQ(j.at("kinetic_energy").at("initial"), 16.0);
    EXPECT_EQ(j.at("kinetic_energy").at("final"), 16.0);
    EXPECT_EQ(j.at("momentum").at("initial"), nlohmann::json::array({8.0, 0.0}));
    EXPECT_EQ(j.at("momentum").at("final"), nlohmann::json::array({8.0, 0.0}));
    EXPECT_EQ(j.at("wall_impulse"), 32.0);
    EXPECT_EQ(j.at("max_overlap"), 0.0);
    EXPECT_EQ(j.at("escaped"), 0);
    // A disc moving along y = 5 at 4 m/s: m (x vy − y vx) = 2 (0 − 5·4) = −40 about the origin;
    // it does not turn.
    EXPECT_EQ(j.at("angular_momentum").at("initial"), -40.0);
    EXPECT_EQ(j.at("rotational_energy").at("initial"), 0.0);
    EXPECT_EQ(j.at("rotational_energy").at("final"), 0.0);
}

TEST(Report, ADiscLaunchedSlidingOnTheFloorSpinsUpAndTheReportSaysHowMuch) {
    // v0 = 3 m/s, mu = 0.2, r = 0.2, k = 1/2: it rolls at 2 m/s, 10 rad/s from 0.51 s. Rotational
    // energy ½ (½ m r²) ω² = 1 J for m = 1; angular momentum about the origin, on the floor at
    // y = 2 − r: m (x vy − y vx) + I ω = −1.8 · 2 + 0.02 · 10 = −3.4 kg m²/s.
    const RunReport r = run(R"({"version": 5,
        "world": {"width": 20, "height": 2, "gravity": [0, 9.81], "restitution": 0, "friction": 0.2},
        "solver": {"dt": 0.001},
        "particles": [{"x": 1, "y": 1.8, "vx": 3, "mass": 1, "radius": 0.2}]})",
                            2.0, {});
    const auto j = nlohmann::json::parse(reportJson(r));
    EXPECT_TRUE(r.rotation);
    EXPECT_EQ(j.at("rotational_energy").at("initial"), 0.0);
    EXPECT_NEAR(j.at("rotational_energy").at("final").get<double>(), 1.0, 1e-9);
    EXPECT_NEAR(j.at("kinetic_energy").at("final").get<double>(), 2.0, 1e-9);
    EXPECT_NEAR(j.at("angular_momentum").at("initial").get<double>(), -1.8 * 3.0, 1e-12);
    EXPECT_NEAR(j.at("angular_momentum").at("final").get<double>(), -3.4, 1e-9);
    // Kinetic + rotational + potential: the friction's work is gone (4.5 J to 3 J).
    EXPECT_NEAR(j.at("mechanical_energy").at("final").get<double>() -
                    j.at("mechanical_energy").at("initial").get<double>(),
                -1.5, 1e-9);
}

/// 12 discs in the left bin, 8 in the right, 3 above the bins; Binomial(1, 1/2) expected.
constexpr const char* kTwoBins = R"({"version": 3, "world": {"width": 1, "height": 1},
    "bins": {"edges": [0, 0.5, 1], "top": 0.5, "expected": {"binomial": {"trials": 1, "p": 0.5}}},
    "generate": [{"count": 12, "radius": 0.01, "region": [0.05, 0.55, 0.45, 0.95]},
                 {"count": 8, "radius": 0.01, "region": [0.55, 0.55, 0.95, 0.95]},
                 {"count": 3, "radius": 0.01, "region": [0.05, 0.05, 0.95, 0.45]}]})";

TEST(Report, ListsTheBinCountsExpectedCountsAndChiSquareWhenTheSceneHasBins) {
    const auto j = nlohmann::json::parse(reportJson(run(kTwoBins, 0.0)));
    const auto& b = j.at("bins");
    EXPECT_EQ(b.at("counts"), nlohmann::json::array({12, 8}));
    EXPECT_EQ(b.at("counted"), 20);
    EXPECT_EQ(b.at("outside"), 0);
    EXPECT_EQ(b.at("above"), 3);
    EXPECT_EQ(b.at("expected"), nlohmann::json::array({10.0, 10.0}));
    const auto& chi = b.at("chi_square");
    EXPECT_DOUBLE_EQ(chi.at("statistic").get<double>(), 0.8);  // (2² + 2²) / 10
    EXPECT_EQ(chi.at("dof"), 1);
    EXPECT_EQ(chi.at("alpha"), 0.01);
    EXPECT_NEAR(chi.at("critical").get<double>(), 6.635, 5e-4);
    EXPECT_NEAR(chi.at("p_value").get<double>(), 0.3711, 1e-4);
    EXPECT_EQ(chi.at("passes"), true);
    EXPECT_EQ(chi.at("observed_merged"), nlohmann::json::array({12.0, 8.0}));
    const auto none = nlohmann::json::parse(reportJson(run(R"({"version": 1})", 0.1)));
    EXPECT_FALSE(none.contains("bins"));
}

TEST(Report, SaysHowManyBallsEachDropperReleasedAndHasLeft) {
    // Two droppers: one every 0.25 s (5 of 7 in 1 s: at 0, 0.25, 0.5, 0.75 and 1.0, the last at
    // the step starting at t = 1), and one that had already dropped 2 and has 1 left.
    constexpr const char* kDroppers = R"({"version": 4,
        "world": {"width": 1, "height": 1, "gravity": [0, 9.81]},
        "droppers": [{"x": 0.3, "y": 0.1, "balls": 7, "interval": 0.25, "radius": 0.01, "mass": 0.01},
                     {"x": 0.7, "y": 0.1, "balls": 1, "interval": 0.1, "radius": 0.01, "mass": 0.01,
                      "released": 2}]})";
    const auto j = nlohmann::json::parse(reportJson(run(kDroppers, 1.1)));
    const auto& d = j.at("droppers");
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].at("released"), 5);
    EXPECT_EQ(d[0].at("left"), 2);
    EXPECT_EQ(d[1].at("released"), 1);  // during this run
    EXPECT_EQ(d[1].at("left"), 0);
    const auto none = nlohmann::json::parse(reportJson(run(R"({"version": 1})", 0.1)));
    EXPECT_FALSE(none.contains("droppers"));
}

TEST(CliApp, SaveKeepsTheScenesBins) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("psb-runner-bins-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    { std::ofstream(dir / "in.json") << kTwoBins; }
    std::ostringstream out, err;
    EXPECT_EQ(runCli({"particle-sim", (dir / "in.json").string(), "--duration", "0.1", "--save",
                      (dir / "out.json").string()},
                     out, err, false),
              kExitOk)
        << err.str();
    const Scene saved = loadScene(dir / "out.json");
    EXPECT_EQ(saved.bins, parseScene(kTwoBins, "in").bins);
    std::filesystem::remove_all(dir);
}

TEST(CliApp, ExitCodesSeparateBadCommandLinesFromBadScenes) {
    std::ostringstream out, err;
    EXPECT_EQ(runCli({"particle-sim", "--help"}, out, err, false), kExitOk);
    EXPECT_NE(out.str().find("Usage:"), std::string::npos);
    EXPECT_EQ(runCli({"particle-sim", "x.json"}, out, err, false), kExitUsage);
    err.str("");
    EXPECT_EQ(runCli({"particle-sim", "no/such.json", "--duration", "1"}, out, err, false),
              kExitFailure);
    EXPECT_EQ(err.str(),
              "particle-sim: error: no/such.json: cannot open (No such file or directory)\n");
}

TEST(CliApp, NoProgressBarWhenStderrIsNotATerminal) {
    std::ostringstream out, err;
    const std::string scene = std::string(PSB_ASSETS_DIR) + "/scenes/01-original.json";
    EXPECT_EQ(runCli({"particle-sim", scene, "--duration", "1", "--progress"}, out, err, false),
              kExitOk);
    EXPECT_EQ(err.str(), "");
    EXPECT_TRUE(nlohmann::json::accept(out.str()));
    // On a terminal the bar is drawn (and ends its line).
    std::ostringstream out2, err2;
    EXPECT_EQ(runCli({"particle-sim", scene, "--duration", "1", "--progress"}, out2, err2, true),
              kExitOk);
    EXPECT_NE(err2.str().find("100%"), std::string::npos);
    EXPECT_EQ(err2.str().back(), '\n');
}

}  // namespace
}  // namespace psb::cli
