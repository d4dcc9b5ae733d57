// The bins panel's words (legend and verdict, from the same counts the chart draws), the
// dropper's label, and the session's keeping of a scene's bins (shown by default, switched in
// the Show section, kept by save and undo). The chart's drawing: render/bin_chart_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <particle_sandbox/presets.hpp>
#include <particle_sandbox/scene.hpp>

#include "session/session.hpp"
#include "session/test_assets.hpp"
#include "temp_dir_test.hpp"
#include "view/bin_histogram.hpp"
#include "view/bins_fixture.hpp"
#include "view/box_area.hpp"
#include "view/fixed_measure.hpp"
#include "view/frame_view.hpp"

namespace psb::app {
namespace {

using test::eightRows;
using test::kBell;
using test::landed;

TEST(BinHistogram, SaysInWordsWhatTheBarsDotsAndCurveAreAndHowFarTheCountsAreFromIt) {
    const BinHistogram h = binHistogram(eightRows(), landed(kBell, 12));
    ASSERT_EQ(h.legend.size(), 4u);
    EXPECT_EQ(
        h.legend[0],
        "bars: balls in bins 0 to 8, marked on the board (1000 landed, 12 not yet in the bins)");
    EXPECT_EQ(h.legend[1], "dots: binomial, 8 rows, p = 1/2");
    EXPECT_EQ(h.legend[2], "line: normal curve (mean 4, spread 1.41 bins)");
    EXPECT_EQ(h.legend[3].rfind("close to the curve: chi-squared ", 0), 0u) << h.legend[3];
    EXPECT_NE(h.legend[3].find("< 16.8"), std::string::npos) << h.legend[3];
    EXPECT_EQ(h.now.counts.counts[4], 273u);
    EXPECT_NEAR(h.now.expected[4], 1000.0 * 70.0 / 256.0, 1e-9);
}

TEST(BinHistogram, AFlatPileIsFarFromTheCurveAndAFewBallsAreTooFewToJudge) {
    const BinHistogram flat = binHistogram(eightRows(), landed(std::vector<int>(9, 100)));
    EXPECT_EQ(flat.legend[3].rfind("far from the curve: chi-squared ", 0), 0u) << flat.legend[3];
    EXPECT_NE(flat.legend[3].find("> 16.8"), std::string::npos) << flat.legend[3];
    const BinHistogram few = binHistogram(eightRows(), landed({0, 0, 0, 1, 2, 1}, 900));
    EXPECT_EQ(
        few.legend[0],
        "bars: balls in bins 0 to 8, marked on the board (4 landed, 900 not yet in the bins)");
    EXPECT_EQ(few.legend[3], "too few balls yet to compare with the curve");
}

TEST(BinHistogram, BinsWithoutAnExpectationOnlyCount) {
    Bins b = eightRows();
    b.binomial.reset();
    ParticleArrays p = landed({1, 2});
    p.x.push_back(-3.0);  // below the top, left of the bins
    p.y.push_back(6.0);
    const BinHistogram h = binHistogram(b, p);
    ASSERT_EQ(h.legend.size(), 1u);
    EXPECT_EQ(h.legend[0],
              "bars: balls in bins 0 to 8, marked on the board (3 landed, 1 outside the bins)");
    EXPECT_TRUE(h.now.expected.empty());
}

TEST(BinHistogram, TheNormalCurveHasTheBinomialsMeanSpreadAndTotal) {
    const BinomialExpectation b{8, 0.5};
    double sum = 0.0;
    for (int i = -400; i <= 1200; ++i)
        sum += normalCount(i / 100.0, b, 1000.0) / 100.0;
    EXPECT_NEAR(sum, 1000.0, 1e-3);  // the tails beyond 5.6 sigma are left out
    EXPECT_NEAR(normalCount(4.0, b, 1000.0), 1000.0 / (std::sqrt(2.0) * std::sqrt(2.0 * M_PI)),
                1e-9);
    EXPECT_LT(normalCount(5.0, b, 1000.0), normalCount(4.0, b, 1000.0));
    EXPECT_EQ(normalCount(1.0, {3, 1.0}, 10.0), 0.0);  // no spread: no curve
    EXPECT_EQ(probabilityText(0.5), "1/2");
    EXPECT_EQ(probabilityText(0.25), "0.25");
}

class SessionBinsTest : public TempDirTest {
  protected:
    SessionBinsTest() : TempDirTest("psb-session-bins") {}
    [[nodiscard]] Session session() const {
        SessionOptions o;
        o.saveTo = dir_ / "save.json";
        o.paused = true;
        o.layout = windowLayout(test::FixedMeasure{}, o.viewportWidth, o.viewportHeight, {});
        return Session(makeWorld(psb::defaultScene()),
                       SceneInfo{.name = "default", .dt = 1.0 / 60.0}, o);
    }
    void writeBoard() const {
        std::ofstream(dir_ / "board.json") << R"({"version": 3, "name": "board",
            "world": {"width": 1, "height": 1},
            "bins": {"edges": [0, 0.5, 1], "top": 0.5,
                     "expected": {"binomial": {"trials": 1, "p": 0.5}}}})";
    }
};

TEST_F(SessionBinsTest, AScenesBinsAreShownUnlessSwitchedOffAndKeptBySaveAndUndo) {
    Session s = session();
    EXPECT_FALSE(s.meta().bins);
    EXPECT_FALSE(s.binsShown());  // the default scene has none
    writeBoard();
    s.apply(cmd::OpenFile{dir_ / "board.json"});
    ASSERT_TRUE(s.meta().bins);
    EXPECT_EQ(s.meta().bins->edges, (std::vector<double>{0, 0.5, 1}));
    EXPECT_TRUE(s.binsShown());
    s.apply(cmd::SetShow{cmd::ShowOption::Bins, false});
    EXPECT_FALSE(s.binsShown());
    s.apply(cmd::SetShow{cmd::ShowOption::Bins, true});
    EXPECT_TRUE(s.binsShown());

    s.apply(cmd::SaveAs{dir_ / "saved.json"});
    EXPECT_EQ(loadScene(dir_ / "saved.json").bins, s.meta().bins);

    s.apply(cmd::OpenFile{testAsset("scenes/01-original.json")});
    EXPECT_FALSE(s.meta().bins);
    EXPECT_FALSE(s.binsShown());
    s.apply(cmd::Undo{});  // back to the board, bins and all
    ASSERT_TRUE(s.meta().bins);
    EXPECT_TRUE(s.binsShown());
    s.apply(cmd::Restart{});
    EXPECT_TRUE(s.meta().bins);
}

TEST_F(SessionBinsTest, TheGaltonPresetHasBinsForEachRowCount) {
    Session s = session();
    s.apply(cmd::OpenFile{testAsset("scenes/09-galton-board.json")});
    ASSERT_TRUE(s.meta().bins);
    ASSERT_TRUE(s.meta().bins->binomial);
    EXPECT_EQ(s.meta().bins->size(), static_cast<std::size_t>(s.meta().bins->binomial->trials) + 1);
    EXPECT_TRUE(s.binsShown());
}

TEST_F(SessionBinsTest, TheGaltonBoardsDropperCountsDownAndSaveAndResetKeepItsState) {
    Session s = session();
    s.apply(cmd::OpenFile{testAsset("scenes/09-galton-board.json")});
    ASSERT_EQ(s.world().droppers().size(), 1u);
    EXPECT_EQ(s.world().droppers()[0].balls, 1000u);
    EXPECT_EQ(s.world().size(), 0u);
    // Half a second of frames (1/60 s each): a ball every 0.05 s from t = 0.
    for (int k = 0; k < 30; ++k) {
        s.apply(cmd::SingleStep{});
        s.update(0.0, 0.0);
    }
    EXPECT_EQ(s.world().droppers()[0].balls, 990u);
    EXPECT_EQ(s.world().size(), 10u);
    // The legend counts the balls still in the dropper.
    const BinHistogram h = binHistogram(*s.meta().bins, s.world().particles(), 990);
    EXPECT_EQ(h.legend[0],
              "bars: balls in bins 0 to 8, marked on the board (0 landed, 10 not yet "
              "in the bins, 990 still to drop)");
    EXPECT_EQ(dropperLabel(s.world().droppers()[0]), "dropper: 990 balls left");
    // Saved with how far it has got; reset gives the full dropper back.
    s.apply(cmd::SaveAs{dir_ / "galton.json"});
    const Scene saved = loadScene(dir_ / "galton.json");
    ASSERT_EQ(saved.droppers.size(), 1u);
    EXPECT_EQ(saved.droppers[0], s.world().droppers()[0]);
    EXPECT_EQ(saved.particles.size(), 10u);
    s.apply(cmd::Restart{});
    EXPECT_EQ(s.world().droppers()[0].balls, 1000u);
    EXPECT_EQ(s.world().droppers()[0].released, 0u);
    EXPECT_EQ(s.world().size(), 0u);
}

TEST(DropperLabel, SaysHowManyBallsAreLeftInWords) {
    Dropper d;
    d.balls = 1;
    EXPECT_EQ(dropperLabel(d), "dropper: 1 ball left");
    d.balls = 0;
    EXPECT_EQ(dropperLabel(d), "dropper: empty");
}

}  // namespace
}  // namespace psb::app
