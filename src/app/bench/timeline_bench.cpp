// Step back in time (src/app/session/timeline.hpp) on 10^4 particles: the memory the timeline
// holds for the last 10 s, and what one step back costs, in each step mode.
//
// The scene is the gas of bench/gas_scene.hpp (10^4 discs of 1 m at packing fraction 0.1,
// dt = 0.01 s), with gravity 9.81 m/s² in the discrete and substep (k = 4) modes and none in
// the exact mode.
// It is run as the app runs it: 60 frames per second of wall time, each stepping the world by
// dt as often as 1/60 s of simulated time allows, recorded into a Timeline with the default
// settings (horizon 10 s, budget 200 MB), for 12 s. Then, as a paused user would, every frame
// is stepped back to, one by one from the newest to the oldest; each iteration is one such pass.
//
//   build/release/src/app/bench/timeline_bench
//
// BM_StepBack measures the Timeline alone; BM_SessionStepBack (below) the same through the
// Session and its commands, with the undo history, for 10^2, 10^3 and 10^4 particles.
//
// Counters: memory_MB (Timeline::memoryBytes after the run), covered_s (seconds of history
// held), keyframes, spacing_s (between scheduled keyframes), step_back_ms (CPU time of one
// step back, mean over the pass), worst_ms (CPU time of the slowest step back of the pass),
// step_back_wall_ms (mean wall time: what the user waits on this machine), replayed_max (most
// frames one step back re-simulated), record_us (CPU time Timeline::record added to a frame, mean),
// frame_ms (CPU time of a frame's steps, mean, for scale; one thread), rss_growth_MB (how much the
// process's resident memory grew over the recorded run: the world, the timeline and allocator
// slack, a check on memory_MB). Wall-clock figures: on a loaded machine compare ratios.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>

#include <time.h>
#include <unistd.h>

#include <particle_sandbox/world.hpp>

#include "gas_scene.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/timeline.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this thread, ms: what a step back costs in work, whatever else the machine runs.
double cpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

// Resident memory of this process, bytes (Linux).
double residentBytes() {
    long pages = 0, resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

struct Recorded {
    psb::app::Timeline timeline;
    double recordUs = 0.0;
    double frameMs = 0.0;
    double residentGrowth = 0.0;  // bytes: the run's world and timeline
};

// One recorded run per mode, made on first use and shared by the iterations.
Recorded& recorded(psb::StepMode mode) {
    static std::map<psb::StepMode, std::unique_ptr<Recorded>> runs;
    auto& slot = runs[mode];
    if (slot) return *slot;
    const double resident0 = residentBytes();
    slot = std::make_unique<Recorded>();
    psb::World w = psb::bench::makeGasWorld(10'000, psb::BroadPhaseKind::Auto, 1);
    if (mode != psb::StepMode::Exact) w.setGravity(psb::Vec2(0.0, 9.81));
    const double dt = psb::bench::kDt;
    w.setSolver({.mode = mode, .substeps = 4});
    for (int k = 0; k < 20; ++k)
        w.step(dt);  // the random placement's overlaps are separated before recording starts
    constexpr int kFrames = 12 * 60;
    double accumulator = 0.0, stepMs = 0.0, recordMs = 0.0;
    for (int f = 0; f < kFrames; ++f) {
        accumulator += 1.0 / 60.0;
        const double c0 = cpuMs();
        while (accumulator >= dt) {
            w.step(dt);
            slot->timeline.stepped(dt);
            accumulator -= dt;
        }
        const double c1 = cpuMs();
        slot->timeline.record(w);
        recordMs += cpuMs() - c1;
        stepMs += c1 - c0;
    }
    slot->recordUs = 1000.0 * recordMs / kFrames;
    slot->frameMs = stepMs / kFrames;
    slot->residentGrowth = residentBytes() - resident0;
    return *slot;
}

void BM_StepBack(benchmark::State& state) {
    const auto mode = static_cast<psb::StepMode>(state.range(0));
    Recorded& r = recorded(mode);
    psb::app::Timeline& t = r.timeline;
    double totalMs = 0.0, worstMs = 0.0, wallMs = 0.0;
    std::size_t steps = 0, replayedMax = 0;
    for (auto _ : state) {
        for (std::int64_t f = t.lastFrame(); f >= t.firstFrame(); --f) {
            const auto t0 = Clock::now();
            const double c0 = cpuMs();
            const psb::World& w = t.seek(f);
            benchmark::DoNotOptimize(&w);
            const double ms = cpuMs() - c0;
            wallMs += msSince(t0);
            totalMs += ms;
            worstMs = std::max(worstMs, ms);
            replayedMax = std::max(replayedMax, t.lastSeekReplayed());
            ++steps;
        }
    }
    state.SetLabel(std::string(psb::toString(mode)));
    state.counters["memory_MB"] = static_cast<double>(t.memoryBytes()) / 1e6;
    state.counters["rss_growth_MB"] = r.residentGrowth / 1e6;
    state.counters["covered_s"] = t.coveredSeconds();
    state.counters["keyframes"] = static_cast<double>(t.keyframeCount());
    state.counters["spacing_s"] = t.keyframeSpacing();
    state.counters["step_back_ms"] = totalMs / static_cast<double>(steps);
    state.counters["worst_ms"] = worstMs;
    state.counters["step_back_wall_ms"] = wallMs / static_cast<double>(steps);
    state.counters["replayed_max"] = static_cast<double>(replayedMax);
    state.counters["record_us"] = r.recordUs;
    state.counters["frame_ms"] = r.frameMs;
}
BENCHMARK(BM_StepBack)
    ->ArgName("mode")
    ->Arg(static_cast<int>(psb::StepMode::Discrete))
    ->Arg(static_cast<int>(psb::StepMode::Substep))
    ->Arg(static_cast<int>(psb::StepMode::Exact))
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond);

// Through the Session, as a user causes it: a gas of `n` particles run at 60 frames per second
// (Session::update, no frame budget, so 12 s of simulated time are always reached), then paused
// (Space); one iteration is 60 Shift+Left presses (cmd::StepBack) and one 10 s scrub
// (cmd::Seek to 10 s before the present, then back to the present), each apply() timed. Then
// 120 gravity switches (one undo entry each) fill the undo history, and 21 Ctrl+Z are timed.
// Counters: timeline_MB, covered_s, step_back_ms / step_back_worst_ms (CPU, one press),
// scrub_10s_ms (CPU, the seek 10 s back), undo_MB (the history after 120 edits; it keeps
// undo_steps of them), first_undo_ms (CPU, the first undo, which also frees the step-back
// record), undo_ms (CPU, one undo, mean of the 20 after it).
void BM_SessionStepBack(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto mode = static_cast<psb::StepMode>(state.range(1));
    psb::World w = psb::bench::makeGasWorld(n, psb::BroadPhaseKind::Auto, 1);
    if (mode != psb::StepMode::Exact) w.setGravity(psb::Vec2(0.0, 9.81));
    w.setSolver({.mode = mode, .substeps = 4});
    for (int k = 0; k < 20; ++k)
        w.step(psb::bench::kDt);  // the random placement's overlaps are separated first
    psb::app::SessionOptions options;
    options.saveTo = "/dev/null";
    psb::app::Session s(std::move(w), psb::SceneInfo{.name = "gas", .dt = psb::bench::kDt},
                        options);
    double now = 0.0;
    const double start = s.world().time();
    while (s.world().time() < start + 12.0) {
        now += 1.0 / 60.0;
        s.update(1.0 / 60.0, now, 1e9);
    }
    s.apply(psb::app::cmd::TogglePause{});
    s.update(0.0, now);
    double stepMs = 0.0, worstMs = 0.0, scrubMs = 0.0;
    std::size_t presses = 0;
    for (auto _ : state) {
        for (int k = 0; k < 60; ++k) {
            const double c0 = cpuMs();
            s.apply(psb::app::cmd::StepBack{});
            const double ms = cpuMs() - c0;
            stepMs += ms;
            worstMs = std::max(worstMs, ms);
            ++presses;
        }
        const double latest = s.timeline().latest;
        const double c0 = cpuMs();
        s.apply(psb::app::cmd::Seek{latest - 10.0});
        scrubMs += cpuMs() - c0;
        s.apply(psb::app::cmd::Seek{latest});
    }
    const psb::app::TimelineView v = s.timeline();
    state.counters["timeline_MB"] = static_cast<double>(s.timelineRecord().memoryBytes()) / 1e6;
    state.counters["covered_s"] = v.latest - v.earliest;
    state.counters["step_back_ms"] = stepMs / static_cast<double>(presses);
    state.counters["step_back_worst_ms"] = worstMs;
    state.counters["scrub_10s_ms"] = scrubMs / static_cast<double>(state.iterations());
    for (int k = 0; k < 120; ++k) {
        s.apply(psb::app::gravityToggle(s.world().def().gravity, s.loadedWorld().def().gravity));
        now += 1.0 / 60.0;
        s.update(1.0 / 60.0, now);
    }
    state.counters["undo_MB"] = static_cast<double>(s.undoHistory().memoryBytes()) / 1e6;
    state.counters["undo_steps"] = static_cast<double>(s.undoHistory().undoCount());
    // The first undo also lets go of the step-back record (it restarts); the next ones do not.
    const double c0 = cpuMs();
    s.apply(psb::app::cmd::Undo{});
    const double c1 = cpuMs();
    constexpr int kUndos = 20;
    for (int k = 0; k < kUndos; ++k)
        s.apply(psb::app::cmd::Undo{});
    state.counters["first_undo_ms"] = c1 - c0;
    state.counters["undo_ms"] = (cpuMs() - c1) / kUndos;
    state.SetLabel(std::string(psb::toString(mode)) + ", " + std::to_string(n) + " particles");
}
BENCHMARK(BM_SessionStepBack)
    ->ArgNames({"n", "mode"})
    ->ArgsProduct({{100, 1000, 10000},
                   {static_cast<int>(psb::StepMode::Discrete),
                    static_cast<int>(psb::StepMode::Substep),
                    static_cast<int>(psb::StepMode::Exact)}})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
