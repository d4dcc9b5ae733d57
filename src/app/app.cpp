#include "app.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include <particle_sandbox/atomic_file.hpp>
#include <particle_sandbox/scene.hpp>

#include "platform/assets.hpp"
#include "platform/clipboard.hpp"
#include "platform/clock.hpp"
#include "platform/text_input.hpp"
#include "render/screen_text.hpp"
#include "render/screenshot.hpp"
#include "session/benchmark_scene.hpp"
#include "session/scene_io.hpp"
#include "session/stopwatch.hpp"
#include "view/box_area.hpp"
#include "view/hud.hpp"

namespace psb::app {

namespace {

/// Messages shown at once, newest last: the band the camera keeps free below the box holds
/// this many lines.
constexpr std::size_t kShownMessages = 2;
constexpr double kMessageSeconds = 3.0;

bool samePlaces(const std::vector<PanelItem>& a, const std::vector<PanelItem>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& p, const auto& q) {
        return p.name == q.name && p.x0 == q.x0 && p.y0 == q.y0 && p.x1 == q.x1 && p.y1 == q.y1;
    });
}

void logLine(const std::string& line) {
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

}  // namespace

App::App(const AppOptions& options) : options_(options) {
    // The scene first: a bad file is reported before any window opens.
    World world;
    SceneInfo meta;
    if (options_.benchParticles > 0) {
        const Scene scene = benchmarkScene(options_.benchParticles, 1,
                                           options_.benchOverlays.find('R') != std::string::npos,
                                           options_.benchOverlays.find('M') != std::string::npos);
        world = makeWorld(scene);
        meta.name = "benchmark";
        meta.dt = scene.dt;
    } else {
        const Scene scene = psb::app::openScene(options_.scene);
        world = makeWorld(scene);
        meta = sceneInfo(scene, options_.scene);
    }
    SdlContextOptions so;
    so.width = options_.width;
    so.height = options_.height;
    so.vsync = options_.vsync;
    so.renderDriver = options_.renderDriver;
    so.font = findAsset("fonts/DejaVuSansMono.ttf");
    sdl_ = std::make_unique<SdlContext>(so);
    logLine("[I] " + sdl_->rendererNote());
    stats_.renderer = sdl_->rendererName();

    SessionOptions s;
    s.saveTo = options_.saveTo;
    s.saveFolder = options_.screenshotDir;
    if (options_.benchParticles == 0) s.sceneFile = options_.scene;
    s.exportDir = options_.screenshotDir;
    s.presets = presetScenes();
    s.seed =
        options_.seed != 0 ? options_.seed : static_cast<std::uint32_t>(std::random_device{}());
    // A scene named on the command line opens paused, as presets do: its start is shown first.
    s.paused = options_.startPaused || (options_.scene && options_.benchParticles == 0);
    s.arrows = options_.arrows;
    s.inPage = options_.inPage;
    s.touch = options_.touch;
    const SDL_Point out = sdl_->outputSize();
    s.viewportWidth = out.x;
    s.viewportHeight = out.y;
    // Where the box goes: clear of the HUD's lines above it, the messages below it, the
    // control panel and (while they are on) the panels beside it (view/box_area.hpp).
    controls_ = controlsWidth(sdl_->pixelRatio(), out.x);
    s.layout = windowLayout(sdl_->hudFont(), out.x, out.y, controls_, options_.inPage);
    // A window less than twice the panel's width would leave the box less room than the
    // panel: it opens folded (C or >> opens it).
    s.controls = out.x >= 2.0 * controls_.open;
    session_.emplace(std::move(world), std::move(meta), std::move(s));
    for (const char c : options_.benchOverlays) {
        if (c == 'V') session_->apply(cmd::SetShow{ShowOption::Momentum, true});
        if (c == 'K') session_->apply(cmd::SetShow{ShowOption::Plots, true});
        if (c == 'D') session_->apply(cmd::SetShow{ShowOption::Speeds, true});
        if (c == 'I') session_->apply(cmd::SetShow{ShowOption::Values, true});
        if (c == 'J') session_->apply(cmd::SetShow{ShowOption::Collision, true});
        if (c == 'Q') session_->apply(cmd::SetShow{ShowOption::Ruler, true});
        if (c == 'G') session_->apply(cmd::SetShow{ShowOption::Grid, true});
        if (c == 'U') session_->apply(cmd::Stopwatch{cmd::Stopwatch::Action::StartStop});
        if (c == 'L') {
            session_->apply(cmd::SetTrails{static_cast<int>(TrailMode::All)});
        }
    }
    if (options_.benchParticles > 0) (void)session_->takeNotices();
    flushNotices();
    draw_ = std::make_unique<DrawLayer>(sdl_->renderer(), sdl_->hudFont(), sdl_->labelFont());
    GuiOptions gui;
    gui.font = findAsset("fonts/DejaVuSans.ttf");
    gui.fontPixels = 15.f;
    gui_ = std::make_unique<GuiContext>(sdl_->window(), sdl_->renderer(), gui);
    ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange;
    // The UI's scale for the window's height, then what the settings file keeps over it.
    session_->apply(cmd::FitUiScale{mostUiScale(sdl_->windowSize().x)});
    session_->apply(cmd::SetUiScale{automaticScale(), true});
    (void)session_->takeNotices();  // the starting scale is no news
    if (options_.settingsFile && options_.benchParticles == 0) {
        settings_.emplace(*options_.settingsFile);
        loadSettings();
    }
    syncLook();
    for (const VideoFormat f : {VideoFormat::Mp4, VideoFormat::WebM, VideoFormat::Gif}) {
        stats_.video.unavailable[static_cast<std::size_t>(f)] = videoFormatProblem(f).value_or("");
    }
    if (options_.record) {
        // The benchmark records every frame (what recording sustains); a window, in real time.
        if (options_.benchParticles > 0) {
            startVideo({*options_.record, false}, VideoRecorder::Pacing::EveryFrame);
            if (!video_) throw std::runtime_error("--record: cannot record video");
        } else {
            apply(cmd::ToggleVideo{VideoSettings{*options_.record, false}});
        }
    }
}

App::~App() {
    stopVideo();
}

void App::tell(const std::string& text, Notice::Level level) {
    logLine(logPrefix(level) + text);
    messages_.push_back({text, now() + kMessageSeconds, {}});
    if (messages_.size() > kShownMessages) {
        messages_.erase(messages_.begin(), messages_.end() - kShownMessages);
    }
}

double App::now() const {
    return ticksToSeconds(SDL_GetTicks64());
}

void App::flushNotices() {
    for (Notice& n : session_->takeNotices()) {
        if (n.log) logLine(logPrefix(n.level) + n.text);
        if (!n.show) continue;
        if (!n.topic.empty() && !messages_.empty() && messages_.back().topic == n.topic) {
            messages_.back() = {std::move(n.text), now() + kMessageSeconds, std::move(n.topic)};
        } else {
            messages_.push_back({std::move(n.text), now() + kMessageSeconds, std::move(n.topic)});
        }
    }
    if (messages_.size() > kShownMessages) {
        messages_.erase(messages_.begin(), messages_.end() - kShownMessages);
    }
    updateTextInput();
}

void App::updateTextInput() {
    // Text input only while the edit prompt or a field of the panel wants characters.
    const bool editing = session_->prompt().active() || (gui_ && gui_->io().WantTextInput);
    if (editing != textInput_) {
        setTextInput(editing);
        textInput_ = editing;
    }
}

void App::placeTyping() {
    if (!textInput_) return;
    const double ratio = sdl_->pixelRatio();
    const auto scale = static_cast<float>(session_->view().uiScaleInUse());
    TipRect at;
    if (const std::optional<GuiContext::Typing> t = gui_->typing()) {
        at = t->caret;
        for (const PanelItem& i : panel_.items()) {
            if (i.id == t->id) {  // the whole field the panel drew
                at = {i.x0 * scale, i.y0 * scale, (i.x1 - i.x0) * scale, (i.y1 - i.y0) * scale};
                break;
            }
        }
    } else if (session_->prompt().active()) {  // the edit prompt is in the message band
        const PixelRect& band = lastFrame_.layout.messages;
        const auto r = static_cast<float>(ratio > 0.0 ? ratio : 1.0);
        at = {static_cast<float>(band.x) / r, static_cast<float>(band.y) / r,
              static_cast<float>(band.w) / r, static_cast<float>(band.h) / r};
    }
    if (at.empty() || (at.x == typingAt_.x && at.y == typingAt_.y && at.w == typingAt_.w &&
                       at.h == typingAt_.h)) {
        return;
    }
    typingAt_ = at;
    placeTextInput(at.x, at.y, at.w, at.h);
}

std::vector<std::string> App::messages() const {
    std::vector<std::string> out;
    const double t = now();
    for (const Message& m : messages_)
        if (m.until >= t) out.push_back(m.text);
    return out;
}

void App::apply(const Command& c) {
    if (const auto* u = std::get_if<cmd::SetUiScale>(&c); u && u->automatic) {
        session_->apply(cmd::SetUiScale{automaticScale(), true});  // only the app knows the window
    } else {
        session_->apply(c);
    }
    syncLook();
    saveSettings();
    if (const std::optional<VideoSettings> video = session_->takeVideoToggle()) {
        toggleVideo(*video);
    }
    if (const std::optional<std::string> text = session_->takeClipboardText()) {
        // A page's answer comes later, as an event (processEvent).
        if (const std::optional<cmd::ClipboardResult> r = putOnClipboard(*text))
            session_->apply(*r);
    }
    flushNotices();
}

void App::warn(const std::string& text) {
    logLine("[W] " + text);
    show(text);
}

void App::inform(const std::string& text) {
    logLine("[I] " + text);
    show(text);
}

void App::show(const std::string& text) {
    messages_.push_back({text, now() + kMessageSeconds, {}});
    if (messages_.size() > kShownMessages) {
        messages_.erase(messages_.begin(), messages_.end() - kShownMessages);
    }
}

void App::processEvent(const SDL_Event& e) {
    // The controls first: what they take (a click on the panel, typing in its fields) is theirs.
    if (const std::optional<cmd::ClipboardResult> r = clipboardResult(e)) {
        apply(*r);
        return;
    }
    // A finger on the screen: hints name the panel's buttons from now on.
    if (e.type == SDL_FINGERDOWN && !session_->touch()) apply(cmd::SetTouch{true});
    const bool tabToPanel = !session_->prompt().active() && !session_->dialog().open();
    if (gui_ && gui_->handleEvent(e, tabToPanel)) return;
    act(e);
}

void App::act(const SDL_Event& e) {
    for (Command& c :
         input_.translate(e, keyState(*session_), sdl_->pixelRatio(), sdl_->outputSize())) {
        // A new window size comes with where the box may go in it.
        if (auto* r = std::get_if<cmd::Resize>(&c)) {
            // An automatic scale follows the window's height, and no scale may be more than its
            // width allows: the fonts first, for the layout.
            session_->apply(cmd::FitUiScale{mostUiScale(sdl_->windowSize().x)});
            if (session_->view().uiScaleAutomatic) {
                session_->apply(cmd::SetUiScale{automaticScale(), true});
            }
            syncLook();
            // The open panel's width is a share of the window's.
            controls_ = controlsWidth(controls_.pointPixels, r->width);
            r->layout =
                windowLayout(sdl_->hudFont(), r->width, r->height, controls_, options_.inPage);
        }
        apply(c);
    }
}

double App::automaticScale() const {
    return automaticUiScale(sdl_->windowSize().y);
}

void App::syncLook() {
    const ViewOptions& view = session_->view();
    if (view.theme != theme_) {
        gui_->setTheme(view.theme);
        theme_ = view.theme;
    }
    const double points = sdl_->pixelRatio() * view.uiScaleInUse();
    if (points == lookPoints_) return;
    lookPoints_ = points;
    try {
        sdl_->setTextScale(points);
        gui_->setScale(static_cast<float>(view.uiScaleInUse()));
    } catch (const std::exception& e) {  // a font file gone since the start
        logLine(std::string("[E] The text could not be made at the new scale: ") + e.what());
    }
    const SDL_Point out = sdl_->outputSize();
    controls_ = controlsWidth(points, out.x);
    session_->apply(cmd::Resize{
        out.x, out.y, windowLayout(sdl_->hudFont(), out.x, out.y, controls_, options_.inPage)});
}

void App::loadSettings() {
    // Out of the way while its own settings are applied: they are what the file holds.
    SettingsStore store = std::move(*settings_);
    settings_.reset();
    const SettingsRead read = store.load(session_->view());
    for (const std::string& problem : read.problems)
        warn(problem);
    for (const Command& c : read.commands)
        apply(c);
    if (!read.commands.empty()) logLine("[I] Settings read from " + store.file().string());
    store.keep(session_->view());
    settings_.emplace(std::move(store));
}

void App::saveSettings() {
    if (!settings_) return;
    if (const auto problem = settings_->save(session_->view())) warn(*problem);
}

void App::greet() {
    logLine("[I] Particle Sandbox: " + std::to_string(world().size()) +
            " particles. Press H for help.");
    for (const auto& [keys, what] : controls(options_.inPage))
        logLine("    " + keys + ": " + what);
}

int App::run() {
    greet();
    SDL_DisplayMode mode;
    const double refresh = SDL_GetCurrentDisplayMode(0, &mode) == 0 && mode.refresh_rate > 0
                               ? mode.refresh_rate
                               : 60.0;
    while (session_->running()) {
        const auto frameStart = std::chrono::steady_clock::now();
        loopOnce(true);
        // Where vsync is not honoured (a virtual display), do not spin faster than the display.
        const double spent =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
        const double budget = 1.0 / refresh;
        if (spent < budget - 0.001) SDL_Delay(static_cast<Uint32>((budget - spent) * 1000.0));
    }
    stopVideo();
    logLine("[I] Exiting.");
    return 0;
}

void App::loopOnce(bool mayWait) {
    const auto frameStart = std::chrono::steady_clock::now();
    const double real =
        lastLoop_ ? std::chrono::duration<double>(frameStart - *lastLoop_).count() : 0.0;
    lastLoop_ = frameStart;
    ++fpsFrames_;
    fpsSeconds_ += real;
    if (fpsSeconds_ >= 0.5) {
        stats_.fps = fpsFrames_ / fpsSeconds_;
        fpsFrames_ = 0;
        fpsSeconds_ = 0.0;
    }
    handleEvents(mayWait);
    update(std::min(real, 0.25));
    render();
}

void App::handleEvents(bool mayWait) {
    SDL_Event e;
    // Paused and idle: sleep until something happens (or a quarter second, for the messages).
    if (mayWait && session_->paused() &&
        session_->interaction().mode() == Interaction::Mode::Idle && !panelSettling_) {
        if (SDL_WaitEventTimeout(&e, 250) != 0) processEvent(e);
    }
    while (SDL_PollEvent(&e) != 0)
        processEvent(e);
}

void App::update(double realSeconds) {
    session_->update(realSeconds, now());
    flushNotices();
    stats_.lastStepMs = session_->lastStepMs();
    stats_.stepMs = 0.95 * stats_.stepMs + 0.05 * stats_.lastStepMs;
}

void App::frame(double realSeconds) {
    update(realSeconds);
    render();
}

void App::writeScreenshot(const DrawStats& drawn) {
    try {
        lastScreenshot_ = saveScreenshot(sdl_->renderer(), options_.screenshotDir);
        std::filesystem::path text = *lastScreenshot_;
        writeFileAtomically(text.replace_extension(".txt"), screenText(lastFrame_, drawn));
        std::error_code ec;
        const auto shown = std::filesystem::absolute(*lastScreenshot_, ec).lexically_normal();
        logLine("[I] Saved screenshot " + lastScreenshot_->string());
        const std::filesystem::path named = options_.inPage ? lastScreenshot_->filename()
                                            : ec            ? *lastScreenshot_
                                                            : shown;
        messages_.push_back({"Saved screenshot " + named.string(), now() + kMessageSeconds});
    } catch (const std::exception& e) {  // SaveError, or the pixels could not be read
        logLine(std::string("[E] Screenshot failed: ") + e.what());
        messages_.push_back(
            {std::string("Screenshot failed: ") + e.what(), now() + kMessageSeconds});
    }
}

void App::render() {
    const auto t0 = std::chrono::steady_clock::now();
    updateVideoStatus();
    stats_.messages = messages();
    gui_->beginFrame();
    panel_.holdLayout(gui_->fingerOnPanel());
    const double ratio = sdl_->pixelRatio();
    const SDL_Point out = sdl_->outputSize();
    // The help is read, then closed: meanwhile it takes the window's width, the panel's too.
    if (!session_->helpShown()) {
        // The panel's points are the UI's (gui_context.hpp): the pixel ratio × its scale.
        const double points = ratio * session_->view().uiScaleInUse();
        // Tooltips keep off the message band (where the last frame put it).
        const PixelRect band = lastFrame_.layout.messages;
        const auto p = static_cast<float>(points);
        gui_->setTooltipAvoid({static_cast<float>(band.x) / p, static_cast<float>(band.y) / p,
                               static_cast<float>(band.w) / p, static_cast<float>(band.h) / p});
        for (const Command& c : panel_.build(*session_, stats_, static_cast<float>(out.y / points),
                                             static_cast<float>(points))) {
            apply(c);
        }
    }
    lastFrame_ = buildFrame(*session_, stats_, sdl_->hudFont(), sdl_->labelFont(), controls_);
    const DrawStats drawn = draw_->draw(lastFrame_);
    if (gui_->endFrame() != 0) logLine("[W] The control panel was not drawn completely");
    // A Ctrl shortcut pressed in a field: the field's text was kept in this frame, now the key.
    for (const SDL_Event& e : gui_->takeAppKeys())
        act(e);
    if (const auto problem = gui_->takeProblem()) {
        logLine("[E] The text could not be made at the new scale: " + *problem);
    }
    updateTextInput();
    placeTyping();
    // A panel whose controls moved (a section opened) settles in the next frame: draw it even
    // when nothing else happens.
    panelSettling_ = !samePlaces(panel_.items(), lastItems_);
    if (panelSettling_) lastItems_ = panel_.items();
    if (options_.logControls) logControls();
    stats_.labelsSuppressed = drawn.labelsSuppressed;
    stats_.labelsCrowded = drawn.labelsCrowded;
    stats_.labelsOffWindow = drawn.labelsOffWindow;
    // The video takes the frame as drawn; the recording mark, the messages and the HUD's key
    // hints are on the screen, not in it.
    captureVideo();
    draw_->drawMessagesAfterCapture(lastFrame_);
    if (lastFrame_.recordingMark && video_) draw_->drawRecordingMark(*lastFrame_.recordingMark);
    if (session_->takeScreenshotRequest()) writeScreenshot(drawn);
    sdl_->setTitle(lastFrame_.title);
    sdl_->present();
    stats_.lastDrawMs = msSince(t0);
    stats_.drawMs = 0.95 * stats_.drawMs + 0.05 * stats_.lastDrawMs;
}

void App::logControls() {
    if (gui_->shownTooltip() != loggedTooltip_) {
        loggedTooltip_ = gui_->shownTooltip();
        logLine("[I] Tooltip " + (loggedTooltip_.empty() ? "none" : loggedTooltip_));
    }
    if (panel_.statusLines() != loggedStatus_) {
        loggedStatus_ = panel_.statusLines();
        for (const auto& [name, text] : loggedStatus_)
            logLine("[I] Control " + name + " says " + text);
    }
    const auto& items = panel_.items();
    if (samePlaces(items, loggedItems_)) return;
    loggedItems_ = items;
    char buf[160];
    const float scale = gui_->scale();  // the panel's points in window points
    for (const PanelItem& i : items) {
        std::snprintf(buf, sizeof buf, "[I] Control %s at %.0f %.0f", i.name.c_str(),
                      scale * (i.x0 + i.x1) / 2.f, scale * (i.y0 + i.y1) / 2.f);
        logLine(buf);
        // Its extent too (a finger's target is measured, tests/web/phone_test.mjs).
        std::snprintf(buf, sizeof buf, "[I] Control %s spans %.0f %.0f %.0f %.0f", i.name.c_str(),
                      scale * i.x0, scale * i.y0, scale * i.x1, scale * i.y1);
        logLine(buf);
    }
}

int App::runBenchmark() {
    while (benchmarkFrame()) {
    }
    (void)benchmarkReport();
    if (video_) {
        // Every frame went into the video (the frame waited for room in the encoder's queue):
        // the figures above are what recording sustains. The file is completed after timing.
        const VideoSettings settings = videoSettings_;
        const std::unique_ptr<VideoRecorder> recorder = std::move(video_);
        try {
            const VideoSummary v = recorder->stop();
            std::error_code ec;
            const auto bytes = std::filesystem::file_size(v.file, ec);
            std::printf("bench: video %s %dx%d, %zu frames, %zu dropped, %.1f MB: %s\n",
                        toString(settings.format), v.width, v.height, v.frames, v.dropped,
                        ec ? 0.0 : static_cast<double>(bytes) / 1e6, v.file.string().c_str());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "particle-sandbox: the video failed: %s\n", e.what());
            return 1;
        }
    }
    std::fflush(stdout);
    return 0;
}

bool App::benchmarkFrame() {
    // The normal frame, one step of the scene's dt each, no frame limiter, vsync as configured.
    const int warmup = std::min(10, options_.benchFrames / 10);
    if (benchFrame_ >= warmup + options_.benchFrames || !session_->running()) return false;
    if (benchFrame_ == 0) {
        if (session_->paused()) apply(cmd::TogglePause{});
        (void)session_->takeNotices();
    }
    if (benchFrame_ == warmup) benchMeasured_ = std::chrono::steady_clock::now();
    SDL_Event e;
    while (SDL_PollEvent(&e) != 0)
        processEvent(e);
    // The budget is the frame's: a benchmark frame never drops its one step.
    session_->update(session_->meta().dt / session_->timeScale(), now(), 1e9);
    stats_.lastStepMs = session_->lastStepMs();
    render();
    if (benchFrame_ >= warmup) {
        benchStepMs_ += stats_.lastStepMs;
        benchDrawMs_ += stats_.lastDrawMs;
    }
    ++benchFrame_;
    return true;
}

std::string App::benchmarkReport() {
    const double n = options_.benchFrames;
    const double step = benchStepMs_, draw = benchDrawMs_;
    const std::string overlays = session_->overlayFlags();
    const SDL_Point out = sdl_->outputSize();
    char line[320];
    std::snprintf(
        line, sizeof line,
        "bench: %zu particles, %d frames, %dx%d, renderer %s: step %.3f ms, draw %.3f ms, "
        "frame %.3f ms (%.1f fps)%s",
        world().size(), options_.benchFrames, out.x, out.y, sdl_->rendererName().c_str(), step / n,
        draw / n, (step + draw) / n, 1000.0 * n / (step + draw),
        overlays.empty() ? "" : (", overlays " + overlays).c_str());
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - benchMeasured_).count();
    char wallLine[120];
    std::snprintf(wallLine, sizeof wallLine, "bench: wall clock %.3f ms a frame (%.1f fps)",
                  1000.0 * wall / n, n / wall);
    logLine(line);
    logLine(wallLine);
    return std::string(line) + "; " + (wallLine + 7);
}

}  // namespace psb::app
