#include "view/frame_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "view/bin_numbers.hpp"
#include "view/box_area.hpp"
#include "view/chart_text.hpp"
#include "view/hud.hpp"
#include "view/inspector_lines.hpp"
#include "view/mass_shade.hpp"
#include "view/momentum_view.hpp"
#include "view/plot_scale.hpp"
#include "view/pressure_plot.hpp"

namespace psb::app {

namespace {

HudData hudData(const Session& session) {
    const World& world = session.world();
    HudData hud;
    hud.simTime = world.time();
    hud.timeScale = session.timeScale();
    hud.reachedTimeScale = session.reachedTimeScale();
    hud.particles = world.size();
    hud.kineticEnergy = session.observables().kineticEnergy;
    hud.momentum = session.axes().vector(session.observables().momentum);
    hud.spawnMass = session.spawn().mass();
    hud.spawnRadius = session.spawn().radius();
    hud.arrowSeconds = session.view().arrows ? session.view().arrowSeconds : 0.0;
    hud.paused = session.paused();
    hud.touch = session.touch();
    const double overlap = session.accuracy().overlap();
    if (overlap > 0.05 * session.spawn().typicalRadius) hud.overlap = overlap;
    const TimelineView past = session.timeline();
    hud.past = past.viewingPast;
    hud.secondsBack = past.secondsBack();
    hud.recording = session.data().recording();
    if (const MassRange masses = massRange(world.particles().mass); masses.varies()) {
        hud.lightestMass = masses.lo;
        hud.heaviestMass = masses.hi;
    }
    return hud;
}

/// Pixels kept clear round a bin's number on the board by the other readings.
constexpr int kBinNumberAir = 2;

PixelRect grown(const PixelRect& r, int by) {
    return {r.x - by, r.y - by, r.w + 2 * by, r.h + 2 * by};
}

/// Messages narrower than this beside the inspector go under it instead, pixels.
constexpr int kMinMessageRoom = 200;

/// The inspector's `lines` with the long ones wrapped at the width of the others (a refusal's
/// reason), and never wider than `room`.
std::vector<std::string> inspectorPanel(const TextMeasure& font, std::vector<std::string> lines,
                                        int room) {
    int width = 0;
    for (const std::string& l : lines)
        if (l.rfind("Refused: ", 0) != 0) width = std::max(width, font.measure(l));
    return wrapLines(font, lines, std::min(width + 8, room - 2 * kPanelMargin));
}

std::string speedLabel(const CappedVelocity& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2f m/s%s", v.velocity.norm(),
                  v.capped ? " (capped: 2 box widths/s)" : "");
    return buf;
}

}  // namespace

LabelKeepOut labelKeepOut(const FrameView& frame, const TextMeasure& labelFont) {
    LabelKeepOut out;
    out.rects = panelRects(frame.layout);
    // Labels keep out from under the control panel (drawn over them).
    if (frame.controlsInset > 0 && frame.camera != nullptr) {
        out.rects.push_back({0, 0, frame.controlsInset, frame.camera->viewportHeight()});
    }
    // The ruler's reading is placed first, among the discs; the labels go round it and the
    // ruler.
    if (frame.ruler) {
        out.rects.push_back(labelRect(frame.ruler->label, labelFont, kReadingPad));
        out.walls.push_back(rulerBand(*frame.ruler));
    }
    // The grid's distances and the droppers' words are readings too: no label covers them.
    if (frame.grid) {
        for (const PixelRect& plate : gridLabelPlates(*frame.grid, labelFont))
            out.rects.push_back(plate);
    }
    for (const DropperView& d : frame.droppers)
        out.rects.push_back(d.words.at);
    // The momentum view's total arrow from the centre of mass, its head and the centre's mark:
    // after the lesson's collision ball 2's label stood on it, read as the arrow's.
    if (frame.view.momentum && frame.world != nullptr && frame.camera != nullptr &&
        frame.world->size() > 0) {
        const TotalMomentumArrow total =
            totalMomentumArrow(*frame.world, frame.now, frame.view.arrowSeconds);
        const Vec2 a = frame.camera->worldToScreen(total.from),
                   b = frame.camera->worldToScreen(total.to);
        out.walls.push_back({a.x(), a.y(), b.x(), b.y(), 0.6 * labelFont.lineHeight()});
    }
    if (frame.bins && frame.camera != nullptr && frame.world != nullptr) {
        for (const BinNumber& n :
             binNumbers(*frame.camera, frame.bins->bins, frame.world->def().height, labelFont)) {
            out.rects.push_back(grown(n.at, kBinNumberAir));
        }
    }
    return out;
}

const char* videoStopHint(bool touch) {
    return touch ? "Video: Stop video" : "Ctrl+R stops";
}

std::string recordingLabel(const VideoStatus& video, bool touch) {
    const auto whole = static_cast<long>(video.seconds);
    char buf[96];
    std::snprintf(buf, sizeof buf, "REC %ld:%02ld %s - %s", whole / 60, whole % 60,
                  toString(video.format), videoStopHint(touch));
    return buf;
}

std::optional<BoxMarkerView> boxMarker(const Camera& camera, double width, double height,
                                       bool touch) {
    const Camera::ScreenBox b = camera.boxOnScreen(width, height);
    const double w = camera.viewportWidth(), h = camera.viewportHeight();
    const bool visible = b.topLeft.x() + b.size.x() >= 0.0 && b.topLeft.x() <= w &&
                         b.topLeft.y() + b.size.y() >= 0.0 && b.topLeft.y() <= h;
    if (visible) return std::nullopt;
    const Vec2 centre(w / 2.0, h / 2.0);
    const Vec2 boxCentre = b.topLeft + b.size / 2.0;
    const Vec2 d = boxCentre - centre;
    const double n = d.norm();
    if (!(n > 0.0) || !std::isfinite(n)) return std::nullopt;
    const Vec2 u = d / n;
    // The ray from the centre towards the box leaves the screen (less a margin) at `at`.
    const double margin = 24.0;
    const double tx = std::abs(u.x()) > 1e-12 ? (w / 2.0 - margin) / std::abs(u.x()) : 1e300;
    const double ty = std::abs(u.y()) > 1e-12 ? (h / 2.0 - margin) / std::abs(u.y()) : 1e300;
    BoxMarkerView m;
    m.at = centre + std::min(tx, ty) * u;
    m.direction = u;
    m.label = touch ? "box this way (Show: Fit view)" : "box this way (F fits)";
    return m;
}

FrameView buildFrame(const Session& session, const FrameStats& stats, const TextMeasure& hudFont,
                     const TextMeasure& labelFont, const ControlsWidth& controls) {
    const World& world = session.world();
    FrameView f;
    f.world = &world;
    f.camera = &session.camera();
    f.series = &session.series();
    f.rateWindow = session.rateWindow();
    f.now = session.observables();
    f.view = session.view();
    f.frameLength = session.meta().dt;
    f.sceneGeneration = session.sceneGeneration();
    f.trailParticle = session.trailParticle();
    f.selected = session.selected();
    if (session.interaction().mode() == Interaction::Mode::Launching) {
        LaunchPreviewView l;
        const CappedVelocity v = session.launchPreview();
        l.from = session.interaction().pressPoint();
        // The velocity arrow the particle will have: arrowSeconds of its motion.
        l.to = l.from + v.velocity * session.view().arrowSeconds;
        l.radius = session.spawn().radius();
        l.label = speedLabel(v);
        f.launch = l;
    }
    if (const auto i = session.selectedObstacle(); i && *i < world.obstacles().size()) {
        f.selectedObstacle = world.obstacles()[*i];
    }
    f.obstaclePreview = session.obstaclePreview();
    if (f.obstaclePreview && !f.obstaclePreview->isPeg()) {
        f.wallAngle = wallAngleLabel(f.obstaclePreview->a, f.obstaclePreview->b, session.camera());
    }
    f.boxMarker =
        boxMarker(session.camera(), world.def().width, world.def().height, session.touch());
    f.periodic = periodicBoxView(world, session.camera());
    if (f.periodic && f.selected) {
        if (const std::optional<std::size_t> at = world.indexOf(f.selected->id)) {
            for (const PeriodicImage& image : f.periodic->images) {
                if (image.index == *at) f.selectedImages.push_back(image.offset);
            }
        }
    }
    f.gas = session.gasReading();
    if (f.gas) f.pressurePlot = pressurePlotLine(session.gasHistory());
    if (session.view().collision) f.collision = session.lastCollision();
    if (session.view().values)
        f.values = valuesTable(world, session.selection().id(), session.axes());
    if (session.view().grid) {
        f.grid =
            gridView(session.camera(), world.def().width, world.def().height, session.view().yUp,
                     kGridMinPixels * controls.pointPixels, labelFont.lineHeight());
    }
    if (session.view().ruler) f.ruler = rulerView(session.ruler(), session.camera());
    if (stats.video.recording) {
        // At the top of the side column (layoutPanels places it).
        RecordingMarkView mark;
        mark.label = recordingLabel(stats.video, session.touch());
        f.recordingMark = mark;
    }
    std::uint64_t stillToDrop = 0;
    for (const Dropper& d : world.droppers()) {
        stillToDrop += d.balls;
        f.droppers.push_back({d.position, d.radius, d.spread, dropperLabel(d), {}});
    }
    if (session.binsShown()) {
        f.bins = binHistogram(*session.meta().bins, world.particles(), stillToDrop);
    }

    Overlays& o = f.overlays;
    // The HUD's readings wrap between their parts within the room right of the control panel.
    const int left = controlsInset(session, controls);
    f.controlsInset = left;
    const int hudRoom = session.camera().viewportWidth() - left;
    const auto readings = [&](const HudData& d) {
        std::vector<std::string> lines = hudLines(d);
        // The stopwatch where the eye is, and in screenshots and videos of the box.
        if (std::string line =
                stopwatchLine(session.stopwatch(), session.world().time(), session.touch());
            !line.empty()) {
            lines.push_back(std::move(line));
        }
        return wrapHudLines(hudFont, lines, hudRoom - 8);
    };
    const bool narrow = hudIsNarrow(hudFont, hudRoom);
    HudData hud = hudData(session);
    hud.narrow = narrow;
    o.hud = readings(hud);
    // While a video records, the layout is the video's: the room it keeps for the HUD is the
    // video's HUD with the lines that come and go as it records (a step into the past, an
    // overlap), so that the panels beside and below it, the plots' rows among them, stay put
    // through the clip. The screen's hints are drawn over the frame once it is taken.
    std::optional<PixelPoint> videoHud;
    if (stats.video.recording) {
        HudData video = hud;
        video.forVideo = true;
        o.hudRecorded = readings(video);
        video.past = true;
        video.secondsBack = std::max(video.secondsBack, 99.99);
        video.overlap = std::max(video.overlap, 0.999);
        const PixelPoint now = textBoxSize(hudFont, o.hudRecorded),
                         most = textBoxSize(hudFont, readings(video));
        videoHud = PixelPoint{std::max(now.x, most.x), std::max(now.y, most.y)};
    }
    if (stats.labelsSuppressed) o.hud.emplace_back("Labels hidden: too many on screen");
    if (sideColumnFolded(session, controls)) {
        // Said where the eye is: the charts asked for are not drawn over the box.
        for (std::string& line : wrapLines(
                 hudFont, {foldedChartsNote(session.controlsShown(), session.touch(), narrow)},
                 hudRoom - 8)) {
            o.hud.push_back(std::move(line));
        }
    }
    // What kept labels out, in words: other labels and panels in the way, or the window's
    // edges all round a disc (the drawing layer slides a label along its disc's side before
    // giving up, so a disc near an edge is not among these).
    if (session.view().labels) {
        // Wrapped as the readings are: at 200 % a note ran past the window's right edge.
        for (const auto& [count, offWindow] :
             {std::pair{stats.labelsCrowded, false}, std::pair{stats.labelsOffWindow, true}}) {
            if (count == 0) continue;
            for (std::string& line :
                 wrapLines(hudFont, {labelsLeftOutNote(count, offWindow, narrow)}, hudRoom - 8)) {
                o.hud.push_back(std::move(line));
            }
        }
    }
    o.showHelp = session.helpShown();
    if (o.showHelp) {
        const PixelRect room =
            helpRoom(session.camera().viewportWidth(), session.camera().viewportHeight());
        const auto pages = helpPages(hudFont, helpLines(session.inPage()), {room.w, room.h});
        o.help = pages[std::min(session.helpPage(), pages.size() - 1)];
        o.helpAt = {room.x, room.y};
    }
    o.showProfile = session.profileShown();
    if (o.showProfile) {
        ProfileData pd;
        pd.profile = world.profile();
        pd.mode = world.solver().mode;
        pd.eventsPerStep = session.accuracy().eventsPerStep();
        pd.frameStepMs = stats.lastStepMs;
        pd.frameDrawMs = stats.lastDrawMs;
        o.profile = profileLines(pd);
    }
    // With the control panel open the selected particle's values are in it; the inspector
    // beside the box stays for the keyboard's edit prompt (Enter). Its long lines (a refusal's
    // reason) wrap at the width of its readings.
    // Left of the values table where it docks at the right.
    const int room = session.camera().viewportWidth() - left -
                     (session.view().values && session.valuesDock().right
                          ? static_cast<int>(session.valuesDock().size)
                          : 0);
    const bool editing = session.prompt().active();
    if (f.selected && (!session.controlsShown() || editing)) {
        o.inspector =
            inspectorPanel(hudFont,
                           inspectorLines(*f.selected, session.prompt(), true,
                                          world.rotationInUse(), session.axes(), session.touch()),
                           room);
    }
    LayoutRequest req;
    req.width = session.camera().viewportWidth();
    req.height = session.camera().viewportHeight();
    req.left = left;
    req.foldColumn = session.columnFolded();
    req.plots = f.view.plots;
    req.speeds = f.view.speeds;
    req.bins = f.bins.has_value();
    req.scale = controls.pointPixels;
    req.values = valuesTableRect(session, controls);
    req.valuesRight = session.valuesDock().right;
    if (session.chartsBelow()) {
        // Under the box, above the messages (SceneView::fit chose it; BoxArea::chartsBand).
        const BoxArea& bare = session.layout().area(session.controlsShown(), false);
        req.chartsBand = chartsBandRect(req.width, req.height, left, static_cast<int>(bare.bottom),
                                        static_cast<int>(bare.chartsBand) - kPanelGap);
    }
    // Under the plots, the names of those left out for want of room.
    req.plotsNote = labelFont.lineHeight() + 4;
    {
        // Side by side under the box, a plot is as narrow as its brief title, or its y axis's
        // labels and three lines' worth of curve, allow: the lesson's four at 200 %.
        int least =
            yAxisRoom(labelFont, {"t (s)  ", "-10.00"}, 78) + 8 + 3 * labelFont.lineHeight();
        for (int k = 0; k < kPlotCount; ++k)
            least = std::max(
                least, labelFont.measure(plotTitle(k, session.rateWindow(), true)) + 2 * kChartPad);
        req.plotColumnLeast = least;
    }
    // Long messages wrap within the room right of the control panel and left of the side
    // column's charts (a message of three lines under the column took a row of plots away
    // while it showed), beside the inspector when that leaves them room; the newest messages
    // that fit the band below the box whole are shown.
    const int messageRoom = std::min(room, sideColumnLeft(req) - kPanelGap - left);
    const int besideInspector =
        messageRoom - textBoxSize(hudFont, o.inspector).x - kPanelGap - kPanelMargin;
    const bool beside = !o.inspector.empty() && besideInspector >= kMinMessageRoom;
    const int messageWidth = beside ? besideInspector : messageRoom;
    o.messages = messageLines(hudFont, stats.messages, messageWidth - 8, kMessageLines);
    o.messagesAfterCapture = stats.video.recording;

    req.hud = textBoxSize(hudFont, o.hud);
    req.hudShown = req.hud;
    if (videoHud) {
        // As drawn over the frame once it is taken (drawMessages): the video's box and more.
        const PixelPoint video = textBoxSize(hudFont, o.hudRecorded);
        req.hudShown = {std::max(req.hud.x, video.x), std::max(req.hud.y, video.y)};
        // The screen's HUD is drawn over the frame once it is taken, opaque (its hints and
        // notes are lines more than the video's): the mark and the panels stand clear of it
        // too, and of its line that comes and goes as the user steps into the past.
        HudData screen = hud;
        screen.past = true;
        screen.secondsBack = std::max(screen.secondsBack, 99.99);
        screen.overlap = std::max(screen.overlap, 0.999);
        std::vector<std::string> most = readings(screen);
        for (std::size_t k = readings(hud).size(); k < o.hud.size(); ++k)
            most.push_back(o.hud[k]);
        const PixelPoint shown = textBoxSize(hudFont, most);
        req.hud = {std::max({req.hud.x, videoHud->x, shown.x}),
                   std::max({req.hud.y, videoHud->y, shown.y})};
    }
    if (o.showProfile) req.profile = textBoxSize(hudFont, o.profile);
    if (f.view.momentum) {
        req.legend = textBoxSize(labelFont,
                                 momentumLegend(world, f.now, f.view.arrowSeconds, session.axes()));
    }
    req.messages = textBoxSize(hudFont, o.messages);
    req.inspector = textBoxSize(hudFont, o.inspector);
    // The open prompt has the keyboard: it is never hidden, by a message or for want of room
    // (then without the readings), or the keys typed would go into fields nobody sees.
    req.inspectorFirst = editing;
    {
        // The box with its walls as drawn: the legend keeps off it.
        const WorldDef& def = world.def();
        const Camera::ScreenBox b = session.camera().boxOnScreen(def.width, def.height);
        const int wall = def.walls ? static_cast<int>(std::ceil(boxWallPixels(
                                         def.width, def.height, session.camera().zoom())))
                                   : 0;
        req.box = {static_cast<int>(std::floor(b.topLeft.x())) - wall,
                   static_cast<int>(std::floor(b.topLeft.y())) - wall,
                   static_cast<int>(std::ceil(b.size.x())) + 2 * wall + 1,
                   static_cast<int>(std::ceil(b.size.y())) + 2 * wall + 1};
    }
    if (req.legend.x > 0 && !o.messages.empty()) {
        // The legend stands where it would with no message: where that is in the messages'
        // band (right of them, under the plots' band), they wrap left of it. A message as wide
        // as the band sent the legend into the plots' band, which lost a plot to it for as long
        // as the message showed, in the video too.
        LayoutRequest quiet = req;
        quiet.messages = {0, 0};
        quiet.recording = {0, 0};
        const PixelRect legend = layoutPanels(quiet).legend;
        const int bandTop = req.height - kPanelMargin -
                            textBoxSize(hudFont, std::vector<std::string>(kMessageLines, "0")).y;
        const int besideLegend = legend.x - kPanelGap - left;
        if (legend.w > 0 && legend.y + legend.h > bandTop && besideLegend < messageWidth &&
            besideLegend >= kMinMessageRoom) {
            o.messages = messageLines(hudFont, stats.messages, besideLegend - 8, kMessageLines);
            req.messages = textBoxSize(hudFont, o.messages);
        }
    }
    if (f.recordingMark) {
        // Its red dot and the plate's margin left of the text (DrawLayer::drawRecordingMark).
        const PixelPoint text = textBoxSize(hudFont, {f.recordingMark->label});
        req.recording = {text.x + hudFont.lineHeight() / 2 + 6, text.y};
    }
    if (!stats.messages.empty() && !o.messages.empty()) {
        // The newest message is read whole: where the band cuts it (an aside dropped, "…"), it
        // takes the lines it needs, in the band at the bottom (left of the legend there, or
        // the width of the room) or else over the box's lower part, above the charts' band
        // under it, at the room's width, its background opaque as ever. Each place is taken
        // only where the panels stand as they do with no message and it covers none of them
        // (the plots and the legend are in the video); nowhere: the band's three lines, cut,
        // and the log has it whole.
        const std::string& newest = stats.messages.back();
        const auto needs = [&](int width) {
            return wrapLines(hudFont, {newest}, width - 8).size();
        };
        const int shownWidth = req.messages.x;
        if (needs(shownWidth) > kMessageLines) {
            LayoutRequest quietReq = req;
            quietReq.messages = {0, 0};
            const PanelLayout quiet = layoutPanels(quietReq);
            const auto stays = [&quiet](const PanelLayout& l) {
                const auto same = [](const PixelRect& a, const PixelRect& b) {
                    return a.x == b.x && a.y == b.y && a.w == b.w && a.h == b.h;
                };
                if (l.messages.w == 0) return false;
                for (const PixelRect& r : panelRects(l))
                    if (!same(r, l.messages) && overlaps(r, l.messages)) return false;
                return same(l.plots, quiet.plots) && l.plotRows == quiet.plotRows &&
                       l.plotColumns == quiet.plotColumns && l.plotsNote == quiet.plotsNote &&
                       same(l.legend, quiet.legend) && same(l.speeds, quiet.speeds) &&
                       same(l.bins, quiet.bins) && same(l.profile, quiet.profile) &&
                       same(l.hud, quiet.hud) && same(l.inspector, quiet.inspector) &&
                       same(l.values, quiet.values) && l.columnFolded == quiet.columnFolded;
            };
            struct Place {
                int width;
                int bottom;  // LayoutRequest::messagesBottom
            };
            std::vector<Place> places{{shownWidth, 0}};
            if (messageWidth != shownWidth) places.push_back({messageWidth, 0});
            const int boxBottom = req.box.y + req.box.h;
            if (req.box.w > 0) {
                // Over the box's lower part: above the charts' band, or at the box's bottom.
                if (req.chartsBand.w > 0) places.push_back({messageRoom, req.chartsBand.y});
                places.push_back({messageRoom, boxBottom});
            }
            for (const Place& p : places) {
                if (p.width < kMinMessageRoom) continue;
                const std::size_t lines = std::max(kMessageLines, needs(p.width));
                LayoutRequest tried = req;
                tried.messages =
                    textBoxSize(hudFont, messageLines(hudFont, stats.messages, p.width - 8, lines));
                tried.messagesBottom = p.bottom > 0 ? p.bottom - kPanelGap : 0;
                const PanelLayout l = layoutPanels(tried);
                // Over the box's lower part at most, no higher than its middle.
                if (req.box.w > 0 && l.messages.y < req.box.y + req.box.h / 2) continue;
                if (l.messages.y < 0 || l.messages.x + l.messages.w > req.width || !stays(l))
                    continue;
                o.messages = messageLines(hudFont, stats.messages, p.width - 8, lines);
                req = tried;
                break;
            }
        }
    }
    f.layout = layoutPanels(req);
    if (editing && f.selected && f.layout.inspector.w == 0) {
        o.inspector =
            inspectorPanel(hudFont,
                           inspectorLines(*f.selected, session.prompt(), false,
                                          world.rotationInUse(), session.axes(), session.touch()),
                           room);
        req.inspector = textBoxSize(hudFont, o.inspector);
        f.layout = layoutPanels(req);
    }
    if (f.recordingMark) f.recordingMark->at = f.layout.recording;
    if (f.recordingMark && o.showHelp) {
        // The help covers the panels the mark would keep off: the mark goes to a corner
        // clear of the help's lines, the top-right one first (the help's title is short),
        // else the bottom-right one (it was drawn over the help's text).
        const PixelRect& r = f.layout.recording;
        const PixelRect top{req.width - kPanelMargin - req.recording.x, kPanelMargin,
                            req.recording.x, req.recording.y};
        const PixelRect low{top.x, req.height - kPanelMargin - req.recording.y, top.w, top.h};
        const auto clear = [&](const PixelRect& at) {
            const std::vector<PixelRect> lines = helpLineRects(hudFont, o.help, o.helpAt);
            return std::none_of(lines.begin(), lines.end(),
                                [&at](const PixelRect& l) { return overlaps(l, at); });
        };
        f.recordingMark->at = clear(top) ? top : clear(low) ? low : r;
    }
    // The window right of the control panel, where the readings drawn over the box are read.
    const PixelRect window{left, 0, req.width - left, req.height};
    if (!f.droppers.empty()) {
        // A dropper's words inside the box, clear of the panels and of the pegs below the
        // spout (wrapped words ran down over the Galton board's first rows).
        std::vector<PixelRect> keepOut = panelRects(f.layout);
        for (const PixelRect& r : pegsOnScreen(world, session.camera()))
            keepOut.push_back(r);
        const LabelRoom words = labelRoom(world, session.camera(), window, std::move(keepOut));
        for (DropperView& d : f.droppers)
            d.words = dropperWords(dropperSpout(session.camera(), d), d.label, labelFont, words);
    }
    if (f.grid || f.ruler) {
        // The marks' labels are read whole: in the window right of the control panel, clear of
        // every panel and of each other; the ruler's reading off the discs and pegs where it can.
        std::vector<PixelRect> discs;
        if (f.ruler) {
            discs = discsOnScreen(world, session.camera(), window);
            for (const PixelRect& r : pegsOnScreen(world, session.camera()))
                discs.push_back(r);
        }
        // A dropper's words are a reading too: the grid's labels keep off them.
        std::vector<PixelRect> keepOut = panelRects(f.layout);
        for (const DropperView& d : f.droppers)
            keepOut.push_back(d.words.at);
        // So are the bins' numbers on the board, with air round them (the Galton board's "0"
        // touched "0.4 m").
        if (f.bins) {
            for (const BinNumber& n :
                 binNumbers(session.camera(), f.bins->bins, world.def().height, labelFont)) {
                keepOut.push_back(grown(n.at, kBinNumberAir));
            }
        }
        keepMarkLabelsClear(f.grid ? &*f.grid : nullptr, f.ruler ? &*f.ruler : nullptr, labelFont,
                            labelRoom(world, session.camera(), window, std::move(keepOut)), discs);
    }
    f.title =
        windowTitle(world.size(), session.paused(), session.meta().name, session.unsavedChanges());
    return f;
}

}  // namespace psb::app
