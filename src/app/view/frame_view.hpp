#pragma once
// What one frame shows, as read-only data: render() builds it from the session (and the
// frame-time figures only the loop knows), the drawing layer (render/draw_layer.hpp) draws it.
// Nothing in the view draws or includes SDL: text is measured through TextMeasure.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <particle_sandbox/particle.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"
#include "session/gas_gauges.hpp"
#include "session/last_collision.hpp"
#include "session/video_settings.hpp"
#include "session/view_options.hpp"
#include "view/bin_histogram.hpp"
#include "view/box_area.hpp"
#include "view/dropper_mark.hpp"
#include "view/lab_marks.hpp"
#include "view/overlays.hpp"
#include "view/periodic_box.hpp"
#include "view/screen_layout.hpp"
#include "view/text_measure.hpp"
#include "view/values_table.hpp"

namespace psb::app {

class Session;

/// A launch being dragged out: where the particle will appear and the velocity arrow it will
/// have (world metres), with its speed as text.
struct LaunchPreviewView {
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    double radius = 0.0;
    std::string label;
};

/// The box is entirely off screen: an arrow at the screen's edge pointing to it.
struct BoxMarkerView {
    Vec2 at = Vec2::Zero();         ///< screen pixels, on the edge
    Vec2 direction = Vec2::Zero();  ///< unit, towards the box
    std::string label;
};

/// A video is being recorded: a red mark in the box's top-right corner, drawn after the frame
/// is captured, so that it is on the screen and not in the video.
struct RecordingMarkView {
    PixelRect at;       ///< the mark's box, pixels
    std::string label;  ///< "REC 0:12 MP4 - Ctrl+R stops"
};

struct FrameView {
    const World* world = nullptr;
    const Camera* camera = nullptr;
    const TimeSeries* series = nullptr;
    /// The window its collision rate counts over, s of simulated time (Session::rateWindow).
    double rateWindow = 0.0;
    ObservablesSample now;
    ViewOptions view;
    double frameLength = 0.0;  ///< the scene's dt (the session's meta().dt), seconds
    std::uint64_t sceneGeneration = 0;
    ParticleId trailParticle;
    std::optional<Particle> selected;
    std::optional<LaunchPreviewView> launch;
    std::optional<Obstacle> selectedObstacle;  ///< drawn highlighted
    std::optional<Obstacle> obstaclePreview;   ///< a peg or wall the tool would make now
    std::optional<BoxMarkerView> boxMarker;
    /// A periodic box: its dashed edges and the discs drawn again across them
    /// (view/periodic_box.hpp); nullopt for a box with walls or none.
    std::optional<PeriodicBoxView> periodic;
    /// Where the selected particle is drawn again across the periodic box's edges: metres added
    /// to its centre (its images' offsets), each outlined as the particle is.
    std::vector<Vec2> selectedImages;
    std::optional<RecordingMarkView> recordingMark;
    /// The gas instruments' reading, when they apply (the panel's Readouts show it).
    std::optional<GasReading> gas;
    /// The pressure plot's latest point as a line of text (view/pressure_plot.hpp), with the gas.
    std::string pressurePlot;
    /// The last collision card, while shown (J) and once there was a collision to show.
    std::optional<CollisionCard> collision;
    /// The values table, while shown (I).
    std::optional<ValuesTable> values;
    /// The grid of metres (Shift+G) and the ruler (Q), while shown (view/lab_marks.hpp).
    std::optional<GridView> grid;
    std::optional<RulerView> ruler;
    /// A wall being drawn: its length and slope beside its end (the Wall tool's protractor).
    std::optional<MarkLabel> wallAngle;
    std::optional<BinHistogram> bins;  ///< the scene's bins, while shown
    std::vector<DropperView> droppers;
    Overlays overlays;
    PanelLayout layout;
    int controlsInset = 0;  ///< pixels at the window's left the control panel covers
    std::string title;
};

/// The video the app's recorder is writing (platform/video_recorder.hpp), as the frame loop
/// knows it.
struct VideoStatus {
    bool recording = false;
    VideoFormat format = VideoFormat::Mp4;
    double seconds = 0.0;     ///< recorded so far, real time
    std::size_t frames = 0;   ///< captured so far
    std::size_t dropped = 0;  ///< frames left out because the encoder was behind
    std::string lastFile;     ///< the last video written (absolute); empty: none yet
    /// Why this build or machine cannot record each format (by VideoFormat: no FFmpeg, no
    /// encoder); empty: it can.
    std::array<std::string, 3> unavailable;
};

/// What only the frame loop knows.
struct FrameStats {
    double fps = 0.0;
    double stepMs = 0.0;              ///< smoothed
    double drawMs = 0.0;              ///< smoothed
    double lastStepMs = 0.0;          ///< the last frame's
    double lastDrawMs = 0.0;          ///< the last frame's
    bool labelsSuppressed = false;    ///< the last draw had too many particles for labels
    std::size_t labelsCrowded = 0;    ///< labels the last draw left out: others in the way
    std::size_t labelsOffWindow = 0;  ///< labels left out: no side of the disc in the window
    std::string renderer;             ///< the render driver in use
    std::vector<std::string> messages;
    VideoStatus video;
};

/// The frame for `session` beside the control panel `controls` wide; the fonts only measure
/// text for the layout.
[[nodiscard]] FrameView buildFrame(const Session& session, const FrameStats& stats,
                                   const TextMeasure& hudFont, const TextMeasure& labelFont,
                                   const ControlsWidth& controls);

/// What the particles' labels keep clear of besides the discs and the scene's walls: the
/// panels, the control panel's column, the ruler and its reading, the grid's labels, the
/// droppers' words and the bins' numbers (measured in `labelFont`): a label is never drawn over
/// another reading.
[[nodiscard]] LabelKeepOut labelKeepOut(const FrameView& frame, const TextMeasure& labelFont);

/// How a video being recorded is stopped: "Ctrl+R stops", or on a touch screen (`touch`:
/// Session::touch) the panel's button, "Video: Stop video".
[[nodiscard]] const char* videoStopHint(bool touch);
/// The recording mark's text: "REC 0:12 MP4 - Ctrl+R stops" (videoStopHint).
[[nodiscard]] std::string recordingLabel(const VideoStatus& video, bool touch = false);

/// Where the box marker goes, or nullopt while any of the box [0, w] × [0, h] is on screen. Its
/// label names what fits the box back: the key F, or on a touch screen (`touch`) the panel's.
[[nodiscard]] std::optional<BoxMarkerView> boxMarker(const Camera& camera, double width,
                                                     double height, bool touch = false);

}  // namespace psb::app
