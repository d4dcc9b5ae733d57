// Suggestions for unknown keys and names.

#include <gtest/gtest.h>

#include <string>

#include <particle_sandbox/detail/nearest_name.hpp>

namespace psb::detail {
namespace {

TEST(NearestName, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("gravity", "gravity"), 0u);
    EXPECT_EQ(editDistance("gravty", "gravity"), 1u);
    EXPECT_EQ(editDistance("raduis", "radius"), 2u);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
}

TEST(NearestName, SuggestsTheNearestNameOnlyWhenItIsClose) {
    EXPECT_EQ(suggestion("partciles", {"version", "particles", "world"}),
              " (did you mean 'particles'?)");
    EXPECT_EQ(suggestion("substeps", {"discrete", "substep", "exact"}),
              " (did you mean 'substep'?)");
    EXPECT_EQ(suggestion("zzz", {"x", "y"}), " (expected one of: x, y)");
    EXPECT_EQ(suggestion(std::string(100000, 'a'), {"x", "y"}), " (expected one of: x, y)");
}

}  // namespace
}  // namespace psb::detail
