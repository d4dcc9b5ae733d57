#include "browser_loop.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include <emscripten.h>

#include "platform/browser_files.hpp"
#include "platform/browser_input.hpp"
#include "platform/browser_settings.hpp"

// The page's functions (web/index.html), called if it has them.
// clang-format off
EM_JS(void, psb_js_started, (void* loop), {
    if (typeof psbStarted === "function") psbStarted(loop);
});
EM_JS(void, psb_js_ended, (const char* line), {
    if (typeof psbEnded === "function") psbEnded(UTF8ToString(line));
});
EM_JS(void, psb_js_show_about, (), {
    if (typeof psbShowAbout === "function") psbShowAbout();
});
// clang-format on

namespace psb::app {

namespace {

/// What the loop owns; it lives as long as the page.
struct BrowserLoop {
    std::unique_ptr<App> app;
    DownloadFolder downloads;
    BrowserSettings settings;
    bool benchmark = false;
    int benchFrames = 0;
    std::chrono::steady_clock::time_point benchStart;
};

void ended(const std::string& line) {
    emscripten_cancel_main_loop();
    psb_js_ended(line.c_str());
}

void benchmarkPass(BrowserLoop& loop) {
    const auto t = std::chrono::steady_clock::now();
    if (loop.benchFrames == 0) loop.benchStart = t;
    if (loop.app->benchmarkFrame()) {
        ++loop.benchFrames;
        return;
    }
    // The frames' wall-clock rate: what the browser's animation frames reached, the drawing of
    // the canvas included (the report's own figure is the step and draw times alone).
    const double seconds = std::chrono::duration<double>(t - loop.benchStart).count();
    char rate[160];
    std::snprintf(rate, sizeof rate, "; browser: %d frames in %.2f s (%.1f fps)", loop.benchFrames,
                  seconds, seconds > 0 ? (loop.benchFrames - 1) / seconds : 0.0);
    std::string line = loop.app->benchmarkReport() + rate;
    std::puts(rate + 2);
    ended(line);
}

void pass(void* arg) {
    auto& loop = *static_cast<BrowserLoop*>(arg);
    try {
        if (loop.benchmark) {
            benchmarkPass(loop);
            return;
        }
        loop.app->loopOnce(false);
        std::string problem;
        for (const Command& c : loop.settings.load(loop.app->session().view(), problem))
            loop.app->command(c);
        if (!problem.empty()) loop.app->warn(problem);
        loop.settings.save(loop.app->session().view());
        if (loop.app->controlPanel().takeUploadRequest()) askForUpload(loop.downloads.folder());
        if (loop.app->controlPanel().takeAboutRequest()) psb_js_show_about();
        for (const std::string& name : loop.downloads.offerNew()) {
            loop.app->inform("Downloaded " + name + " (the browser's downloads)");
        }
        if (!loop.app->running()) ended("The sandbox has closed. Reload the page to start again.");
    } catch (const std::exception& e) {  // what main() reports on the desktop
        std::fprintf(stderr, "particle-sandbox: %s\n", e.what());
        ended(std::string("particle-sandbox: ") + e.what());
    }
}

}  // namespace

void runInBrowser(std::unique_ptr<App> app, const std::filesystem::path& folder, bool benchmark) {
    app->controlPanel().setBrowser(true);
    stampPointerEventsWithBrowserTimes();
    if (!benchmark) app->greet();
    auto* loop = new BrowserLoop{
        std::move(app), DownloadFolder(folder), BrowserSettings("/settings"), benchmark, 0, {}};
    psb_js_started(loop);
    // 0: the browser's animation frame rate; false: return, the loop runs after main().
    emscripten_set_main_loop_arg(pass, loop, 0, false);
}

}  // namespace psb::app

/// The page wrote the scene file the user picked at `path` (in the download folder): open it,
/// as if it had been dropped on the window.
extern "C" EMSCRIPTEN_KEEPALIVE void psb_web_uploaded(void* loopPtr, const char* path) {
    auto& loop = *static_cast<psb::app::BrowserLoop*>(loopPtr);
    loop.downloads.markSeen(path);
    SDL_Event e{};
    e.type = SDL_DROPFILE;
    e.drop.file = SDL_strdup(path);
    e.drop.windowID = 0;
    SDL_PushEvent(&e);
}
