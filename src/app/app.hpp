#pragma once
// The interactive sandbox: a window over a session, and a loop of three verbs.
//
//   while running:
//     handleEvents()   SDL events -> Commands (platform/) -> Session::apply, the one place
//                      where anything changes
//     update(dt_real)  Session::update: fixed steps of the scene's dt driven by an accumulator
//                      (scaled by the time speed), the held particle placed at the hand first
//     render()         the control panel (gui/, Dear ImGui) reads the session and
//                      returns Commands, applied like the keys'; view/buildFrame(): a read-only
//                      FrameView of the session; render/DrawLayer::draw() draws it (the only code
//                      calling SDL's drawing functions), then GuiContext draws the panel; present
//
//   App ──owns──> SdlContext (window, renderer, fonts; RAII)
//    │            GuiContext + ControlPanel (the on-screen controls: events to ImGui first,
//    │                     the rest to Input)
//    │            Session (world, scene as loaded, presets, camera, view toggles, hand,
//    │                     selection, edit prompt, spawn rules, clock; no SDL)
//    │            DrawLayer (Renderer, trails, analysis panels, text panels)
//    └ Input: SDL_Event -> Command
//
// Session knows no SDL and is tested without a window; a command is the only way to change it,
// whether it comes from a key, the mouse or a test. World and screen coordinates meet only in the
// session's Camera. --bench runs this same frame (one step of the scene's dt per frame) and
// prints what it cost.
//
// The world advances in steps of the scene's dt whatever the frame rate; when a frame is so
// slow that catching up would take longer than the frame itself, the backlog is dropped (the
// simulation slows down instead of spiralling, and the HUD shows the speed reached). While
// paused the loop sleeps in SDL_WaitEventTimeout, so an idle paused window costs no CPU, and
// still redraws after every event so panning, zooming and spawning show.
//
// No globals: everything the loop touches is a member.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <SDL.h>

#include "gui/control_panel.hpp"
#include "gui/gui_context.hpp"
#include "platform/input.hpp"
#include "platform/sdl_context.hpp"
#include "platform/settings_store.hpp"
#include "platform/video_recorder.hpp"
#include "render/draw_layer.hpp"
#include "session/session.hpp"
#include "view/frame_view.hpp"

namespace psb::app {

/// The command line, parsed.
struct AppOptions {
    std::optional<std::filesystem::path> scene;  ///< scene file to open; the default if none
    /// What Save As proposes (--save-to); none: a name after the scene's in screenshotDir.
    std::optional<std::filesystem::path> saveTo;
    std::filesystem::path screenshotDir = ".";  ///< where F12 writes, and Save As proposes
    int width = 800;                            ///< window, pixels
    int height = 800;
    bool vsync = true;
    bool startPaused = false;
    bool arrows = true;  ///< velocity arrows shown at start (A toggles)
    /// The app runs in a web page (SessionOptions::inPage): Esc does not quit, files are
    /// downloads, the help lists the page's keys.
    bool inPage = false;
    /// A touch screen is the user's hands (SessionOptions::touch); a finger seen turns it on.
    bool touch = false;
    std::string renderDriver;        ///< SDL render driver name ("software", ...); chosen if empty
    std::size_t benchParticles = 0;  ///< > 0: run the frame-time benchmark with this many particles
    int benchFrames = 300;
    /// Overlays and instruments the benchmark draws, by key: any of "V", "L" (all trails), "K",
    /// "D", "I", "J", "Q", "G", "U", and "R" (every particle turning, so that each draws its
    /// spin mark).
    std::string benchOverlays;
    std::uint32_t seed = 0;  ///< random spawns; 0 = from the clock
    /// Record a video from the start (--record); with --bench, every frame, waiting for the
    /// encoder rather than leaving frames out, so that the figure is what recording sustains.
    std::optional<VideoFormat> record;
    /// Log "[I] Control NAME at X Y" (window points, the control's centre) for every control of
    /// the panel whenever their places change, for scripts that drive the window.
    bool logControls = false;
    /// The settings file to read at start and keep the settings in (settings_store.hpp); none:
    /// neither read nor written (--no-settings, --bench, the tests).
    std::optional<std::filesystem::path> settingsFile;
};

class App {
  public:
    /// Opens the window and loads the scene. Throws std::runtime_error with a message for the
    /// user when SDL, the fonts or the scene cannot be set up.
    explicit App(const AppOptions& options);
    App(const App&) = delete;
    App& operator=(const App&) = delete;
    /// Completes a video still recording.
    ~App();

    /// Runs until the session stops running (Esc, the window closed); returns the exit code.
    int run();
    /// Runs the benchmark frames (see AppOptions) and prints mean step and draw times.
    int runBenchmark();

    // The loops' parts, for a caller that owns the loop (the browser's, one pass per animation
    // frame; see browser_loop.hpp).
    /// Logs the greeting and the controls, as run() does first.
    void greet();
    /// One pass of run()'s loop: the events (while paused and idle, waiting up to a quarter
    /// second for one if `mayWait`), the update by the real time since the last pass, the render.
    void loopOnce(bool mayWait);
    /// One frame of the benchmark; false once every frame has run (or the session stopped).
    bool benchmarkFrame();
    /// Prints the benchmark's lines (after the frames: the mean step and draw times, the wall
    /// clock's time a frame) and returns them as one.
    std::string benchmarkReport();
    /// Applies `c` as a key or the panel would.
    void command(const Command& c) { apply(c); }
    /// Logs `text` as a warning and shows it as a message.
    void warn(const std::string& text);
    /// Logs `text` and shows it as a message.
    void inform(const std::string& text);

    // Driving the app without run()'s loop, for the tests.
    /// Handles one event as run() does.
    void processEvent(const SDL_Event& e);
    /// The rest of one loop iteration: update by `realSeconds` of real time, then render.
    void frame(double realSeconds);
    [[nodiscard]] const Session& session() const { return *session_; }
    [[nodiscard]] const World& world() const { return session_->world(); }
    [[nodiscard]] const Camera& camera() const { return session_->camera(); }
    [[nodiscard]] bool running() const { return session_->running(); }
    [[nodiscard]] bool editing() const { return session_->prompt().active(); }
    /// The particle the user clicked last (nullopt when none, or once it is deleted).
    [[nodiscard]] std::optional<ParticleId> selected() const { return session_->selection().id(); }
    /// The file the last F12 wrote.
    [[nodiscard]] const std::optional<std::filesystem::path>& lastScreenshot() const {
        return lastScreenshot_;
    }
    /// The messages on screen now, oldest first.
    [[nodiscard]] std::vector<std::string> messages() const;
    /// The frame the last render() drew.
    [[nodiscard]] const FrameView& lastFrame() const { return lastFrame_; }
    /// The control panel as the last render() built it.
    [[nodiscard]] const ControlPanel& panel() const { return panel_; }
    /// Whether the control panel has the keyboard (Tab gave it, Esc takes it back).
    [[nodiscard]] bool panelHasKeyboard() const { return gui_->hasKeyboard(); }
    /// The control panel, for a loop that sets its mode and takes its requests (the browser's).
    [[nodiscard]] ControlPanel& controlPanel() { return panel_; }

  private:
    struct Message {
        std::string text;
        double until;            ///< seconds (SDL ticks)
        std::string topic = {};  ///< Notice::topic
    };

    void handleEvents(bool mayWait);
    /// What `e` does to the session, the controls having left it to the sandbox.
    void act(const SDL_Event& e);
    void apply(const Command& c);
    void update(double realSeconds);
    void render();
    /// Logs and shows what the session said.
    void flushNotices();
    /// Shows `text` as the newest message.
    void show(const std::string& text);
    /// The window as NAME.png and the text it shows as NAME.txt (screen_text.hpp).
    void writeScreenshot(const DrawStats& drawn);
    /// SDL's text input on while the edit prompt or a panel field wants characters.
    void updateTextInput();
    /// Where the text being typed is (the panel's field, else its text cursor, else the edit
    /// prompt's message band), for the page's typing field (platform/text_input.hpp).
    void placeTyping();
    void logControls();
    [[nodiscard]] double now() const;
    /// Logs `text` and shows it as a message; `level` as the session's notices.
    void tell(const std::string& text, Notice::Level level = Notice::Level::Info);
    /// The window's look as the session's view asks: ImGui's colours for its theme, and for its
    /// UI scale the fonts (HUD, labels, panel) made again at their new size and the box fitted
    /// to the layout they give.
    void syncLook();
    /// The automatic UI scale for the window as it is (automaticUiScale of its height).
    [[nodiscard]] double automaticScale() const;
    /// The settings file: read at start, written when a kept setting changes.
    void loadSettings();
    void saveSettings();

    // Video (app_video.cpp): Ctrl+R starts and stops a VideoRecorder fed from render().
    void toggleVideo(const VideoSettings& settings);
    void startVideo(const VideoSettings& settings, VideoRecorder::Pacing pacing);
    /// Completes the video and says where it is; `why` (if any) says why it stopped by itself.
    void stopVideo(const std::string& why = {});
    /// After the frame is drawn, before the recording mark: the recorded area into the video.
    void captureVideo();
    /// The window's pixels a recording with `settings` takes: all of it, or right of the panel.
    [[nodiscard]] SDL_Rect videoArea(const VideoSettings& settings) const;
    void updateVideoStatus();

    AppOptions options_;
    std::unique_ptr<SdlContext> sdl_;
    std::unique_ptr<GuiContext> gui_;  ///< after sdl_: destroyed before the renderer it draws on
    ControlPanel panel_;
    std::vector<PanelItem> loggedItems_;  ///< what --log-controls last wrote
    std::vector<std::pair<std::string, std::string>> loggedStatus_;  ///< and the status lines
    std::string loggedTooltip_;         ///< the tooltip --log-controls last named
    std::vector<PanelItem> lastItems_;  ///< the panel's controls in the frame before
    bool panelSettling_ = true;         ///< they moved in the last frame
    /// The control panel's width, pixels: the view keeps it out of the box's area.
    ControlsWidth controls_;
    std::optional<Session> session_;
    std::unique_ptr<DrawLayer> draw_;
    Input input_;
    bool textInput_ = false;
    TipRect typingAt_;  ///< where placeTyping last put the typing field, window points
    std::optional<SettingsStore> settings_;
    Theme theme_ = Theme::Dark;  ///< ImGui's colours now
    double lookPoints_ = 0.0;    ///< pixels per UI point the fonts were made for (0: not yet)

    std::vector<Message> messages_;
    std::optional<std::filesystem::path> lastScreenshot_;
    FrameView lastFrame_;

    std::unique_ptr<VideoRecorder> video_;
    VideoSettings videoSettings_;  ///< the running recording's
    SDL_Rect videoArea_{};
    double videoStart_ = 0.0;  ///< now() when it started

    // Frame statistics, smoothed for display.
    FrameStats stats_;
    int fpsFrames_ = 0;
    double fpsSeconds_ = 0.0;
    std::optional<std::chrono::steady_clock::time_point> lastLoop_;  ///< loopOnce's last pass
    int benchFrame_ = 0;  ///< benchmark frames run, the warm-up's included
    double benchStepMs_ = 0.0, benchDrawMs_ = 0.0;         ///< summed after the warm-up
    std::chrono::steady_clock::time_point benchMeasured_;  ///< the first frame after the warm-up
};

}  // namespace psb::app
