// The plots' words (plot_scale.hpp): the collision rate's title names its window, a y axis
// keeps three labelled ticks; where the plots' titles, axes and time labels go (chart_text.hpp):
// no title on a tick label, and a row at its least height has room for three labels.

#include <gtest/gtest.h>

#include "session/monitor.hpp"
#include "view/chart_text.hpp"
#include "view/plot_scale.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {
namespace {

TEST(PlotScale, TheCollisionRatesTitleNamesItsWindowOfSimulatedTime) {
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(1.0 / 60.0)), "collisions/s, last 0.5 s");
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(0.002)), "collisions/s, last 0.5 s");
    // A dt that does not divide the window: two figures of what it is (26 samples of 0.019 s).
    EXPECT_NEAR(Monitor::rateWindow(0.019), 0.494, 1e-12);
    EXPECT_EQ(collisionRateTitle(Monitor::rateWindow(0.019)), "collisions/s, last 0.49 s");
}

/// Whether the lines [a, a + h) and [b, b + h) share a pixel row.
bool overlap(float a, float b, float h) {
    return a < b + h && b < a + h;
}

TEST(PlotRows, NoTitleOrCaptionSitsOnATickLabel) {
    // At 200 % (a 28-pixel line) a plot's title sat on its top tick label ("175", "100"), and the
    // time axis's caption "t (s)" on the last plot's bottom one ("-100"). A tick label is a line
    // high, centred on its tick; the top and bottom ticks are at the axis's ends.
    for (const float line : {14.f, 17.f, 21.f, 28.f, 34.f}) {
        const float scale = line / 14.f;
        for (int rows = 1; rows <= 4; ++rows) {
            for (const float rowHeight :
                 {kPlotRowMaxHeight * scale, 0.8f * kPlotRowMaxHeight * scale}) {
                const float y = 40.f;
                const PlotRowsPlace p = plotRowsPlace(y, rows, rowHeight, line);
                ASSERT_EQ(p.rows.size(), static_cast<std::size_t>(rows));
                const float frameBottom = y + static_cast<float>(rows) * rowHeight + 8.f;
                for (int k = 0; k < rows; ++k) {
                    const PlotRowPlace& r = p.rows[static_cast<std::size_t>(k)];
                    const std::string at = "line " + std::to_string(line) + ", plot " +
                                           std::to_string(k + 1) + " of " + std::to_string(rows);
                    EXPECT_LT(r.top, r.bottom) << at;
                    EXPECT_GE(r.title, y) << at;
                    const float topLabel = r.top - line / 2.f, bottomLabel = r.bottom - line / 2.f;
                    EXPECT_FALSE(overlap(r.title, topLabel, line))
                        << at << ": title on the top label";
                    if (k + 1 < rows) {
                        const float next = p.rows[static_cast<std::size_t>(k) + 1].title;
                        EXPECT_FALSE(overlap(next, bottomLabel, line))
                            << at << ": the next title on the bottom label";
                    } else {
                        EXPECT_FALSE(overlap(p.timeLabels, bottomLabel, line))
                            << at << ": t (s) on the bottom label";
                        EXPECT_LE(p.timeLabels + line, frameBottom) << at << ": below the frame";
                    }
                }
            }
        }
    }
}

TEST(PlotScale, AnAxisWithRoomForThreeLabelsHasThreeLabelledTicks) {
    // The lesson's plots at 200 % read one number each ("3.50", "-1.0"): a flat energy, a
    // momentum that steps from -1 to 4 at the wall.
    struct Case {
        double lo, hi;
    };
    for (const Case c : {Case{3.48, 3.52}, Case{-1.5, 4.5}, Case{1.0, 5.0}, Case{-1.02, -0.98},
                         Case{0.0, 6.0}, Case{0.0, 1.0}, Case{-10.1, -10.0}}) {
        for (int most = 3; most <= 5; ++most) {
            const AxisTicks t = axisTicks(c.lo, c.hi, most);
            std::string at = std::to_string(c.lo);
            at += " to ";
            at += std::to_string(c.hi);
            at += " with room for ";
            at += std::to_string(most);
            EXPECT_GE(t.values.size(), 3u) << at;
            EXPECT_LE(t.values.size(), static_cast<std::size_t>(most)) << at;
            for (std::size_t k = 0; k < t.values.size(); ++k) {
                EXPECT_GE(t.values[k], c.lo - 1e-9 * (c.hi - c.lo)) << at;
                EXPECT_LE(t.values[k], c.hi + 1e-9 * (c.hi - c.lo)) << at;
                // Each its own label: no two read the same.
                if (k > 0) {
                    EXPECT_NE(tickLabel(t.values[k], t.step), tickLabel(t.values[k - 1], t.step))
                        << at;
                }
            }
        }
    }
}

TEST(PlotRows, ARowAtItsLeastHeightHasRoomForThreeTickLabels) {
    // At 200 % a plot's row was 128 pixels of which its axis had one line: one tick.
    for (const double scale : {0.75, 1.0, 1.5, 2.0, 3.0}) {
        const float line = static_cast<float>(17.0 * scale);  // the charts' line, at most
        const float rowHeight = static_cast<float>(kPlotRowMinHeight * scale);
        for (int rows = 1; rows <= 4; ++rows) {
            const PlotRowsPlace p = plotRowsPlace(40.f, rows, rowHeight, line);
            for (const PlotRowPlace& r : p.rows) {
                EXPECT_GE(yTickCount(r.bottom - r.top, static_cast<int>(line)), kPlotTicksLeast)
                    << "at " << scale << ", " << rows << " rows";
            }
        }
    }
}

}  // namespace
}  // namespace psb::app
