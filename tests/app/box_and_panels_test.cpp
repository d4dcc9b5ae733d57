// The box the session fits, into the areas the view gives it (view/box_area.hpp), against the
// panels the view lays out and the control panel's width: at every window size no chart covers
// the box, and the box's area and the layout agree on when the side column folds away. Across
// three layers, so it is tested with the whole app.

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "gui/control_panel.hpp"
#include "session/keys.hpp"
#include "session/scene_io.hpp"
#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"
#include "view/box_area.hpp"
#include "view/fixed_measure.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

class BoxAndPanels : public SessionFixture {
  protected:
    BoxAndPanels() : SessionFixture("psb-box-panels", TestWindow{}) {}

    /// The window `width` × `height` as the app lays it out for the session, beside `controls`.
    [[nodiscard]] static cmd::Resize resize(int width, int height,
                                            const ControlsWidth& controls = {}) {
        return {width, height, windowLayout(test::FixedMeasure{}, width, height, controls)};
    }
};

TEST_F(BoxAndPanels, ThePanelsSitBesideTheBoxAtEveryWindowSizeFrom800x600) {
    // The layout the app draws (HUD and messages sized as the 14 px font makes them) against
    // the box the fitted camera shows, with the plots, the histogram and the profile on.
    SessionOptions o = options();
    o.layout = resize(o.viewportWidth, o.viewportHeight).layout;
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    s.apply(keys::show(s, ShowOption::Plots));
    s.apply(keys::show(s, ShowOption::Speeds));
    s.apply(keys::show(s, ShowOption::Profile));
    for (const auto& [w, h] : {std::pair{800, 600},
                               {900, 800},
                               {1024, 768},
                               {1280, 720},
                               {1366, 768},
                               {1600, 900},
                               {1920, 1080},
                               {800, 1200}}) {
        s.apply(resize(w, h));
        const auto b = s.camera().boxOnScreen(7.0, 7.0);
        const PixelRect box{static_cast<int>(b.topLeft.x()), static_cast<int>(b.topLeft.y()),
                            static_cast<int>(b.size.x()), static_cast<int>(b.size.y())};
        LayoutRequest req;
        req.width = w;
        req.height = h;
        req.hud = {560, 129};
        req.profile = {260, 220};
        req.messages = {400, 40};
        req.plots = req.speeds = true;
        const PanelLayout l = layoutPanels(req);
        for (const PixelRect& panel : {l.plots, l.speeds, l.profile, l.messages}) {
            EXPECT_FALSE(overlaps(panel, box))
                << w << "x" << h << ": panel at " << panel.x << "," << panel.y << " " << panel.w
                << "x" << panel.h << ", box " << box.x << "," << box.y << " " << box.w << "x"
                << box.h;
        }
        EXPECT_GT(l.plots.w, 0) << w << "x" << h;
        EXPECT_GT(box.w, w / 3) << w << "x" << h;  // the box still gets a good part
    }
}

TEST_F(BoxAndPanels, NoChartCoversTheBoxAtAnyWindowSizeWithTheControlsOpenOrFolded) {
    // The Galton board's bins chart, the plots and the speed histogram, against the box the
    // fitted camera shows, from 500 px wide up; where the column does not fit beside the box the
    // charts fold away and the session says so.
    SessionOptions o = options();
    ControlsWidth panel = controlsWidth(1.0, o.viewportWidth);
    o.layout = resize(o.viewportWidth, o.viewportHeight, panel).layout;
    o.presets = testPresets();
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    const auto& presets = s.presets();
    const auto galton = std::find_if(presets.begin(), presets.end(), [](const SceneListing& p) {
        return p.name == "Galton board";
    });
    ASSERT_NE(galton, presets.end());
    s.apply(cmd::OpenPreset{static_cast<int>(galton - presets.begin())});
    ASSERT_TRUE(s.binsShown());
    s.apply(keys::show(s, ShowOption::Plots));
    s.apply(keys::show(s, ShowOption::Speeds));
    int folded = 0, shown = 0;
    for (const bool controls : {true, false}) {
        for (int w = 500; w <= 1400; w += 50) {
            for (const int h : {500, 600, 800}) {
                panel = controlsWidth(1.0, w);  // a share of the window
                s.apply(resize(w, h, panel));
                // A window too narrow for the box beside the panel folds it: opened again.
                if (s.controlsShown() != controls) s.apply(cmd::ToggleControls{});
                const auto b =
                    s.camera().boxOnScreen(s.world().def().width, s.world().def().height);
                const PixelRect box{static_cast<int>(b.topLeft.x()),
                                    static_cast<int>(b.topLeft.y()), static_cast<int>(b.size.x()),
                                    static_cast<int>(b.size.y())};
                LayoutRequest req;
                req.width = w;
                req.height = h;
                req.left = controlsInset(s, panel);
                req.hud = {300, 129};
                req.messages = {300, 40};
                req.plots = req.speeds = req.bins = true;
                const PanelLayout l = layoutPanels(req);
                EXPECT_EQ(l.columnFolded, sideColumnFolded(s, panel)) << w << "x" << h;
                for (const PixelRect& chart : {l.plots, l.speeds, l.bins}) {
                    EXPECT_FALSE(overlaps(chart, box))
                        << w << "x" << h << (controls ? ", controls open" : "") << ": chart at "
                        << chart.x << "," << chart.y << " " << chart.w << "x" << chart.h << ", box "
                        << box.x << "," << box.y << " " << box.w << "x" << box.h;
                }
                (l.columnFolded ? folded : shown) += 1;
                if (w == 600 && h == 600 && controls) {
                    EXPECT_TRUE(sideColumnFolded(s, panel)) << "the case a new user met";
                }
            }
        }
    }
    EXPECT_GT(folded, 0);
    EXPECT_GT(shown, 0);
}

TEST_F(BoxAndPanels, TheBandAboveTheBoxHoldsTheFoldedChartsNote) {
    // The HUD says the charts are folded; the fitted box starts below that note too.
    SessionOptions o = options();
    o.viewportWidth = o.viewportHeight = 600;
    const ControlsWidth controls = controlsWidth(1.0, 600);
    o.layout = resize(600, 600, controls).layout;
    const double note = o.layout.controlsOpenColumn.top;
    EXPECT_GT(note, o.layout.controlsOpen.top) << "the note's lines";
    Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    const double before = s.camera().boxOnScreen(7.0, 7.0).topLeft.y();
    s.apply(keys::show(s, ShowOption::Plots));
    ASSERT_TRUE(sideColumnFolded(s, controls));
    const double after = s.camera().boxOnScreen(7.0, 7.0).topLeft.y();
    EXPECT_GE(after, note - 1e-9);
    EXPECT_GT(after, before) << "moved down for the note";
    s.apply(cmd::ToggleControls{});  // folded to its strip: the column fits, no note
    EXPECT_FALSE(sideColumnFolded(s, controls));
    EXPECT_LT(o.layout.controlsFoldedColumn.top, note);
}

}  // namespace
}  // namespace psb::app
