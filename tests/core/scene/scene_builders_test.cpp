// The scene builders' limits: one packing limit, the physical one (kMaxPackingFraction, shared
// with the generate block), and a clear refusal, never a hang, for what cannot be placed.

#include <gtest/gtest.h>

#include <string>

#include <particle_sandbox/error.hpp>
#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/scene_builders.hpp>

namespace psb {
namespace {

template <class F>
std::string refusal(F&& build) {
    try {
        (void)build();
    } catch (const InvalidArgument& e) {
        return e.what();
    }
    return "(built)";
}

TEST(ScenesGas, PlacesDiscsOfOneRadiusAtAnyPackingTheirLatticeHolds) {
    EXPECT_EQ(scenes::gas({.count = 1000, .packing = 0.7}).particles.size(), 1000u);
    // The lattice of a large box comes within a part in a few hundred of π/4.
    EXPECT_EQ(scenes::gas({.count = 100000, .packing = 0.78}).particles.size(), 100000u);
}

TEST(ScenesGas, APackingAbovePiOverFourIsRefusedNamingTheLimit) {
    EXPECT_DOUBLE_EQ(kMaxPackingFraction, 0.7853981633974483);
    EXPECT_EQ(refusal([] { return scenes::gas({.count = 10, .packing = 0.79}); }),
              "scenes::gas: packing must be in [1e-12, 0.7853981633974483] (got 0.79)");
    EXPECT_EQ(refusal([] { return scenes::brownian({.count = 10, .packing = 0.79}); }),
              "scenes::brownian: packing must be in [1e-12, 0.7853981633974483] (got 0.79)");
}

TEST(ScenesGas, ACountTheBoxesLatticeCannotHoldIsRefusedWithHowManyItHolds) {
    // 1000 discs at 0.785 need a box of 63.26 m, 31.6 diameters: 31 x 31 = 961 sites.
    EXPECT_EQ(refusal([] { return scenes::gas({.count = 1000, .packing = 0.785}); }),
              "scenes::gas: packing 0.785 is too dense for 1000 discs: their 63.26159070143723 m "
              "box holds at most 961 on the square lattice");
}

TEST(ScenesGas, MixedRadiiThatJamAreRefusedWithHowFarTheyGot) {
    const std::string why =
        refusal([] { return scenes::gas({.count = 1000, .maxRadius = 1.1, .packing = 0.6}); });
    EXPECT_EQ(why.rfind("scenes::gas: packing 0.6 is too dense to place discs of radii 1 to 1.1 m "
                        "at random: disc ",
                        0),
              0u)
        << why;
    EXPECT_NE(why.find("found no room in 100000 tries"), std::string::npos) << why;
    // Widely spread radii fill the gaps between the large ones, up to the same limit.
    EXPECT_EQ(scenes::gas({.count = 1000, .maxRadius = 10.0, .packing = kMaxPackingFraction})
                  .particles.size(),
              1000u);
}

TEST(GenerateBlock, TakesPackingsUpToTheSameLimitAsTheBuilders) {
    // A 300 m box holds 149 x 149 = 22201 sites of 2 m; 0.77 asks for 22058 discs.
    const Scene s = parseScene(R"({"version": 1, "world": {"width": 300, "height": 300},
                                   "generate": {"packing": 0.77, "radius": 1}})",
                               "g.json");
    EXPECT_EQ(s.particles.size(), 22058u);
    try {
        (void)parseScene(R"({"version": 1, "generate": {"packing": 0.79, "radius": 1}})", "g.json");
        ADD_FAILURE() << "accepted a packing above pi/4";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(),
                     "g.json: generate.packing: must be from 0 to 0.7853981633974483 (π/4, the "
                     "densest a square lattice of discs can be; got 0.79)");
    }
}

}  // namespace
}  // namespace psb
