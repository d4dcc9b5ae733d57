// The values table as rows (values_table.hpp): signed values by particle number, the totals
// over every particle, and only the selected row in a crowd.

#include <gtest/gtest.h>

#include <cmath>

#include "view/values_table.hpp"

namespace psb::app {
namespace {

World twoBalls() {
    WorldDef def;
    def.width = 10.0;
    def.height = 4.0;
    World w(def);
    w.add({.position = Vec2(2.0, 2.0), .velocity = Vec2(2.0, 0.0), .mass = 1.0, .radius = 0.4});
    w.add({.position = Vec2(7.0, 2.0), .velocity = Vec2(-1.0, 0.5), .mass = 3.0, .radius = 0.6});
    return w;
}

TEST(ValuesTable, SignedValuesByNumberAndTheirTotals) {
    const World w = twoBalls();
    const ValuesTable t = valuesTable(w, std::nullopt);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0].number, 1u);
    EXPECT_EQ(t.rows[1].number, 2u);
    // x, y, vx, vy, px, py, KE, mass
    EXPECT_EQ(t.rows[1].values[2], -1.0);
    EXPECT_EQ(t.rows[1].values[4], -3.0) << "a ball moving left has px < 0";
    EXPECT_EQ(t.rows[1].values[5], 1.5);
    EXPECT_DOUBLE_EQ(t.rows[1].values[6], 0.5 * 3.0 * 1.25);
    EXPECT_TRUE(std::isnan(t.totals[0])) << "no sum of positions";
    EXPECT_EQ(t.totals[4], -1.0);
    EXPECT_EQ(t.totals[5], 1.5);
    EXPECT_DOUBLE_EQ(t.totals[6], 2.0 + 1.875);
    EXPECT_EQ(t.totals[7], 4.0);
    EXPECT_TRUE(t.note.empty());
    const auto lines = valuesLines(t);
    EXPECT_EQ(lines[0],
              "#\tx (m)\ty (m)\tvx (m/s)\tvy (m/s)\tpx (kg m/s)\tpy (kg m/s)\tKE (J)\tmass (kg)");
    EXPECT_EQ(lines[2], "2\t7.00\t2.00\t-1.00\t0.500\t-3.00\t1.50\t1.88\t3.00");
    EXPECT_EQ(lines[3], "total\t\t\t\t\t-1.00\t1.50\t3.88\t4.00");
}

TEST(ValuesTable, WithRotationInUseOmegaAndTheRotationalEnergyJoinTheColumns) {
    World w = twoBalls();
    const ParticleId second = w.ids().back();
    w.setAngularVelocity(second, -5.0);
    w.setInertiaFactor(second, 0.4);
    const ValuesTable t = valuesTable(w, std::nullopt);
    ASSERT_EQ(t.columns.size(), 10u);
    ASSERT_EQ(t.rows[1].values.size(), 10u);
    // x, y, vx, vy, omega, px, py, KE, KE rot, mass
    EXPECT_EQ(t.rows[1].values[4], -5.0);
    EXPECT_EQ(t.rows[0].values[4], 0.0);
    const double rot = 0.5 * 0.4 * 3.0 * 0.36 * 25.0;  // ½ k m r² ω² = 5.4 J
    EXPECT_DOUBLE_EQ(t.rows[1].values[8], rot);
    EXPECT_TRUE(std::isnan(t.totals[4])) << "no sum of angular velocities";
    EXPECT_DOUBLE_EQ(t.totals[8], rot);
    EXPECT_EQ(t.totals[9], 4.0);
    const auto lines = valuesLines(t);
    EXPECT_EQ(lines[0],
              "#\tx (m)\ty (m)\tvx (m/s)\tvy (m/s)\t\u03c9 (rad/s)\tpx (kg m/s)\tpy (kg "
              "m/s)\tKE (J)\tKE rot (J)\tmass (kg)");
    EXPECT_EQ(lines[2], "2\t7.00\t2.00\t-1.00\t0.500\t-5.00\t-3.00\t1.50\t1.88\t5.40\t3.00");
    EXPECT_EQ(lines[3], "total\t\t\t\t\t\t-1.00\t1.50\t3.88\t5.40\t4.00");
}

TEST(ValuesTable, WithYUpHeightsFromTheFloorUpwardComponentsAndTurningCounterclockwise) {
    World w = twoBalls();
    w.setAngularVelocity(w.ids().back(), -5.0);  // counterclockwise on screen
    const ValuesTable t = valuesTable(w, std::nullopt, Axes{true, 4.0});
    // x, y, vx, vy, omega, px, py, KE, KE rot, mass; the 4 m box's second ball at y = 2 (down)
    // moving at vy = 0.5 down the screen.
    EXPECT_EQ(t.rows[1].values[1], 2.0);
    EXPECT_EQ(t.rows[0].values[1], 2.0);
    EXPECT_EQ(t.rows[1].values[3], -0.5) << "moving down: negative with y up";
    EXPECT_EQ(t.rows[1].values[4], 5.0) << "counterclockwise: positive with y up";
    EXPECT_EQ(t.rows[1].values[6], -1.5);
    EXPECT_EQ(t.totals[6], -1.5) << "the total py, upward";
    EXPECT_DOUBLE_EQ(t.totals[7], 2.0 + 1.875) << "energies do not change";
    EXPECT_EQ(t.axes, "y up from the floor; vy, py up; \u03c9 counterclockwise (Show: y up)");
    EXPECT_EQ(valuesLines(t).back(), t.axes);
    World moved = twoBalls();
    moved.setPosition(moved.ids().front(), Vec2(2.0, 3.5));
    EXPECT_EQ(valuesTable(moved, std::nullopt, Axes{true, 4.0}).rows[0].values[1], 0.5)
        << "0.5 m above the floor";
    EXPECT_EQ(valuesTable(moved, std::nullopt).axes,
              "y down from the top edge; vy, py down (Show: y up is off)");
}

TEST(ValuesTable, ACrowdListsTheSelectedRowAndTheTotalsOfAll) {
    WorldDef def;
    def.width = def.height = 100.0;
    World w(def);
    ParticleId last;
    for (std::size_t k = 0; k <= kValuesMaxRows; ++k) {
        last = w.add({.position = Vec2(1.0 + static_cast<double>(k), 50.0),
                      .velocity = Vec2(1.0, 0.0),
                      .radius = 0.2});
    }
    ValuesTable t = valuesTable(w, std::nullopt);
    EXPECT_TRUE(t.rows.empty());
    EXPECT_NE(t.note.find("61 particles: the totals of all"), std::string::npos) << t.note;
    EXPECT_NE(t.note.find("(click one)"), std::string::npos);
    EXPECT_EQ(t.totals[7], static_cast<double>(kValuesMaxRows + 1));
    t = valuesTable(w, last);
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_EQ(t.rows[0].id, last);
}

}  // namespace
}  // namespace psb::app
