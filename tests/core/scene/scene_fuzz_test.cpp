// Nothing crashes on any input: mutated scene files are either loaded or refused with a
// SceneError, never anything else. Run it under -DPSB_SANITIZE=ON to catch undefined
// behaviour too.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

std::vector<std::string> seeds() {
    std::vector<std::string> texts;
    const std::filesystem::path corpus = std::filesystem::path(PSB_TEST_DATA_DIR) / "scene_corpus";
    for (const char* dir : {"good", "bad"}) {
        for (const auto& entry : std::filesystem::directory_iterator(corpus / dir)) {
            std::ifstream in(entry.path(), std::ios::binary);
            std::ostringstream s;
            s << in.rdbuf();
            texts.push_back(s.str());
        }
    }
    return texts;
}

TEST(SceneFuzz, MutatedScenesAreLoadedOrRefusedButNeverCrash) {
    // Bytes that steer mutations towards interesting JSON: structure, signs, exponents.
    const std::string interesting = "{}[]\":,-+.eE0123456789 \n\\tfn";
    std::mt19937 rng(12345);
    int loaded = 0, refused = 0;
    for (const std::string& seed : seeds()) {
        for (int round = 0; round < 60; ++round) {
            std::string text = seed;
            const int edits = 1 + static_cast<int>(rng() % 4);
            for (int k = 0; k < edits && !text.empty(); ++k) {
                const std::size_t at = rng() % text.size();
                const char c = (rng() % 2) ? interesting[rng() % interesting.size()]
                                           : static_cast<char>(rng() % 256);
                switch (rng() % 3) {
                    case 0:
                        text[at] = c;
                        break;
                    case 1:
                        text.insert(text.begin() + static_cast<long>(at), c);
                        break;
                    default:
                        text.erase(at, 1 + rng() % 8);
                        break;
                }
            }
            try {
                (void)parseScene(text, "fuzz.json");
                ++loaded;
            } catch (const SceneError& e) {
                ++refused;
                ASSERT_EQ(std::string(e.what()).rfind("fuzz.json: ", 0), 0u) << e.what();
            }
        }
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace psb
