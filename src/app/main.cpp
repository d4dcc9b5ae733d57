// particle-sandbox: the interactive window. Parses the command line and runs the App.

#include <cstdio>
#include <exception>
#include <regex>
#include <string>

#include <CLI/CLI.hpp>

#include "app.hpp"

namespace {

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
    std::string scene, window, saveTo = options.saveTo.string();
    cli.add_option("SCENE", scene, "Scene file (JSON) to open; a built-in scene if omitted");
    cli.add_option("--save-to", saveTo, "Where Ctrl+S saves the world")->capture_default_str();
    cli.add_option("--window", window, "Window size in pixels, WIDTHxHEIGHT (default 800x800)");
    cli.add_option("--renderer", options.renderDriver,
                   "SDL render driver (software, opengl, opengles2, ...); SDL picks if omitted");
    cli.add_flag("--paused", options.startPaused, "Start paused (Space resumes)");
    bool noArrows = false;
    cli.add_flag("--no-arrows", noArrows, "Start with the velocity arrows hidden (A shows them)");
    bool noVsync = false;
    cli.add_flag("--no-vsync", noVsync, "Do not wait for the display's refresh");
    cli.add_option("--bench", options.benchParticles,
                   "Frame-time benchmark: open N particles, run --frames frames, print the mean "
                   "step and draw times and exit")
        ->check(CLI::Range(std::size_t{1}, std::size_t{10'000'000}));
    cli.add_option("--frames", options.benchFrames, "Frames for --bench")
        ->check(CLI::Range(1, 1'000'000))
        ->capture_default_str();
    cli.add_option("--bench-overlays", options.benchOverlays,
                   "With --bench: also draw these overlays, by key: any of V (momentum), L (all "
                   "trails), K (plots), D (speed histogram), e.g. VLKD")
        ->check([](const std::string& keys) {
            return keys.find_first_not_of("VLKD") == std::string::npos && !keys.empty()
                       ? std::string()
                       : "expected letters from VLKD, got '" + keys + "'";
        });
    cli.add_option("--seed", options.seed, "Seed for random spawns (0: from the clock)");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e);
    }
    if (!window.empty() && !parseWindowSize(window, options.width, options.height)) {
        std::fprintf(stderr,
                     "particle-sandbox: --window: expected WIDTHxHEIGHT between 200 and 10000 "
                     "pixels, got '%s'\n",
                     window.c_str());
        return 2;
    }
    if (!scene.empty()) options.scene = scene;
    options.saveTo = saveTo;
    options.arrows = !noArrows;
    options.vsync = !noVsync && options.benchParticles == 0;

    try {
        psb::app::App app(options);
        return options.benchParticles > 0 ? app.runBenchmark() : app.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "particle-sandbox: %s\n", e.what());
        return 1;
    }
}
