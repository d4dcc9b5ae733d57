#include "app.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/scene.hpp>

#include "assets.hpp"
#include "benchmark_scene.hpp"
#include "hud.hpp"
#include "inspector_panel.hpp"
#include "overlay.hpp"
#include "physics_controls.hpp"
#include "scene_io.hpp"
#include "screenshot.hpp"

namespace psb::app {

namespace {

constexpr double kMinTimeScale = 1.0 / 16.0, kMaxTimeScale = 8.0;
constexpr double kPanKeyPixels = 50.0;  // the original panned by 50 / zoom world units
constexpr double kWheelZoomStep = 1.15;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void logLine(const std::string& line) {
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

std::string fmt(const char* format, double a, double b) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}

}  // namespace

App::App(const AppOptions& options)
    : options_(options),
      rng_(options.seed != 0 ? options.seed : static_cast<std::uint32_t>(std::random_device{}())) {
    // The scene first: a bad file is reported before any window opens.
    if (options_.benchParticles > 0) {
        world_ = benchmarkWorld(options_.benchParticles);
        sceneName_ = "benchmark";
    } else {
        const Scene scene = psb::app::openScene(options_.scene);
        world_ = makeWorld(scene);
        sceneName_ =
            scene.name.empty() && options_.scene ? options_.scene->stem().string() : scene.name;
    }
    loadedWorld_ = world_;
    presets_ = presetScenes();
    const std::filesystem::path font = findAsset("fonts/DejaVuSansMono.ttf");  // before a window
    view_.arrowSeconds = arrowSecondsFor(world_);
    spawn_.lengthScale = std::min(world_.def().width, world_.def().height) / 700.0;
    paused_ = options_.startPaused;
    view_.arrows = options_.arrows;
    for (const char c : options_.benchOverlays) {
        view_.momentum = view_.momentum || c == 'V';
        view_.plots = view_.plots || c == 'K';
        view_.speeds = view_.speeds || c == 'D';
        if (c == 'L') view_.trails = TrailMode::All;
    }

    if (!options_.renderDriver.empty()) {
        SDL_SetHint(SDL_HINT_RENDER_DRIVER, options_.renderDriver.c_str());
        // By default SDL shows a software renderer's frames through an OpenGL texture; on a
        // machine without a GPU (Xvfb, llvmpipe) that upload costs more than the drawing.
        // The environment variable still wins (SDL_HINT_DEFAULT priority).
        if (options_.renderDriver == "software") {
            SDL_SetHintWithPriority(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0", SDL_HINT_DEFAULT);
        }
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        throw std::runtime_error(std::string("cannot start SDL video: ") + SDL_GetError());
    }
    // SDL starts with text input on; it is wanted only while the edit prompt is open.
    SDL_StopTextInput();
    window_ = SDL_CreateWindow("Particle Sandbox", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               options_.width, options_.height, SDL_WINDOW_RESIZABLE);
    if (window_ == nullptr) {
        const std::string why = SDL_GetError();
        SDL_Quit();
        throw std::runtime_error("cannot open a window: " + why);
    }
    const Uint32 flags = options_.vsync ? SDL_RENDERER_PRESENTVSYNC : 0;
    sdlRenderer_ = SDL_CreateRenderer(window_, -1, flags);
    if (sdlRenderer_ == nullptr) {
        const std::string why = SDL_GetError();
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw std::runtime_error("cannot create a renderer: " + why);
    }
    try {
        hudFont_ = std::make_unique<Font>(sdlRenderer_, font, 14);
        labelFont_ = std::make_unique<Font>(sdlRenderer_, font, 12);
        renderer_ = std::make_unique<Renderer>(sdlRenderer_, labelFont_.get());
    } catch (...) {
        hudFont_.reset();
        labelFont_.reset();
        SDL_DestroyRenderer(sdlRenderer_);
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw;
    }
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(sdlRenderer_, &w, &h);
    camera_.setViewport(w, h);

    fit();
    userAction();
}

App::~App() {
    renderer_.reset();
    labelFont_.reset();
    hudFont_.reset();
    SDL_DestroyRenderer(sdlRenderer_);
    SDL_DestroyWindow(window_);
    SDL_Quit();
}

double App::now() const {
    return static_cast<double>(SDL_GetTicks64()) / 1000.0;
}

Vec2 App::pointerWorld() const {
    return camera_.screenToWorld(mouse_);
}

LaunchSettings App::launchSettings() const {
    LaunchSettings s;
    s.window = 0.1;
    // A hand that moved less than 4 pixels in the last 100 ms was holding still.
    s.minDistance = camera_.toWorld(4.0);
    // A flick faster than two box sizes per second is a slip of the hand, and would tunnel
    // through particles in one step.
    s.maxSpeed = 2.0 * std::max(world_.def().width, world_.def().height);
    return s;
}

void App::setWorld(World world, std::string name) {
    interaction_.reset();
    selection_.clear();
    closeEditPrompt();
    loadedWorld_ = world;
    world_ = std::move(world);
    sceneName_ = std::move(name);
    view_.arrowSeconds = arrowSecondsFor(world_);
    spawn_.lengthScale = std::min(world_.def().width, world_.def().height) / 700.0;
    accumulator_ = 0.0;
    series_.clear();
    collisions_ = 0;
    trails_.reset();
    fit();
    userAction();
}

void App::openScene(const std::optional<std::filesystem::path>& file) {
    try {
        const Scene scene = psb::app::openScene(file);
        std::string name = scene.name.empty() && file ? file->stem().string() : scene.name;
        setWorld(makeWorld(scene), name);
        say("Opened " + (file ? file->filename().string() : std::string("the built-in scene")) +
            ": " + name + " (" + std::to_string(world_.size()) + " particles)");
    } catch (const std::exception& e) {  // SceneError, or a scene the world refuses
        say(std::string("Cannot open scene: ") + e.what(), "[E] ");
    }
}

void App::fit() {
    // Keep the HUD's lines clear of the box.
    const double hudHeight =
        static_cast<double>(hudLines(HudData{}).size()) * hudFont_->lineHeight() + 10.0;
    camera_.fit(world_.def().width, world_.def().height, 10.0, hudHeight);
    const Vec2 topLeft = camera_.worldToScreen(Vec2::Zero());
    char buf[160];
    std::snprintf(buf, sizeof buf, "[I] View: zoom %.6f px/m, box top-left at [%.2f, %.2f] px",
                  camera_.zoom(), topLeft.x(), topLeft.y());
    logLine(buf);
}

void App::userAction() {
    accuracy_.resetReference(kineticEnergy(world_));
}

void App::switchMode() {
    const ModeSwitch r = switchToNextMode(world_);
    // A refusal is shown and logged; the world keeps stepping in its mode.
    say(r.message, r.changed ? "[I] " : "[W] ");
    if (!r.detail.empty()) logLine("[W] " + r.detail);
    if (r.changed) {
        accumulator_ = 0.0;
        userAction();
    }
}

void App::say(std::string text, const char* logPrefix) {
    if (logPrefix != nullptr) logLine(logPrefix + text);
    messages_.push_back({std::move(text), now() + 3.0});
    if (messages_.size() > 4) messages_.erase(messages_.begin());
}

void App::afterCameraMove() {
    // The hand did not move but the world under it did: the held particle follows the cursor.
    if (interaction_.mode() != Interaction::Mode::Idle) interaction_.moveTo(pointerWorld(), now());
}

int App::run() {
    logLine("[I] Particle Sandbox: " + std::to_string(world_.size()) +
            " particles. Press H for help.");
    for (const auto& [keys, what] : controls())
        logLine("    " + keys + ": " + what);
    SDL_DisplayMode mode;
    const double refresh = SDL_GetCurrentDisplayMode(0, &mode) == 0 && mode.refresh_rate > 0
                               ? mode.refresh_rate
                               : 60.0;
    auto last = std::chrono::steady_clock::now();
    while (running_) {
        const auto frameStart = std::chrono::steady_clock::now();
        const double real = std::chrono::duration<double>(frameStart - last).count();
        last = frameStart;
        ++fpsFrames_;
        fpsSeconds_ += real;
        if (fpsSeconds_ >= 0.5) {
            fps_ = fpsFrames_ / fpsSeconds_;
            fpsFrames_ = 0;
            fpsSeconds_ = 0.0;
        }
        handleEvents();
        update(std::min(real, 0.25));
        render();
        // Where vsync is not honoured (a virtual display), do not spin faster than the display.
        const double spent =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
        const double budget = 1.0 / refresh;
        if (spent < budget - 0.001) SDL_Delay(static_cast<Uint32>((budget - spent) * 1000.0));
    }
    logLine("[I] Exiting.");
    return 0;
}

void App::handleEvents() {
    SDL_Event e;
    // Paused and idle: sleep until something happens (or a quarter second, for the HUD).
    if (paused_ && !stepRequested_ && interaction_.mode() == Interaction::Mode::Idle) {
        if (SDL_WaitEventTimeout(&e, 250) != 0) handleEvent(e);
    }
    while (SDL_PollEvent(&e) != 0)
        handleEvent(e);
}

void App::handleEvent(const SDL_Event& e) {
    switch (e.type) {
        case SDL_QUIT:
            running_ = false;
            break;
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                int w = 0, h = 0;
                SDL_GetRendererOutputSize(sdlRenderer_, &w, &h);
                camera_.setViewport(w, h);
            }
            break;
        case SDL_KEYDOWN:
            handleKey(e.key);
            break;
        case SDL_TEXTINPUT:
            if (prompt_.active()) prompt_.type(e.text.text);
            break;
        case SDL_MOUSEBUTTONDOWN:
            mouse_ = Vec2(e.button.x, e.button.y);
            if (e.button.button == SDL_BUTTON_LEFT) {
                interaction_.press(world_, pointerWorld(), e.button.timestamp / 1000.0);
                if (interaction_.mode() == Interaction::Mode::Holding) {
                    const Particle p = world_.get(interaction_.held());
                    logLine(fmt("[I] Grabbed particle at [%.2f, %.2f]", p.position.x(),
                                p.position.y()));
                    userAction();
                }
            } else if (e.button.button == SDL_BUTTON_RIGHT ||
                       e.button.button == SDL_BUTTON_MIDDLE) {
                panning_ = true;
            }
            break;
        case SDL_MOUSEMOTION: {
            const Vec2 m(e.motion.x, e.motion.y);
            if (panning_) camera_.panPixels(m - mouse_);
            mouse_ = m;
            interaction_.moveTo(pointerWorld(), e.motion.timestamp / 1000.0);
            break;
        }
        case SDL_MOUSEBUTTONUP:
            mouse_ = Vec2(e.button.x, e.button.y);
            if (e.button.button == SDL_BUTTON_LEFT) {
                const ReleaseResult r = interaction_.release(
                    world_, pointerWorld(), e.button.timestamp / 1000.0, spawn_, launchSettings());
                using K = ReleaseResult::Kind;
                const std::string at = fmt("at [%.2f, %.2f]", r.position.x(), r.position.y());
                const std::string v =
                    fmt("with velocity [%.2f, %.2f] m/s", r.velocity.x(), r.velocity.y());
                if (r.kind == K::Flung) logLine("[I] Released particle " + at + " " + v);
                if (r.kind == K::Launched) logLine("[I] Launched particle " + at + " " + v);
                if (r.kind == K::Refused) say(r.message);
                if (r.kind == K::Clicked) click(r);
                if (r.kind == K::Flung || r.kind == K::Launched) userAction();
            } else if (e.button.button == SDL_BUTTON_RIGHT ||
                       e.button.button == SDL_BUTTON_MIDDLE) {
                panning_ = false;
            }
            break;
        case SDL_MOUSEWHEEL: {
            const float notches = e.wheel.preciseY;
            if (notches != 0.0f) {
                int x = 0, y = 0;
                SDL_GetMouseState(&x, &y);
                mouse_ = Vec2(x, y);
                camera_.zoomAbout(mouse_, std::pow(kWheelZoomStep, notches));
                char buf[96];
                std::snprintf(buf, sizeof buf, "[I] Zoom %.4f px/m about [%d, %d]", camera_.zoom(),
                              x, y);
                logLine(buf);
                afterCameraMove();
            }
            break;
        }
        default:
            break;
    }
}

void App::handleKey(const SDL_KeyboardEvent& key) {
    if (prompt_.active()) {
        handleEditKey(key);
        return;
    }
    const bool ctrl = (key.keysym.mod & KMOD_CTRL) != 0;
    const bool shift = (key.keysym.mod & KMOD_SHIFT) != 0;
    const SDL_Keycode sym = key.keysym.sym;
    // A held key repeats only where repeating makes sense (pan, single step, spawn mass); a
    // held Space or S must not flicker.
    const bool repeatable = sym == SDLK_LEFT || sym == SDLK_RIGHT || sym == SDLK_UP ||
                            sym == SDLK_DOWN || sym == SDLK_n || sym == SDLK_LEFTBRACKET ||
                            sym == SDLK_RIGHTBRACKET;
    if (key.repeat != 0 && !repeatable) return;
    switch (sym) {
        case SDLK_ESCAPE:
            running_ = false;
            break;
        case SDLK_BACKSPACE:
        case SDLK_DELETE:
            deleteHeld();
            break;
        case SDLK_s:
            if (ctrl) {
                save();
            } else {
                view_.labels = !view_.labels;
                say(view_.labels ? "Labels on" : "Labels off");
            }
            break;
        case SDLK_a:
            view_.arrows = !view_.arrows;
            say(view_.arrows ? "Arrows on" : "Arrows off");
            break;
        case SDLK_m:
            spawnRandom();
            break;
        case SDLK_h:
            showHelp_ = !showHelp_;
            break;
        case SDLK_v:
            toggleMomentumView();
            break;
        case SDLK_l:
            cycleTrails();
            break;
        case SDLK_k:
            togglePlots();
            break;
        case SDLK_d:
            toggleSpeedHistogram();
            break;
        case SDLK_t:
            switchMode();
            break;
        case SDLK_o:
        case SDLK_F3:
            showProfile_ = !showProfile_;
            say(showProfile_ ? "Profile on" : "Profile off");
            break;
        case SDLK_f:
            fit();
            afterCameraMove();
            break;
        case SDLK_SPACE:
            paused_ = !paused_;
            accumulator_ = 0.0;
            say(paused_ ? "Paused" : "Resumed");
            break;
        case SDLK_n:
            if (paused_) stepRequested_ = true;
            break;
        case SDLK_COMMA:
        case SDLK_PERIOD: {
            const double f = key.keysym.sym == SDLK_COMMA ? 0.5 : 2.0;
            timeScale_ = std::clamp(timeScale_ * f, kMinTimeScale, kMaxTimeScale);
            char buf[64];
            std::snprintf(buf, sizeof buf, "Time speed x%g", timeScale_);
            say(buf);
            break;
        }
        case SDLK_r:
            resetScene();
            break;
        case SDLK_e:
            changeRestitution(shift ? +1 : -1);
            break;
        case SDLK_g:
            toggleGravity();
            break;
        case SDLK_F12:
            screenshotRequested_ = true;
            break;
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
            openEditPrompt();
            break;
        case SDLK_p:
            if (presets_.empty()) {
                say("No preset scenes found (assets/scenes)");
            } else {
                openScene(presets_[preset_ % presets_.size()]);
                preset_ = (preset_ + 1) % presets_.size();
            }
            break;
        case SDLK_1:
        case SDLK_2:
        case SDLK_3:
        case SDLK_4:
        case SDLK_5:
        case SDLK_6:
        case SDLK_7:
        case SDLK_8:
        case SDLK_9: {
            const auto k = static_cast<std::size_t>(key.keysym.sym - SDLK_1);
            if (k < presets_.size()) {
                openScene(presets_[k]);
                preset_ = (k + 1) % presets_.size();
            } else {
                say("No preset " + std::to_string(k + 1) + " (there are " +
                    std::to_string(presets_.size()) + ")");
            }
            break;
        }
        case SDLK_LEFTBRACKET:
        case SDLK_RIGHTBRACKET: {
            spawn_.changeMass(key.keysym.sym == SDLK_LEFTBRACKET ? -1.0 : 1.0);
            say(fmt("New particles: %.0f kg, radius %.3g m", spawn_.mass, spawn_.radius()),
                nullptr);
            break;
        }
        case SDLK_LEFT:
        case SDLK_RIGHT:
        case SDLK_UP:
        case SDLK_DOWN: {
            // The view moves the way the arrow points (the world slides the other way).
            const SDL_Keycode k = key.keysym.sym;
            const Vec2 d(k == SDLK_LEFT    ? kPanKeyPixels
                         : k == SDLK_RIGHT ? -kPanKeyPixels
                                           : 0.0,
                         k == SDLK_UP     ? kPanKeyPixels
                         : k == SDLK_DOWN ? -kPanKeyPixels
                                          : 0.0);
            camera_.panPixels(d);
            afterCameraMove();
            break;
        }
        default:
            break;
    }
}

void App::deleteHeld() {
    if (const auto p = interaction_.deleteHeld(world_)) {
        logLine(deletionLogLine(*p));
        say("Deleted a particle", nullptr);
        userAction();
        checkSelection();
    }
}

void App::click(const ReleaseResult& r) {
    if (!r.id.isNull()) {
        if (prompt_.target() != r.id) closeEditPrompt();
        selection_.select(r.id);
        logLine(selectionLogLine(world_.get(r.id)));
    } else if (selection_.id()) {
        selection_.clear();
        closeEditPrompt();
        say("Selection cleared");
    }
}

void App::checkSelection() {
    if (selection_.forgetIfGone(world_)) {
        closeEditPrompt();
        say("Selection cleared: the particle was deleted");
    }
}

void App::openEditPrompt() {
    const auto id = selection_.id();
    if (!id) {
        say("Click a particle to select it, then Enter edits it");
        return;
    }
    prompt_.open(world_.get(*id));
    SDL_StartTextInput();
    logLine("[I] Editing particle " + std::to_string(id->slot));
}

void App::closeEditPrompt() {
    if (!prompt_.active()) return;
    prompt_.close();
    SDL_StopTextInput();
}

void App::handleEditKey(const SDL_KeyboardEvent& key) {
    // Characters arrive as SDL_TEXTINPUT; here only the keys that steer the prompt, and F12,
    // which types nothing and may well be wanted for a picture of the prompt.
    switch (key.keysym.sym) {
        case SDLK_F12:
            screenshotRequested_ = true;
            break;
        case SDLK_ESCAPE:
            closeEditPrompt();
            say("Edit cancelled");
            break;
        case SDLK_TAB:
            if ((key.keysym.mod & KMOD_SHIFT) != 0) {
                prompt_.previousField();
            } else {
                prompt_.nextField();
            }
            break;
        case SDLK_BACKSPACE:
            prompt_.backspace();
            break;
        case SDLK_RETURN:
        case SDLK_KP_ENTER: {
            if (key.repeat != 0) break;
            const EditResult r = applyEdit(world_, prompt_.target(), prompt_.texts());
            if (r.applied) {
                closeEditPrompt();
                say(r.message);
                userAction();
            } else {
                // The prompt stays open with its text, so the value can be corrected.
                prompt_.setError(r.message);
                say("Edit refused: " + r.message, "[W] ");
            }
            break;
        }
        default:
            break;
    }
}

void App::resetScene() {
    World loaded = loadedWorld_;
    setWorld(std::move(loaded), sceneName_);
    say("Reset to the scene as loaded: " + std::to_string(world_.size()) + " particles");
}

void App::changeRestitution(int direction) {
    const ControlChange c = stepRestitution(world_, direction);
    say(c.message);
    if (c.changed) userAction();
}

void App::toggleGravity() {
    const ControlChange c = psb::app::toggleGravity(world_, loadedWorld_.def().gravity);
    say(c.message, c.changed ? "[I] " : "[W] ");
    if (c.changed) userAction();
}

void App::writeScreenshot() {
    screenshotRequested_ = false;
    try {
        lastScreenshot_ = saveScreenshot(sdlRenderer_, options_.screenshotDir);
        say("Saved screenshot " + lastScreenshot_->string());
    } catch (const std::exception& e) {  // SaveError, or the pixels could not be read
        say(std::string("Screenshot failed: ") + e.what(), "[E] ");
    }
}

void App::frame(double realSeconds) {
    update(realSeconds);
    render();
}

void App::spawnRandom() {
    const WorldDef& d = world_.def();
    // The original: mass a random integer 3..20 kg, radius 2.5 m per kg, somewhere in the upper
    // part of the box, colour channels 100..255. Its velocity components were random integers
    // -5..5 pixels per frame at 60 frames per second, i.e. up to 300 m/s in its 700 m box; here
    // they are uniform in -300..300 m/s. Lengths and speeds scale with the box for other boxes.
    std::uniform_int_distribution<int> massDist(3, 20), channel(100, 255);
    const double mass = massDist(rng_), radius = 2.5 * mass * spawn_.lengthScale;
    std::uniform_real_distribution<double> x(radius, std::max(radius, d.width - radius));
    std::uniform_real_distribution<double> y(radius, std::max(radius, d.height / 2.0));
    const double vmax = 300.0 * spawn_.lengthScale;
    std::uniform_real_distribution<double> v(-vmax, vmax);
    const Vec2 want(x(rng_), y(rng_));
    const auto spot = findFreeSpot(world_, want, radius);
    if (!spot) {
        say("No room for a new particle");
        return;
    }
    ParticleDef def;
    def.position = *spot;
    def.velocity = {v(rng_), v(rng_)};
    def.mass = mass;
    def.radius = radius;
    def.color = {static_cast<std::uint8_t>(channel(rng_)), static_cast<std::uint8_t>(channel(rng_)),
                 static_cast<std::uint8_t>(channel(rng_))};
    world_.add(def);
    userAction();
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "[I] Spawned particle at [%.2f, %.2f] with velocity [%.2f, %.2f] m/s and mass "
                  "%.0f kg",
                  spot->x(), spot->y(), def.velocity.x(), def.velocity.y(), mass);
    logLine(buf);
}

void App::save() {
    try {
        say(saveWorld(world_, sceneName_, options_.saveTo));
    } catch (const std::exception& e) {  // SaveError; the old file is intact
        say(std::string("Save failed: ") + e.what(), "[E] ");
    }
}

void App::stepOnce() {
    interaction_.applyHold(world_, now(), launchSettings());
    world_.step(world_.solver().dt);
}

void App::update(double realSeconds) {
    const auto t0 = std::chrono::steady_clock::now();
    const double dt = world_.solver().dt;
    accuracy_.beginSteps(world_);
    if (!paused_) {
        accumulator_ += realSeconds * timeScale_;
        while (accumulator_ >= dt) {
            stepOnce();
            accumulator_ -= dt;
            // Catching up must not take longer than a frame, or each frame would fall further
            // behind: drop the backlog and let the simulation run slower than real time.
            if (msSince(t0) > 30.0) {
                accumulator_ = 0.0;
                break;
            }
        }
    } else if (stepRequested_) {
        stepOnce();
    }
    stepRequested_ = false;
    accuracy_.endSteps(world_);
    // Arrows shorten when the motion speeds up (a bullet scattering a crowd) but never grow
    // back on their own, so their lengths stay comparable over time; opening a scene resets it.
    view_.arrowSeconds = std::min(view_.arrowSeconds, arrowSecondsFor(world_));
    // Show the held particle exactly at the hand, paused or not.
    interaction_.applyHold(world_, now(), launchSettings());
    checkSelection();
    sampleAnalysis();
    lastStepMs_ = msSince(t0);
    stepMs_ = 0.95 * stepMs_ + 0.05 * lastStepMs_;
}

void App::toggleMomentumView() {
    view_.momentum = !view_.momentum;
    say(view_.momentum ? "Momentum view on" : "Momentum view off");
}

void App::cycleTrails() {
    view_.trails = nextTrailMode(view_.trails);
    if (view_.trails == TrailMode::Off) trails_.reset();
    say(std::string("Trails: ") + toString(view_.trails));
}

void App::togglePlots() {
    view_.plots = !view_.plots;
    say(view_.plots ? "Plots on" : "Plots off");
}

void App::toggleSpeedHistogram() {
    view_.speeds = !view_.speeds;
    say(view_.speeds ? "Speed distribution on" : "Speed distribution off");
}

ParticleId App::selectedParticle() const {
    // The clicked particle; while none is selected, the one in the hand.
    if (const auto id = selection_.id(); id && world_.contains(*id)) return *id;
    return interaction_.mode() == Interaction::Mode::Holding ? interaction_.held() : kNullParticle;
}

std::string App::overlayFlags() const {
    std::string f;
    const auto add = [&f](const std::string& s) { f += (f.empty() ? "" : " ") + s; };
    if (view_.momentum) add("V");
    if (view_.trails != TrailMode::Off) add(std::string("L:") + toString(view_.trails));
    if (view_.plots) add("K");
    if (view_.speeds) add("D");
    return f;
}

void App::sampleAnalysis() {
    // Always recorded (three compensated sums over the particles), so the plots and the centre
    // of mass path have a history the moment they are switched on.
    // The accuracy monitor clears the world's counters before each frame's steps, so they hold
    // this frame's collisions; the series wants a running total.
    collisions_ += world_.counters().collisions;
    now_ = sampleObservables(world_);
    now_.collisions = collisions_;
    series_.record(now_);
    if (view_.trails != TrailMode::Off) trails_.update(world_);
}

void App::render() {
    const auto t0 = std::chrono::steady_clock::now();
    drawStats_ = renderer_->draw(world_, camera_, view_, &trails_, selectedParticle());
    std::optional<Particle> selected;
    if (const auto id = selection_.id(); id && world_.contains(*id)) selected = world_.get(*id);
    if (selected) drawSelectionOutline(sdlRenderer_, camera_, *selected);

    HudData hud;
    hud.fps = fps_;
    hud.simTime = world_.time();
    hud.timeScale = timeScale_;
    hud.particles = world_.size();
    hud.kineticEnergy = now_.kineticEnergy;
    hud.momentum = now_.momentum;
    hud.spawnMass = spawn_.mass;
    hud.spawnRadius = spawn_.radius();
    hud.arrowSeconds = view_.arrows ? view_.arrowSeconds : 0.0;
    hud.paused = paused_;
    hud.stepMs = stepMs_;
    hud.drawMs = drawMs_;
    hud.mode = modeName(world_.solver());
    hud.overlays = overlayFlags();
    // The exact mode finds its events through its own cell lists, not the broadphase.
    hud.broadphase = world_.solver().mode == StepMode::Exact
                         ? std::string("event cells")
                         : std::string(toString(world_.broadPhaseInUse()));
    hud.threads = world_.threads();
    hud.maxOverlap = accuracy_.overlap();
    hud.keDrift = accuracy_.drift(hud.kineticEnergy);
    hud.restitution = world_.def().restitution;
    hud.gravity = gravityText(world_.def().gravity);

    Overlays o;
    o.hud = hudLines(hud);
    if (drawStats_.labelsSuppressed) o.hud.emplace_back("Labels hidden: too many on screen");
    o.showHelp = showHelp_;
    if (showHelp_) o.help = helpLines();
    o.showProfile = showProfile_;
    if (showProfile_) {
        ProfileData pd;
        pd.profile = world_.profile();
        pd.mode = world_.solver().mode;
        pd.eventsPerStep = accuracy_.eventsPerStep();
        pd.frameStepMs = lastStepMs_;
        pd.frameDrawMs = lastDrawMs_;
        o.profile = profileLines(pd);
    }
    const double t = now();
    std::erase_if(messages_, [t](const Message& m) { return m.until < t; });
    for (const auto& m : messages_)
        o.messages.push_back(m.text);
    if (selected) o.inspector = inspectorLines(*selected, prompt_);
    LayoutRequest req;
    req.width = camera_.viewportWidth();
    req.height = camera_.viewportHeight();
    req.hud = textBoxSize(*hudFont_, o.hud);
    if (showProfile_) req.profile = textBoxSize(*hudFont_, o.profile);
    if (view_.momentum)
        req.legend = textBoxSize(*labelFont_, momentumLegend(world_, now_, view_.arrowSeconds));
    req.messages = textBoxSize(*hudFont_, o.messages);
    req.inspector = textBoxSize(*hudFont_, o.inspector);
    req.plots = view_.plots;
    req.speeds = view_.speeds;
    const PanelLayout layout = layoutPanels(req);
    analysis_.draw(sdlRenderer_, *labelFont_, world_, now_, camera_, series_, view_, layout);
    // A launch in progress: a ghost disc at the press point and a line to the pointer.
    if (interaction_.mode() == Interaction::Mode::Launching) {
        const Vec2 a = camera_.worldToScreen(interaction_.pressPoint());
        const Vec2 b = camera_.worldToScreen(interaction_.pointer());
        SDL_SetRenderDrawColor(sdlRenderer_, 200, 200, 200, 255);
        SDL_RenderDrawLineF(sdlRenderer_, static_cast<float>(a.x()), static_cast<float>(a.y()),
                            static_cast<float>(b.x()), static_cast<float>(b.y()));
        renderer_->drawGhost(camera_, interaction_.pressPoint(), spawn_.radius());
    }

    drawOverlays(sdlRenderer_, *hudFont_, o, layout);
    if (screenshotRequested_) writeScreenshot();

    const std::string title = windowTitle(world_.size(), paused_, sceneName_);
    if (title != title_) {
        SDL_SetWindowTitle(window_, title.c_str());
        title_ = title;
    }
    SDL_RenderPresent(sdlRenderer_);
    lastDrawMs_ = msSince(t0);
    drawMs_ = 0.95 * drawMs_ + 0.05 * lastDrawMs_;
}

int App::runBenchmark() {
    // One fixed step and one frame per iteration, no frame limiter, vsync as configured.
    SDL_RendererInfo info{};
    SDL_GetRendererInfo(sdlRenderer_, &info);
    double step = 0.0, draw = 0.0;
    const int warmup = std::min(10, options_.benchFrames / 10);
    for (int f = 0; f < warmup + options_.benchFrames && running_; ++f) {
        SDL_Event e;
        while (SDL_PollEvent(&e) != 0)
            handleEvent(e);
        const auto t0 = std::chrono::steady_clock::now();
        world_.resetCounters();  // as a frame of update() does (see sampleAnalysis)
        world_.step(world_.solver().dt);
        sampleAnalysis();
        const double s = msSince(t0);
        render();
        if (f >= warmup) {
            step += s;
            draw += lastDrawMs_;
        }
    }
    const double n = options_.benchFrames;
    std::printf(
        "bench: %zu particles, %d frames, %dx%d, renderer %s: step %.3f ms, draw %.3f ms, "
        "frame %.3f ms (%.1f fps)%s\n",
        world_.size(), options_.benchFrames, camera_.viewportWidth(), camera_.viewportHeight(),
        info.name != nullptr ? info.name : "?", step / n, draw / n, (step + draw) / n,
        1000.0 * n / (step + draw),
        overlayFlags().empty() ? "" : (", overlays " + overlayFlags()).c_str());
    std::fflush(stdout);
    return 0;
}

}  // namespace psb::app
