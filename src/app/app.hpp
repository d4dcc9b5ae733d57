#pragma once
// The interactive sandbox: a window, a world, and a loop of three verbs.
//
//   while running:
//     handleEvents()   SDL events -> commands on the camera, the interaction, the toggles
//     update(dt_real)  fixed-step simulation driven by an accumulator (scaled by the time
//                      speed), the held particle placed at the hand before every step
//     render()         a const view of the world, the HUD and the overlays, then present
//
// The world advances in steps of its solver's dt whatever the frame rate; when a frame is so
// slow that catching up would take longer than the frame itself, the backlog is dropped (the
// simulation slows down instead of spiralling). While paused the loop sleeps in
// SDL_WaitEventTimeout, so an idle paused window costs no CPU, and still redraws after every
// event so panning, zooming and spawning show.
//
// No globals: everything the loop touches is a member.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/launch.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "accuracy.hpp"
#include "analysis_overlays.hpp"
#include "camera.hpp"
#include "edit_prompt.hpp"
#include "interaction.hpp"
#include "renderer.hpp"
#include "selection.hpp"
#include "text.hpp"
#include "trails.hpp"

namespace psb::app {

/// The command line, parsed.
struct AppOptions {
    std::optional<std::filesystem::path> scene;  ///< scene file to open; the default if none
    std::filesystem::path saveTo = "particle-sandbox-save.json";  ///< where Ctrl+S writes
    std::filesystem::path screenshotDir = ".";                    ///< where F12 writes
    int width = 800;                                              ///< window, pixels
    int height = 800;
    bool vsync = true;
    bool startPaused = false;
    bool arrows = true;        ///< velocity arrows shown at start (A toggles)
    std::string renderDriver;  ///< SDL render driver name ("software", ...); SDL's choice if empty
    std::size_t benchParticles = 0;  ///< > 0: run the frame-time benchmark with this many particles
    int benchFrames = 300;
    /// Overlays the benchmark draws, by key: any of "V", "L" (all trails), "K", "D".
    std::string benchOverlays;
    std::uint32_t seed = 0;  ///< random spawns; 0 = from the clock
};

class App {
  public:
    /// Opens the window and loads the scene. Throws std::runtime_error with a message for the
    /// user when SDL, the fonts or the scene cannot be set up.
    explicit App(const AppOptions& options);
    ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    /// Runs until the window is closed or ESC; returns the process exit code.
    int run();
    /// Runs the benchmark frames (see AppOptions) and prints mean step and draw times.
    int runBenchmark();

    /// The particle the user clicked last (nullopt when none, or once it is deleted).
    [[nodiscard]] std::optional<ParticleId> selected() const { return selection_.id(); }

    // Driving the app without run()'s loop, for the tests.
    /// Handles one event as run() does.
    void processEvent(const SDL_Event& e) { handleEvent(e); }
    /// The rest of one loop iteration: update by `realSeconds` of real time, then render.
    void frame(double realSeconds);
    [[nodiscard]] const World& world() const { return world_; }
    [[nodiscard]] const Camera& camera() const { return camera_; }
    [[nodiscard]] bool running() const { return running_; }
    [[nodiscard]] bool editing() const { return prompt_.active(); }
    /// The file the last F12 wrote.
    [[nodiscard]] const std::optional<std::filesystem::path>& lastScreenshot() const {
        return lastScreenshot_;
    }

  private:
    struct Message {
        std::string text;
        double until;  ///< seconds (SDL ticks)
    };

    void handleEvents();
    void handleEvent(const SDL_Event& e);
    void handleKey(const SDL_KeyboardEvent& key);
    void update(double realSeconds);
    void render();

    void stepOnce();
    /// A click: select the particle clicked on, or clear the selection on empty space.
    void click(const ReleaseResult& r);
    /// The selected particle is gone: forget it (and close its edit prompt), saying so.
    void checkSelection();
    void openEditPrompt();
    /// A key while the edit prompt is open: nothing else sees it.
    void handleEditKey(const SDL_KeyboardEvent& key);
    void closeEditPrompt();
    /// R: the world as it was loaded, from the copy kept at load.
    void resetScene();
    void changeRestitution(int direction);
    void toggleGravity();
    /// Writes the frame being rendered (called between drawing and present).
    void writeScreenshot();
    void spawnRandom();
    void deleteHeld();
    void save();
    void setWorld(World world, std::string name);
    /// Opens `file` (the built-in scene when nullopt) and makes it current; on failure says
    /// why and keeps the world as it is.
    void openScene(const std::optional<std::filesystem::path>& file);
    void fit();
    void switchMode();
    /// The user changed the world: the kinetic energy drift is measured from here on.
    void userAction();
    void afterCameraMove();
    /// Shows `text` on screen for a few seconds and, unless `logPrefix` is null, logs it.
    void say(std::string text, const char* logPrefix = "[I] ");
    [[nodiscard]] double now() const;
    [[nodiscard]] Vec2 pointerWorld() const;
    [[nodiscard]] LaunchSettings launchSettings() const;

    // Analysis overlays (V, L, K, D).
    void toggleMomentumView();
    void cycleTrails();
    void togglePlots();
    void toggleSpeedHistogram();
    /// Feeds the time series and the trails after the frame's steps.
    void sampleAnalysis();
    /// The particle whose trail TrailMode::Selected shows: the clicked one, else the one held,
    /// else none.
    [[nodiscard]] ParticleId selectedParticle() const;
    /// The overlays that are on, for the HUD ("V L:all K D"); empty when none.
    [[nodiscard]] std::string overlayFlags() const;

    AppOptions options_;
    SDL_Window* window_ = nullptr;
    SDL_Renderer* sdlRenderer_ = nullptr;
    std::unique_ptr<Font> hudFont_;
    std::unique_ptr<Font> labelFont_;
    std::unique_ptr<Renderer> renderer_;

    World world_;
    World loadedWorld_;  ///< world_ as it was loaded, for R
    std::string sceneName_;
    std::vector<std::filesystem::path> presets_;
    std::size_t preset_ = 0;  ///< the preset P shows next
    Camera camera_;
    Interaction interaction_;
    Selection selection_;
    EditPrompt prompt_;
    SpawnSettings spawn_;
    ViewOptions view_;
    std::mt19937 rng_;

    bool running_ = true;
    bool paused_ = false;
    bool showHelp_ = false;
    bool showProfile_ = false;
    bool stepRequested_ = false;
    bool screenshotRequested_ = false;
    std::optional<std::filesystem::path> lastScreenshot_;
    bool panning_ = false;
    double timeScale_ = 1.0;
    double accumulator_ = 0.0;
    Vec2 mouse_ = Vec2::Zero();  ///< pointer, screen pixels
    std::vector<Message> messages_;
    std::string title_;

    // Frame statistics, smoothed for display.
    double fps_ = 0.0;
    int fpsFrames_ = 0;
    double fpsSeconds_ = 0.0;
    double stepMs_ = 0.0;
    double drawMs_ = 0.0;
    double lastStepMs_ = 0.0;
    double lastDrawMs_ = 0.0;
    DrawStats drawStats_;
    AccuracyMonitor accuracy_;

    /// About 68 s of frames at 60 fps for the plots and the centre of mass path.
    static constexpr std::size_t kSeriesSamples = 4096;
    TimeSeries series_{kSeriesSamples};
    std::uint64_t collisions_ = 0;  ///< since the scene opened, for series_
    /// The world's observables as update() left it, summed once a frame for the HUD, the
    /// momentum view and series_.
    ObservablesSample now_;
    Trails trails_;
    AnalysisOverlays analysis_;
};

}  // namespace psb::app
