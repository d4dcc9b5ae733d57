// The exact mode with fixed obstacles: rebounds off pegs and segments at the instant of
// contact, without and with gravity, rest on them, and a Galton board whose bin counts follow
// the binomial distribution.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/chi_square.hpp>
#include <particle_sandbox/world.hpp>

#include "exact_stepper.hpp"
#include "obstacle_geometry.hpp"

namespace psb {
namespace {

double coreDistance(const Obstacle& o, const Vec2& p) {
    double qx, qy;
    nearestCorePoint(o, p.x(), p.y(), qx, qy);
    return std::hypot(p.x() - qx, p.y() - qy);
}

/// The deepest any particle is inside any obstacle (metres, <= 0 when none is).
double deepestObstacleOverlap(const World& w) {
    double deepest = -INFINITY;
    for (const ParticleId id : w.ids()) {
        const Particle p = w.get(id);
        for (const Obstacle& o : w.obstacles())
            deepest = std::max(deepest, o.radius + p.radius - coreDistance(o, p.position));
    }
    return deepest;
}

SolverSettings exactMode() {
    return {.mode = StepMode::Exact};
}

TEST(ExactObstacles, TheCollisionLogNamesTheObstacleHit) {
    // A ball dropped from rest onto a segment under it, and from there (e = 1) back up: the
    // log names the segment (obstacle 1, after a peg off to the side) at each impact, the
    // first at sqrt(2 h / g).
    WorldDef def{.width = 4.0, .height = 4.0, .gravity = {0.0, 9.81}, .restitution = 1.0};
    def.obstacles = {Obstacle::peg({0.5, 3.0}, 0.1),
                     Obstacle::segment({1.0, 3.0}, {3.0, 3.0}, 0.05)};
    const double r = 0.1, h = 0.5;
    ParticleArrays p;
    p.x = {2.0};
    p.y = {3.0 - 0.025 - r - h};  // thickness 0.05: 0.025 either side of the line
    p.vx = {0.0};
    p.vy = {0.0};
    p.radius = {r};
    p.mass = {1.0};
    p.invMass = {1.0};
    p.id = {ParticleId{0, 1}};
    p.color = {Color{}};
    exact::ExactStepper stepper;
    std::vector<exact::CollisionRecord> log;
    stepper.setLog(&log);
    StepProfile profile;
    StepCounters counters;
    for (int k = 0; k < 60; ++k)
        stepper.step(p, def, 1.0 / 60.0, profile, counters);
    ASSERT_GE(log.size(), 2u);
    for (const exact::CollisionRecord& c : log)
        EXPECT_EQ(c.j, exact::CollisionRecord::kObstacle + 1);
    EXPECT_NEAR(log[0].time, std::sqrt(2.0 * h / 9.81), 1e-9);
}

TEST(ExactObstacles, BallBouncesOffAPegAtTheInstantOfContact) {
    // r = 0.5 at x = 2 moving at 1 m/s towards a peg R = 1 at x = 5: contact at x = 3.5 after
    // 1.5 s, elastic: back at 1 m/s, at x = 2 again after 3 s.
    World w(WorldDef{.width = 10.0, .height = 10.0}, exactMode());
    w.addObstacle(Obstacle::peg({5.0, 5.0}, 1.0));
    const ParticleId id = w.add({.position = {2.0, 5.0}, .velocity = {1.0, 0.0}, .radius = 0.5});
    w.step(1.0);
    EXPECT_NEAR(w.get(id).position.x(), 3.0, 1e-12);
    w.step(2.0);
    EXPECT_NEAR(w.get(id).position.x(), 2.0, 1e-12);
    EXPECT_NEAR(w.get(id).velocity.x(), -1.0, 1e-12);
    EXPECT_EQ(w.counters().obstacleCollisions, 1u);
}

TEST(ExactObstacles, GlancingHitOffASegmentSideAndCap) {
    // A wall from (2, 6) to (8, 6), thickness 0.2; a ball r = 0.5 falling onto its side at 45°
    // leaves at 45° the other way (e = 1, no friction).
    World w(WorldDef{.width = 10.0, .height = 10.0}, exactMode());
    w.addObstacle(Obstacle::segment({2.0, 6.0}, {8.0, 6.0}, 0.2));
    const ParticleId id = w.add({.position = {4.0, 3.0}, .velocity = {1.0, 1.0}, .radius = 0.5});
    w.step(3.0);  // contact at y = 5.4 after 2.4 s; then 0.6 s up again
    EXPECT_NEAR(w.get(id).position.x(), 7.0, 1e-12);
    EXPECT_NEAR(w.get(id).position.y(), 4.8, 1e-12);
    EXPECT_NEAR(w.get(id).velocity.y(), -1.0, 1e-12);
    // Head-on into the end cap along the segment's line: straight back.
    World cap(WorldDef{.width = 10.0, .height = 10.0}, exactMode());
    cap.addObstacle(Obstacle::segment({2.0, 6.0}, {8.0, 6.0}, 0.2));
    const ParticleId c = cap.add({.position = {9.5, 6.0}, .velocity = {-1.0, 0.0}, .radius = 0.5});
    cap.step(1.0);  // contact at x = 8.6 after 0.9 s
    EXPECT_NEAR(cap.get(c).velocity.x(), 1.0, 1e-12);
    EXPECT_NEAR(cap.get(c).position.x(), 8.7, 1e-12);
}

TEST(ExactObstacles, WithoutWallsObstaclesAreFoundWhereverTheGridFolds) {
    // Walls off: the cell grid folds onto itself, so a cell's obstacles are looked up for the
    // place the particle is. A particle far outside the box flies past its images; one aimed at
    // the peg bounces off it.
    World w(WorldDef{.width = 10.0, .height = 10.0, .walls = false}, exactMode());
    w.addObstacle(Obstacle::peg({5.0, 5.0}, 1.0));
    w.addObstacle(Obstacle::segment({1.0, 9.0}, {9.0, 9.0}, 0.2));
    const ParticleId hit = w.add({.position = {2.0, 5.0}, .velocity = {1.0, 0.0}, .radius = 0.5});
    const ParticleId far = w.add({.position = {-95.0, 5.0}, .velocity = {0.0, 1.0}, .radius = 0.5});
    const ParticleId down =
        w.add({.position = {5.0, 12.0}, .velocity = {0.0, -1.0}, .radius = 0.5});
    w.step(3.0);
    EXPECT_NEAR(w.get(hit).position.x(), 2.0, 1e-12);   // back after 1.5 s out and 1.5 s in
    EXPECT_NEAR(w.get(far).position.y(), 8.0, 1e-12);   // untouched by the folded images
    EXPECT_NEAR(w.get(down).velocity.y(), 1.0, 1e-12);  // off the segment's underside at 2.4 s
    EXPECT_EQ(w.counters().obstacleCollisions, 2u);
}

/// A dilute gas (e = 1, no gravity) among pegs and slanted walls.
World gasAmongObstacles(unsigned seed, int count) {
    World w(WorldDef{.width = 40.0, .height = 40.0}, exactMode());
    for (int k = 0; k < 6; ++k) {
        w.addObstacle(Obstacle::peg({6.0 + 5.5 * k, 12.0}, 0.8));
        w.addObstacle(Obstacle::segment({3.0 + 6.0 * k, 20.0}, {6.0 + 6.0 * k, 26.0}, 0.3));
    }
    w.addObstacle(Obstacle::segment({2.0, 34.0}, {38.0, 30.0}, 0.5));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(1.0, 39.0), vel(-3.0, 3.0);
    while (static_cast<int>(w.size()) < count) {
        const Vec2 p(pos(rng), pos(rng));
        bool clear = true;
        for (const Obstacle& o : w.obstacles())
            clear = clear && coreDistance(o, p) > o.radius + 0.6;
        for (const ParticleId id : w.ids())
            clear = clear && (w.get(id).position - p).norm() > 1.2;
        if (clear) w.add({.position = p, .velocity = {vel(rng), vel(rng)}, .radius = 0.5});
    }
    return w;
}

TEST(ExactObstacles, ElasticGasAmongObstaclesKeepsEnergyAndNeverEntersOne) {
    World w = gasAmongObstacles(7, 150);
    const auto energy = [&] {
        double e = 0.0;
        for (const ParticleId id : w.ids())
            e += 0.5 * w.get(id).mass * w.get(id).velocity.squaredNorm();
        return e;
    };
    const double e0 = energy();
    double deepest = -INFINITY;
    for (int k = 0; k < 400; ++k) {
        w.step(1.0 / 60.0);
        deepest = std::max(deepest, deepestObstacleOverlap(w));
    }
    EXPECT_GT(w.counters().obstacleCollisions, 100u);
    EXPECT_LT(deepest, 1e-9);
    EXPECT_NEAR(energy(), e0, 1e-10 * e0);
}

TEST(ExactObstacles, BallDroppedOntoASegmentBouncesAsOnTheFloorThenRests) {
    // A floor segment at y = 8 (y down) under a ball dropped from y = 3: the same bounces as on
    // the box floor at the same height, then it rests (no more events).
    const double g = 9.81, r = 0.25;
    World seg(WorldDef{.width = 10.0, .height = 10.0, .gravity = {0.0, g}, .restitution = 0.8},
              exactMode());
    seg.addObstacle(Obstacle::segment({1.0, 8.0 + 0.05}, {9.0, 8.0 + 0.05}, 0.1));
    World floor(WorldDef{.width = 10.0, .height = 8.0, .gravity = {0.0, g}, .restitution = 0.8},
                exactMode());
    const ParticleId a = seg.add({.position = {5.0, 3.0}, .radius = r});
    const ParticleId b = floor.add({.position = {5.0, 3.0}, .radius = r});
    for (int k = 0; k < 120; ++k) {  // 2 s: the first bounces, both above the rest speed
        seg.step(1.0 / 60.0);
        floor.step(1.0 / 60.0);
        EXPECT_NEAR(seg.get(a).position.y(), floor.get(b).position.y(), 1e-9) << k;
    }
    for (int k = 0; k < 600; ++k)
        seg.step(1.0 / 60.0);
    EXPECT_NEAR(seg.get(a).position.y(), 8.0 - r, 1e-3);
    EXPECT_LT(seg.get(a).velocity.norm(), 1e-12);
    const std::uint64_t events = seg.counters().events;
    seg.step(1.0);
    EXPECT_EQ(seg.counters().events, events) << "a ball at rest on a segment makes no events";
}

TEST(ExactObstacles, FrictionlessRampIsSlidDownAndAFrictionalOneHolds) {
    // A 30° ramp: without friction a ball placed on it slides down (it must not rest there);
    // with mu = 1 (friction angle 45°) it stays.
    const double g = 9.81, r = 0.2, angle = 30.0 * 3.14159265358979 / 180.0;
    const Vec2 from(1.0, 5.0),
        to(from.x() + 6.0 * std::cos(angle), from.y() + 6.0 * std::sin(angle));
    const Vec2 n(std::sin(angle), -std::cos(angle));  // the ramp's upper normal (y down)
    const Vec2 start = from + 0.3 * (to - from) + (r + 0.05) * n;
    for (const double mu : {0.0, 1.0}) {
        World w(WorldDef{.width = 10.0,
                         .height = 10.0,
                         .gravity = {0.0, g},
                         .restitution = 0.3,
                         .friction = mu},
                exactMode());
        w.addObstacle(Obstacle::segment(from, to, 0.1));
        const ParticleId id = w.add({.position = start, .radius = r});
        for (int k = 0; k < 30; ++k)
            w.step(1.0 / 60.0);
        const Vec2 moved = w.get(id).position - start;
        if (mu == 0.0) {
            // Down the slope by ½·g·sin30°·t² = 0.613 m in 0.5 s, to within the hops.
            EXPECT_NEAR(moved.dot((to - from).normalized()), 0.5 * g * 0.5 * 0.25, 0.03);
        } else {
            EXPECT_LT(moved.norm(), 0.01);
        }
        EXPECT_LT(deepestObstacleOverlap(w), 1e-9);
    }
}

TEST(ExactObstacles, BallRestingOnAPegWakesWhenHit) {
    const double g = 9.81, r = 0.2;
    World w(WorldDef{.width = 10.0,
                     .height = 10.0,
                     .gravity = {0.0, g},
                     .restitution = 0.5,
                     .friction = 0.5},
            exactMode());
    w.addObstacle(Obstacle::peg({5.0, 6.0}, 0.3));
    const ParticleId top = w.add({.position = {5.0, 5.0}, .radius = r});
    for (int k = 0; k < 120; ++k)
        w.step(1.0 / 60.0);
    EXPECT_NEAR(w.get(top).position.y(), 6.0 - 0.5, 1e-3);
    const std::uint64_t events = w.counters().events;
    w.step(0.5);
    EXPECT_EQ(w.counters().events, events) << "resting on the peg: asleep";
    // A ball thrown at it from the side knocks it off.
    w.add({.position = {2.0, 5.5}, .velocity = {12.0, -1.2}, .radius = r});
    for (int k = 0; k < 120; ++k)
        w.step(1.0 / 60.0);
    EXPECT_GT(w.get(top).position.y(), 6.0);  // fell off, below the peg's top
    EXPECT_LT(deepestObstacleOverlap(w), 1e-9);
}

/// What dropBalls saw.
struct GaltonDrop {
    std::vector<int> bins;
    int outside = 0, stuck = 0;
    double deepest = -INFINITY;  ///< deepest overlap with a peg or a bin wall, metres
    double fastest = 0.0;        ///< fastest ball, m/s
};

/// Eight staggered rows of pegs (spacing d), bins under the gaps of the last row; `balls`
/// balls dropped one every 0.1 s above the top peg with a small random offset, stepped by `dt`.
/// A ball's bin is decided when it falls below the last row into the bins; it is counted there
/// and taken out (the bins' piles are the discrete tests' business). A ball not there within
/// 20 s is stuck.
GaltonDrop dropBalls(const SolverSettings& solver, int kBalls, double dt) {
    constexpr int kRows = 8;
    const double d = 0.02, r = 0.0025;
    // Pegs nearly as wide as their spacing leave channels a ball's width and a half wide, so
    // that a ball cannot skate across a row and meets one peg per row. The distribution is
    // sensitive to that width (measured with seeds 1-3 and 2026: at 6.5 mm the tails are a
    // little heavy, chi2 4-12 at 6.55 mm, at 6.7 mm too light): a peg is a fair coin only
    // where the ball falls one row per peg.
    const double peg = 0.00655;
    const double h = d * std::sqrt(3.0) / 2.0;
    const double width = (kRows + 4) * d, cx = 0.5 * width, y0 = 0.05;
    const double yLast = y0 + (kRows - 1) * h, binTop = yLast + peg + 2.0 * r;
    World w(WorldDef{.width = width,
                     .height = binTop + 0.1,
                     .gravity = {0.0, 9.81},
                     .restitution = 0.3,
                     .friction = 0.0},
            solver);
    Obstacles obstacles;
    for (int k = 0; k < kRows; ++k) {
        for (int j = -kRows; j <= kRows; ++j) {
            const double x = cx + (j + 0.5 * (k % 2)) * d;
            if (x > peg && x < width - peg)
                obstacles.push_back(Obstacle::peg({x, y0 + k * h}, peg));
        }
    }
    // Bin walls under the pegs of the last row.
    for (int j = -kRows; j <= kRows; ++j) {
        const double x = cx + (j + 0.5 * ((kRows - 1) % 2)) * d;
        if (x > 0.001 && x < width - 0.001)
            obstacles.push_back(Obstacle::segment({x, binTop}, {x, binTop + 0.1}, 0.002));
    }
    w.setObstacles(obstacles);

    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> offset(-0.5 * peg, 0.5 * peg);
    GaltonDrop out;
    out.bins.assign(kRows + 1, 0);
    int dropped = 0;
    std::vector<std::pair<ParticleId, double>> flying;  // id, time dropped
    double t = 0.0;
    while (dropped < kBalls || !flying.empty()) {
        if (dropped < kBalls && std::fmod(t + 1e-9, 0.1) < dt) {  // one ball every 0.1 s
            flying.push_back(
                {w.add({.position = {cx + offset(rng), y0 - 0.02}, .mass = 0.002, .radius = r}),
                 t});
            ++dropped;
        }
        w.step(dt);
        t += dt;
        out.deepest = std::max(out.deepest, deepestObstacleOverlap(w));
        for (std::size_t k = 0; k < flying.size();) {
            const Particle p = w.get(flying[k].first);
            out.fastest = std::max(out.fastest, p.velocity.norm());
            const bool in = p.position.y() > binTop + 2.0 * r;
            const bool late = t - flying[k].second > 20.0;
            if (!in && !late) {
                ++k;
                continue;
            }
            if (in) {
                const int m =
                    static_cast<int>(std::floor((p.position.x() - cx) / d + 0.5 * kRows + 0.5));
                (m >= 0 && m <= kRows ? out.bins[m] : out.outside) += 1;
            } else {
                ++out.stuck;
            }
            w.remove(flying[k].first);
            flying.erase(flying.begin() + static_cast<std::ptrdiff_t>(k));
        }
    }
    return out;
}

TEST(ExactObstacles, GaltonBoardBinsFollowTheBinomialDistribution) {
    // The board of dropBalls, 1000 balls: the counts against Binomial(8, 1/2) by a χ² test at
    // 1 %, and no ball ever inside a peg or a bin wall.
    constexpr int kRows = 8, kBalls = 1000;
    const GaltonDrop drop = dropBalls(exactMode(), kBalls, 0.01);
    const std::vector<int>& bins = drop.bins;
    const int stuck = drop.stuck, outside = drop.outside;
    const double deepest = drop.deepest;
    EXPECT_EQ(stuck, 0);
    EXPECT_EQ(outside, 0);
    EXPECT_LT(deepest, 1e-9) << "a ball went into a peg or a bin wall";
    // χ² over the bins against Binomial(8, 1/2), thin tails merged (expected counts >= 5).
    const std::vector<double> expected = binomialProbabilities({.trials = kRows, .p = 0.5});
    std::vector<double> counts(expected.size());
    std::vector<std::size_t> observed(bins.begin(), bins.end());
    for (std::size_t k = 0; k < counts.size(); ++k)
        counts[k] = kBalls * expected[k];
    const ChiSquareTest test = chiSquareTest(observed, counts);
    std::string table;
    for (std::size_t k = 0; k < test.observed.size(); ++k) {
        table += std::to_string(static_cast<int>(test.observed[k])) + "/" +
                 std::to_string(static_cast<int>(std::lround(test.expected[k]))) + " ";
    }
    EXPECT_EQ(test.dof, 6);  // 7 classes: the outermost bin on each side merged into its neighbour
    EXPECT_TRUE(test.passes()) << "chi2 " << test.statistic << " above " << test.critical
                               << "; bins (observed/expected): " << table;
    std::printf("Galton board, exact mode: chi2 = %.2f (%d dof, 1 %% critical %.2f), bins %s\n",
                test.statistic, test.dof, test.critical, table.c_str());
}

TEST(DiscreteObstacles, NoBallHangsOnAGaltonBoardsPeg) {
    // The discrete mode on the same board: a ball pressed against a peg's side by the ball on
    // top of it once hung there, its speed growing without bound (a time-0 "first contact"
    // threw its whole move away every step). Every ball must reach the bins, none faster than
    // a fall from the top of the board gives.
    SolverSettings discrete;
    discrete.dt = 0.001;
    const GaltonDrop drop = dropBalls(discrete, 100, 0.001);
    EXPECT_EQ(drop.stuck, 0);
    EXPECT_LT(drop.fastest, 3.0);
    EXPECT_EQ(drop.outside, 0);
}

}  // namespace
}  // namespace psb
