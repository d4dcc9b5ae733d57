// The `bins` field of a scene file: read, written back bit for bit, and absent from scenes
// that do not use it (the bad files are in scene_corpus/bad, bins_*.json).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

constexpr const char* kBoard = R"({"version": 3, "world": {"width": 0.3, "height": 0.5},
  "bins": {"edges": [0.05, 0.1, 0.15, 0.2], "top": 0.4,
           "expected": {"binomial": {"trials": 2, "p": 0.5}}}})";

TEST(SceneBins, AreReadWithTheirEdgesTopAndExpectedDistribution) {
    const Scene s = parseScene(kBoard, "board.json");
    ASSERT_TRUE(s.bins);
    EXPECT_EQ(s.bins->edges, (std::vector<double>{0.05, 0.1, 0.15, 0.2}));
    EXPECT_EQ(s.bins->size(), 3u);
    EXPECT_EQ(s.bins->top, 0.4);
    ASSERT_TRUE(s.bins->binomial);
    EXPECT_EQ(s.bins->binomial->trials, 2);
    EXPECT_EQ(s.bins->binomial->p, 0.5);
}

TEST(SceneBins, ExpectedIsOptional) {
    const Scene s = parseScene(
        R"({"version": 3, "world": {"width": 1, "height": 1},
            "bins": {"edges": [0, 0.25, 1], "top": 0.5}})",
        "b.json");
    ASSERT_TRUE(s.bins);
    EXPECT_FALSE(s.bins->binomial);
    EXPECT_EQ(s.bins->size(), 2u);
}

TEST(SceneBins, AScenewithoutBinsHasNoneAndIsWrittenWithout) {
    const Scene s = parseScene(R"({"version": 2, "world": {"width": 1, "height": 1}})", "s.json");
    EXPECT_FALSE(s.bins);
    const std::string text = serializeScene(s);
    EXPECT_EQ(text.find("bins"), std::string::npos);
    EXPECT_NE(text.find("\"version\": 2"), std::string::npos);  // not raised to 3
}

TEST(SceneBins, RoundTripBitForBitAndRaiseTheVersionToThree) {
    Scene s = parseScene(kBoard, "board.json");
    s.version = 1;
    s.bins->edges[1] = 0.1 + 0.2 / 30.0;  // an awkward double
    s.bins->top = std::nextafter(0.4, 0.0);
    s.bins->binomial->p = 1.0 / 3.0;
    const std::string text = serializeScene(s);
    EXPECT_NE(text.find("\"version\": 3"), std::string::npos);
    const Scene back = parseScene(text, "mem");
    EXPECT_EQ(back.bins, s.bins);
    EXPECT_EQ(serializeScene(back), text);
}

TEST(SceneBins, ABinomialNeedsOneBinPerNumberOfSuccesses) {
    EXPECT_NO_THROW((void)parseScene(kBoard, "b.json"));
    std::string three = kBoard;
    three.replace(three.find("\"trials\": 2"), 11, "\"trials\": 3");
    try {
        (void)parseScene(three, "b.json");
        FAIL() << "accepted 3 trials over 3 bins";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(),
                     "b.json: bins.expected.binomial.trials: 3 trials need 4 bins (0 to 3 "
                     "successes), the edges make 3");
    }
}

}  // namespace
}  // namespace psb
