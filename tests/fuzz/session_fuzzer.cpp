// libFuzzer target for sequences of the session's commands: everything a user can do in the
// window, as the keys, the mouse and the control panel send it, with the frames between.
//
// The session (src/app/session) links the core only, so it is fuzzed without a window. The
// bytes choose a scene (the built-in one or a small preset), then up to 64 commands — pointer
// presses, drags and releases anywhere on screen, deletions, pan and zoom, every toggle, pause,
// single steps, time speed, step back and forward, seeks, undo and redo, spawns, the laws and
// the mode, presets, the edit prompt's keys and the panel's edits with any text, tools, pegs
// and walls, obstacle removal, selection, saves and opens of what was saved — each followed by
// a frame of some length. Properties (built with ASan and UBSan, so any memory error or
// undefined behaviour is a finding): nothing crashes or hangs, and after every frame every
// particle is finite. (Not "inside the box": paused, a particle dragged past a wall stays where
// the hand put it until the next step.)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

#include "session/command.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"

namespace {

namespace fs = std::filesystem;
using namespace psb;
using namespace psb::app;

constexpr int kMaxCommands = 64;
constexpr int kWindow = 800;

[[noreturn]] void violated(const char* what, const std::string& detail) {
    std::fprintf(stderr, "session_fuzzer: %s: %s\n", what, detail.c_str());
    std::abort();
}

/// The presets small enough to fuzz with (a few hundred particles at most), by path.
std::vector<fs::path> smallPresets() {
    std::vector<fs::path> presets;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::path(PSB_ASSETS_DIR) / "scenes", ec)) {
        try {
            const Scene s = loadScene(e.path());
            if (s.particles.size() <= 300 && s.droppers.empty()) presets.push_back(e.path());
        } catch (const SceneError&) {
        }
    }
    std::sort(presets.begin(), presets.end());
    return presets;
}

/// A folder of this process's own for saves, emptied before each input.
const fs::path& saveDir() {
    static const fs::path dir =
        fs::temp_directory_path() / ("psb-session-fuzz-" + std::to_string(::getpid()));
    return dir;
}

/// PSB_FUZZ_TRACE=1 prints each command to stderr (for reading a finding).
bool tracing() {
    static const bool on = std::getenv("PSB_FUZZ_TRACE") != nullptr;
    return on;
}

Vec2 screenPoint(FuzzedDataProvider& in) {
    // Mostly in the window, sometimes far outside it.
    const double lo = in.ConsumeBool() ? -100.0 : -1e6, hi = lo < -1e3 ? 1e6 : kWindow + 100.0;
    return {in.ConsumeFloatingPointInRange<double>(lo, hi),
            in.ConsumeFloatingPointInRange<double>(lo, hi)};
}

double value(FuzzedDataProvider& in, double lo, double hi) {
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {
        case 0:
            return std::nan("");
        case 1:
            return INFINITY;
        case 2:
            return -in.ConsumeFloatingPointInRange<double>(0.0, hi);
        case 3:
            return hi * 1e6;
        default:
            return in.ConsumeFloatingPointInRange<double>(lo, hi);
    }
}

/// Text for the edit prompt and the panel's fields: numbers, signs, junk.
std::string text(FuzzedDataProvider& in) {
    static const char* const kWords[] = {"1",      "0",   "-3", "2.5",   "1e308",
                                         "nan",    "inf", "-0", "0.001", "99999",
                                         "1e-320", "abc", ".",  "",      "12.5e-1"};
    if (in.ConsumeBool()) return kWords[in.ConsumeIntegralInRange<std::size_t>(0, 14)];
    return in.ConsumeRandomLengthString(16);
}

ParticleId someParticle(FuzzedDataProvider& in, const Session& s) {
    const std::vector<ParticleId> ids = s.world().ids();
    if (ids.empty() || in.ConsumeIntegralInRange<int>(0, 7) == 0) return ParticleId{};
    return ids[in.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)];
}

Command command(FuzzedDataProvider& in, const Session& s, double now,
                const std::vector<fs::path>& presets) {
    switch (in.ConsumeIntegralInRange<int>(0, 66)) {
        case 0:
        case 1:
            return cmd::PointerDown{screenPoint(in), now};
        case 2:
        case 3:
            return cmd::PointerMove{screenPoint(in), now};
        case 4:
        case 5:
            return cmd::PointerUp{screenPoint(in), now};
        case 6:
            return cmd::DeleteHeld{};
        case 7:
            return cmd::Pan{{value(in, -500, 500), value(in, -500, 500)}};
        case 8:
            return cmd::Zoom{screenPoint(in), value(in, 0.01, 100.0)};
        case 9:
            return cmd::Fit{};
        case 10:
            return cmd::Resize{in.ConsumeIntegralInRange<int>(-10, 4000),
                               in.ConsumeIntegralInRange<int>(-10, 4000)};
        case 11: {
            // A key that shows or hides something, the trails key, or the help.
            const int k = in.ConsumeIntegralInRange<int>(0, 12);
            if (k == 9) return cmd::ToggleHelp{};
            if (k == 10) return cmd::SetTrails{static_cast<int>(nextTrailMode(s.view().trails))};
            const auto option = k == 11   ? ShowOption::Spin
                                : k == 12 ? ShowOption::YUp
                                          : static_cast<ShowOption>(k);
            return cmd::SetShow{option, !s.view().shown(option)};
        }
        case 12:
            return cmd::TogglePause{};
        case 13:
            return cmd::SingleStep{};
        case 14:
            return cmd::SetTimeScale{s.timeScale() * value(in, 0.1, 10.0)};
        case 15:
            return cmd::StepBack{};
        case 16:
            return cmd::StepForward{};
        case 17:
            return cmd::Seek{value(in, -1.0, 20.0)};
        case 18:
            return cmd::SeekBy{value(in, -5.0, 5.0)};
        case 19:
            return cmd::Undo{};
        case 20:
            return cmd::Redo{};
        case 21:
            return cmd::SpawnRandom{};
        case 22:
            return cmd::ChangeSpawnMass{in.ConsumeIntegralInRange<int>(-2, 2)};
        case 23:
            return restitutionStep(s.world().def().restitution,
                                   in.ConsumeIntegralInRange<int>(-2, 2));
        case 24:
            return in.ConsumeBool() ? Command{gravityToggle(s.world().def().gravity,
                                                            s.loadedWorld().def().gravity)}
                                    : Command{modeStep(s.world().solver())};
        case 25:
            return cmd::Restart{};
        case 26:
            return cmd::OpenPreset{presets.empty() ? -1
                                                   : in.ConsumeIntegralInRange<int>(
                                                         -2, static_cast<int>(presets.size()))};
        case 27:
            switch (in.ConsumeIntegralInRange<int>(0, 4)) {
                case 0:
                    return cmd::OpenEdit{};
                case 1:
                    return cmd::EditType{text(in)};
                case 2:
                    return cmd::EditField{in.ConsumeBool()};
                case 3:
                    return cmd::EditBackspace{};
                default:
                    return cmd::EditApply{};
            }
        case 28:
            return cmd::SetRestitution{value(in, 0.0, 1.0), in.ConsumeBool()};
        case 29:
            return cmd::SetFriction{value(in, 0.0, 2.0), in.ConsumeBool()};
        case 30:
            return cmd::SetGravity{in.ConsumeBool(), value(in, 0.0, 50.0), in.ConsumeBool()};
        case 31:
            return cmd::SetWalls{in.ConsumeBool()};
        case 32:
            return cmd::SetMode{static_cast<StepMode>(in.ConsumeIntegralInRange<int>(0, 2)),
                                in.ConsumeIntegralInRange<int>(-1, 70)};
        case 33:
            return cmd::SetTimeScale{value(in, 0.05, 10.0)};
        case 34:
            return cmd::SetTool{static_cast<cmd::Tool>(in.ConsumeIntegralInRange<int>(0, 5)),
                                in.ConsumeBool()};
        case 35:
            return cmd::SetObstacleSizes{value(in, 0.01, 2.0), value(in, 0.01, 2.0)};
        case 36:
            return cmd::RemoveObstacle{in.ConsumeIntegralInRange<std::size_t>(0, 6)};
        case 37:
            return cmd::SetLaunchBody{value(in, 0.001, 100.0), value(in, 0.0, 1.0), std::nullopt};
        case 38:
            return cmd::EditParticle{
                someParticle(in, s),
                static_cast<ParticleField>(in.ConsumeIntegralInRange<int>(0, 7)), text(in)};
        case 39:
            return cmd::DeleteParticle{someParticle(in, s)};
        case 40:
            return cmd::Select{someParticle(in, s)};
        case 41:
            return cmd::SetShow{static_cast<cmd::ShowOption>(in.ConsumeIntegralInRange<int>(0, 11)),
                                in.ConsumeBool()};
        case 42:
            return in.ConsumeBool() ? Command{cmd::ToggleControls{}} : Command{cmd::Back{}};
        case 43:
            if (in.ConsumeBool()) return cmd::Save{};
            return cmd::SaveAs{saveDir() / text(in), in.ConsumeBool()};
        case 44:
            // The dialogs: opened, answered, cancelled, in any order.
            switch (in.ConsumeIntegralInRange<int>(0, 3)) {
                case 0:
                    return cmd::AskSaveAs{};
                case 1:
                    return cmd::AskNewScene{};
                case 2:
                    return cmd::CloseDialog{};
                default:
                    return cmd::Quit{};
            }
        case 45:
            return cmd::AnswerQuit{
                static_cast<cmd::AnswerQuit::Choice>(in.ConsumeIntegralInRange<int>(0, 2))};
        case 46:
            return cmd::NewScene{value(in, -1.0, 50.0), value(in, -1.0, 50.0),
                                 value(in, -1.0, 100.0), in.ConsumeBool()};
        case 47:
            return in.ConsumeBool() ? Command{cmd::Revert{}} : Command{cmd::Restart{}};
        case 48:
            return cmd::SetSceneText{text(in), text(in)};
        case 49: {
            // A name, not a path: the export folder is the fuzzer's own.
            std::string name = text(in);
            std::replace(name.begin(), name.end(), '/', '_');
            return cmd::ExportTable{
                static_cast<cmd::DataTable>(in.ConsumeIntegralInRange<int>(0, 3)), name};
        }
        case 50:
            return cmd::CopyTable{
                static_cast<cmd::DataTable>(in.ConsumeIntegralInRange<int>(0, 3))};
        case 51:
            return cmd::SetRecording{in.ConsumeBool(), in.ConsumeIntegralInRange<int>(-2, 2000)};
        case 52: {
            const VideoSettings v{static_cast<VideoFormat>(in.ConsumeIntegralInRange<int>(0, 2)),
                                  in.ConsumeBool()};
            return in.ConsumeBool() ? cmd::ToggleVideo{v} : cmd::ToggleVideo{};
        }
        case 53:
            return cmd::SetVideoSettings{
                {static_cast<VideoFormat>(in.ConsumeIntegralInRange<int>(0, 2)), in.ConsumeBool()}};
        case 54:
            return cmd::Stopwatch{
                static_cast<cmd::Stopwatch::Action>(in.ConsumeIntegralInRange<int>(0, 3))};
        case 55: {
            static const double kFactors[] = {1.1,
                                              1.0 / 1.1,
                                              0.0,
                                              -1.0,
                                              10.0,
                                              11.0,
                                              1e-300,
                                              std::numeric_limits<double>::quiet_NaN(),
                                              std::numeric_limits<double>::infinity()};
            return cmd::ScaleSpeeds{in.ConsumeBool()
                                        ? value(in, 0.0, 20.0)
                                        : kFactors[in.ConsumeIntegralInRange<int>(0, 8)]};
        }
        case 56: {
            static const double kSeconds[] = {
                0.005, 5.0, 0.0, -1.0, 1e300, std::numeric_limits<double>::quiet_NaN()};
            return cmd::SetArrowScale{in.ConsumeBool()
                                          ? value(in, 0.0, 6.0)
                                          : kSeconds[in.ConsumeIntegralInRange<int>(0, 5)],
                                      in.ConsumeBool()};
        }
        case 57: {
            static const double kBetas[] = {
                -1.0, 1.0, 0.0, -1.5, 2.0, 1e300, std::numeric_limits<double>::quiet_NaN()};
            return cmd::SetTangentialRestitution{in.ConsumeBool()
                                                     ? value(in, -1.5, 1.5)
                                                     : kBetas[in.ConsumeIntegralInRange<int>(0, 6)],
                                                 in.ConsumeBool()};
        }
        case 58:
            return cmd::SetDiscsTurn{in.ConsumeBool()};
        case 59: {
            static const double kSides[] = {0.0, -1.0,  0.01,
                                            1e6, 1e300, std::numeric_limits<double>::quiet_NaN()};
            const double w = s.world().def().width, h = s.world().def().height;
            switch (in.ConsumeIntegralInRange<int>(0, 2)) {
                case 0:
                    return cmd::ResizeBox{w * value(in, 0.0, 2.0), h * value(in, 0.0, 2.0)};
                case 1:
                    return cmd::ResizeBox{kSides[in.ConsumeIntegralInRange<int>(0, 5)], h};
                default:
                    return cmd::ResizeBox{w * std::sqrt(0.9), h * std::sqrt(0.9)};
            }
        }
        case 60: {
            static const double kScales[] = {
                0.75, 3.0, 1.0, 0.0, 0.74, 3.01, -1.0, std::numeric_limits<double>::quiet_NaN()};
            return cmd::SetUiScale{in.ConsumeBool() ? value(in, 0.0, 4.0)
                                                    : kScales[in.ConsumeIntegralInRange<int>(0, 7)],
                                   in.ConsumeBool()};
        }
        case 61:
            return cmd::SetTheme{in.ConsumeBool() ? Theme::Light : Theme::Dark};
        case 62:
            return cmd::ClipboardResult{in.ConsumeBool(), text(in)};
        case 63:
            return cmd::SetTouch{in.ConsumeBool()};
        case 65:
            return cmd::FitUiScale{in.ConsumeBool() ? value(in, 0.0, 4.0) : 1.6};
        case 66:
            return cmd::PointerLeave{};
        default:
            return cmd::OpenFile{saveDir() / (in.ConsumeBool() ? "save.json" : text(in))};
    }
}

void checkWorld(const World& w, int step) {
    const ParticleArrays& p = w.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(p.vx[i]) ||
            !std::isfinite(p.vy[i])) {
            violated("frame", "particle " + std::to_string(i) + " is not finite after command " +
                                  std::to_string(step));
        }
        if (p.rotation && (!std::isfinite(p.angle[i]) || !std::isfinite(p.omega[i]) ||
                           !(p.inertiaFactor[i] > 0.0 && p.inertiaFactor[i] <= 1.0) ||
                           (p.fixedRotation[i] != 0 && p.omega[i] != 0.0))) {
            violated("frame", "particle " + std::to_string(i) +
                                  "'s rotation is out of its rules after command " +
                                  std::to_string(step));
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<fs::path> presets = smallPresets();
    FuzzedDataProvider in(data, size);
    std::error_code ec;
    fs::remove_all(saveDir(), ec);
    fs::create_directories(saveDir(), ec);

    const std::size_t pick = in.ConsumeIntegralInRange<std::size_t>(0, presets.size());
    const Scene scene = pick == presets.size() ? defaultScene() : loadScene(presets[pick]);
    SessionOptions o;
    o.saveTo = saveDir() / "save.json";
    o.exportDir = saveDir();
    o.presets = presets;
    o.seed = in.ConsumeIntegral<std::uint32_t>();
    o.paused = in.ConsumeBool();
    o.viewportWidth = kWindow;
    o.viewportHeight = kWindow;
    Session session(makeWorld(scene), sceneInfo(scene, std::nullopt), o);

    double now = 0.0;
    for (int k = 0; k < kMaxCommands && in.remaining_bytes() > 0; ++k) {
        const Command c = command(in, session, now, presets);
        if (tracing()) {
            std::fprintf(stderr, "command %d: variant %zu, %zu particles, mode %d, paused %d\n", k,
                         c.index(), session.world().size(),
                         static_cast<int>(session.world().solver().mode), session.paused());
        }
        if (tracing()) {
            if (const auto* save = std::get_if<cmd::SaveAs>(&c))
                std::fprintf(stderr, "  save as '%s'\n", save->path.c_str());
            if (const auto* edit = std::get_if<cmd::EditParticle>(&c)) {
                std::fprintf(stderr, "  edit %s of particle %llu: '%s'\n", fieldName(edit->field),
                             static_cast<unsigned long long>(particleNumber(edit->id)),
                             edit->text.c_str());
            }
        }
        session.apply(c);
        const double frame = in.PickValueInArray({0.0, 1.0 / 60.0, 1.0 / 30.0, 0.1, 0.5});
        now += frame;
        session.update(frame, now, 50.0);
        (void)session.takeNotices();
        (void)session.takeScreenshotRequest();
        (void)session.takeClipboardText();
        (void)session.takeVideoToggle();
        checkWorld(session.world(), k);
    }
    return 0;
}
