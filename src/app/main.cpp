// particle-sandbox: the interactive window. Parses the command line and runs the App.

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <regex>
#include <string>

#include <CLI/CLI.hpp>

#include "app.hpp"
#include "build_info.hpp"
#include "parse_error_message.hpp"
#include "platform/assets.hpp"
#include "platform/output_directory.hpp"
#include "platform/settings_store.hpp"
#ifdef __EMSCRIPTEN__
#include "browser_loop.hpp"
#endif

namespace {

/// Most particles --bench takes: 200,000 run at about 18 frames per second with the software
/// renderer (step 7 ms, draw 47 ms), so the default 300 frames take under 20 s; far more would
/// mostly measure the machine's memory.
constexpr std::size_t kMaxBenchParticles = 200'000;

int badOption(const std::string& message) {
    std::fprintf(stderr, "particle-sandbox: %s\n", message.c_str());
    return 2;
}

/// "800x600" -> (800, 600); false when malformed or outside 200..10000 pixels.
bool parseWindowSize(const std::string& text, int& width, int& height) {
    static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
    std::smatch m;
    if (!std::regex_match(text, m, pattern)) return false;
    width = std::stoi(m[1].str());
    height = std::stoi(m[2].str());
    return width >= 200 && height >= 200 && width <= 10000 && height <= 10000;
}

}  // namespace

int main(int argc, char** argv) {
    psb::app::AppOptions options;
    CLI::App cli{
        "Particle Sandbox: fling, launch and watch elastic circles collide.\n"
        "Press H in the window for the controls.",
        "particle-sandbox"};
    cli.set_version_flag("--version", psb::versionLine("particle-sandbox"),
                         "Print the version (and git revision) and exit");
    const auto assets = psb::app::assetDirectory();
    cli.footer(assets ? "Preset scenes (P, 1-9) and fonts are read from " + assets->string()
                      : std::string("No fonts or preset scenes found; set PSB_ASSETS_DIR."));
    std::string scene, window, saveTo;
    std::string screenshotDir = options.screenshotDir.string();
    cli.add_option("SCENE", scene, "Scene file (JSON) to open; a built-in scene if omitted");
    cli.add_option("--save-to", saveTo,
                   "The file Save As proposes (Enter in its dialog writes it; a free NAME-2.json "
                   "beside it if it exists)");
    cli.add_option("--screenshot-dir", screenshotDir,
                   "Where F12 saves PNG screenshots, and where Save As proposes a file")
        ->capture_default_str();
    cli.add_option("--window", window, "Window size in pixels, WIDTHxHEIGHT (default 800x800)");
    cli.add_option("--renderer", options.renderDriver,
                   "SDL render driver (software, opengl, opengles2, ...); SDL picks if omitted");
    cli.add_flag("--paused", options.startPaused, "Start paused (Space resumes)");
#ifdef __EMSCRIPTEN__
    // The page's own: a device whose pointer is a finger (web/index.html asks the browser).
    cli.add_flag("--touch", options.touch, "A touch screen: hints name buttons, not keys");
#endif
    bool noArrows = false;
    cli.add_flag("--no-arrows", noArrows, "Start with the velocity arrows hidden (A shows them)");
    bool noVsync = false;
    cli.add_flag("--no-vsync", noVsync, "Do not wait for the display's refresh");
    long long bench = 0;  // signed, so that -5 is reported as -5 rather than wrapped
    cli.add_option("--bench", bench,
                   "Frame-time benchmark: open N particles (1 to 200000), run --frames frames, "
                   "print the mean step and draw times and exit");
    cli.add_option("--frames", options.benchFrames, "Frames for --bench")
        ->check(CLI::Range(1, 1'000'000))
        ->capture_default_str();
    cli.add_option("--bench-overlays", options.benchOverlays,
                   "With --bench: also draw these overlays and instruments, by key: any of V "
                   "(momentum), L (all trails), K (plots), D (speed histogram), I (values "
                   "table), J (last collision card), Q (ruler), G (grid), U (stopwatch), R "
                   "(every particle turning, with its spin mark), and M (masses of 1 to 4 kg, "
                   "each disc shaded by its mass), e.g. VLKD")
        ->check([](const std::string& keys) {
            return keys.find_first_not_of("VLKDIJQGURM") == std::string::npos && !keys.empty()
                       ? std::string()
                       : "expected letters from VLKDIJQGURM, got '" + keys + "'";
        });
    cli.add_option("--seed", options.seed, "Seed for random spawns (0: from the clock)");
    std::string record;
    cli.add_option("--record", record,
                   "Record a video from the start, into --screenshot-dir: mp4, webm or gif "
                   "(Ctrl+R stops); with --bench, every frame (what recording sustains)");
    bool noSettings = false;
    cli.add_flag("--no-settings", noSettings,
                 "Neither read nor write the settings file ($XDG_CONFIG_HOME/particle-sandbox/"
                 "settings.json, else ~/.config/...): UI scale, theme, what is shown");
    cli.add_flag("--log-controls", options.logControls,
                 "Log where each control of the panel is when they move, and each tooltip shown "
                 "(for scripted input)");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version exit 0 with CLI11's text; every other problem is one line and
        // status 2, like particle-sim's.
        if (e.get_exit_code() == 0) return cli.exit(e);
        return badOption(psb::parseErrorMessage(cli, e) + " (see --help)");
    }
    if (!window.empty() && !parseWindowSize(window, options.width, options.height)) {
        return badOption("--window: expected WIDTHxHEIGHT between 200 and 10000 pixels, got '" +
                         window + "'");
    }
    if (cli.count("--bench") > 0) {
        if (bench < 1 || bench > static_cast<long long>(kMaxBenchParticles)) {
            return badOption("--bench: expected 1 to " + std::to_string(kMaxBenchParticles) +
                             " particles, got " + std::to_string(bench));
        }
        options.benchParticles = static_cast<std::size_t>(bench);
    }
    // A path the app cannot write to is reported now, not at the first Ctrl+S or F12.
    if (cli.count("--save-to") > 0) {
        if (saveTo.empty()) return badOption("--save-to: needs a file name");
        if (std::filesystem::is_directory(saveTo)) {
            return badOption("--save-to: " + saveTo + " is a directory; give a file name");
        }
        if (const auto why = psb::app::outputDirectoryProblem(psb::app::directoryOf(saveTo))) {
            return badOption("--save-to: " + *why);
        }
        options.saveTo = saveTo;
    }
    if (const auto why = psb::app::outputDirectoryProblem(screenshotDir)) {
        return badOption("--screenshot-dir: " + *why);
    }
    if (cli.count("--record") > 0) {
        options.record = psb::app::parseVideoFormat(record);
        if (!options.record) {
            return badOption("--record: expected mp4, webm or gif, got '" + record + "'");
        }
        if (const auto why = psb::app::videoFormatProblem(*options.record)) {
            return badOption("--record: " + *why);
        }
    }
    if (!scene.empty()) options.scene = scene;
    options.screenshotDir = screenshotDir;
    options.arrows = !noArrows;
    options.vsync = !noVsync && options.benchParticles == 0;
#ifndef __EMSCRIPTEN__
    // The benchmark measures the program's defaults, not the user's settings.
    if (!noSettings && options.benchParticles == 0) {
        options.settingsFile =
            psb::app::settingsPath(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
    }
#endif

#ifdef __EMSCRIPTEN__
    options.inPage = true;  // Esc does not quit, what is saved is downloaded
#endif
    try {
        auto app = std::make_unique<psb::app::App>(options);
#ifdef __EMSCRIPTEN__
        // The browser runs the loop, one pass per animation frame; main() returns at once.
        psb::app::runInBrowser(std::move(app), options.screenshotDir, options.benchParticles > 0);
        return 0;
#else
        return options.benchParticles > 0 ? app->runBenchmark() : app->run();
#endif
    } catch (const std::exception& e) {
        std::fprintf(stderr, "particle-sandbox: %s\n", e.what());
        return 1;
    }
}
