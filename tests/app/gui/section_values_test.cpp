// The values table docked in the window (gui/section_values.cpp): where it goes at each UI
// scale, and that the lessons' and the ramp's columns and rows show their numbers whole.

#include "control_panel_fixture.hpp"
#include "gui/widgets.hpp"

namespace psb::app {
namespace {

class SectionValuesTest : public ControlPanelTest {};

TEST_F(SectionValuesTest, TheValuesTableStaysInTheWindowAndOffTheBoxAtEveryScale) {
    // At 200 % the table's window ran off the window's right edge; at 125 % it covered half of
    // the box. Docked where the view keeps room for it, it does neither, at every size.
    for (const auto& [width, height] : {std::pair{800, 600}, {1024, 768}, {1600, 1000}}) {
        for (const float scale : {1.f, 1.25f, 2.f}) {
            const std::string at = std::to_string(width) + "x" + std::to_string(height) + " at " +
                                   std::to_string(scale);
            SessionOptions so;
            so.paused = true;
            so.viewportWidth = width;
            so.viewportHeight = height;
            so.layout = windowLayout(*font_, width, height, controlsWidth(scale, width));
            so.controls = so.layout.controlsFit;
            Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                      so);
            s.apply(cmd::SetShow{ShowOption::Values, true});
            gui_->setScale(scale);
            ControlPanel panel;
            for (int k = 0; k < 3; ++k) {
                gui_->beginFrame(static_cast<float>(width), static_cast<float>(height));
                for (const Command& c :
                     panel.build(s, FrameStats{}, static_cast<float>(height) / scale, scale))
                    s.apply(c);
                EXPECT_EQ(gui_->endFrame(), 0);
            }
            const PanelItem* w = panel.item("values window");
            ASSERT_NE(w, nullptr) << at;
            const float x0 = w->x0 * scale, y0 = w->y0 * scale, x1 = w->x1 * scale,
                        y1 = w->y1 * scale;
            EXPECT_GE(x0, 0.f) << at;
            EXPECT_LE(x1, static_cast<float>(width) + 0.5f) << at << ": off the right edge";
            EXPECT_LE(y1, static_cast<float>(height) + 0.5f) << at;
            // Under the box or beside it (a short window docks it at the right), never over it.
            const Camera::ScreenBox box =
                s.camera().boxOnScreen(s.world().def().width, s.world().def().height);
            const bool under = y0 >= box.topLeft.y() + box.size.y() - 0.5;
            const bool beside = x0 >= box.topLeft.x() + box.size.x() - 0.5;
            EXPECT_TRUE(under || beside) << at << ": over the box";
        }
    }
    gui_->setScale(1.f);
}

TEST_F(SectionValuesTest, TheLessonsValuesTableShowsEveryColumnAndRowWithoutScrolling) {
    // The momentum lesson's two balls on a projector: at 200 % the table's py, KE and mass
    // were scrolled off to the right (each field kept room for "-0.0000e-00") and the totals
    // row was under the scroll bar (the band chosen held one row, for a box 5 % larger).
    Scene lesson;
    lesson.world.width = 10.0;
    lesson.world.height = 4.0;
    for (const auto& [x, vx, mass] : {std::tuple{2.0, 2.0, 1.0}, {7.0, -1.0, 3.0}}) {
        ParticleDef p;
        p.position = {x, 2.0};
        p.velocity = {vx, 0.0};
        p.radius = 0.3;
        p.mass = mass;
        lesson.particles.push_back(p);
    }
    struct Case {
        int width, height;
        float scale;
    };
    for (const Case& c : {Case{1600, 1000, 2.f}, Case{1600, 1000, 1.25f}, Case{1280, 800, 1.5f},
                          Case{1024, 768, 1.f}, Case{1024, 768, 1.25f}}) {
        const std::string at = std::to_string(c.width) + "x" + std::to_string(c.height) + " at " +
                               std::to_string(c.scale);
        SessionOptions so;
        so.paused = true;
        so.viewportWidth = c.width;
        so.viewportHeight = c.height;
        so.layout = windowLayout(*font_, c.width, c.height, controlsWidth(c.scale, c.width));
        so.controls = so.layout.controlsFit;
        Session s(makeWorld(lesson), SceneInfo{.name = "lesson", .dt = 1.0 / 60.0}, so);
        s.apply(cmd::SetShow{ShowOption::Values, true});
        gui_->setScale(c.scale);
        ControlPanel panel;
        for (int k = 0; k < 3; ++k) {
            gui_->beginFrame(static_cast<float>(c.width), static_cast<float>(c.height));
            for (const Command& command :
                 panel.build(s, FrameStats{}, static_cast<float>(c.height) / c.scale, c.scale))
                s.apply(command);
            EXPECT_EQ(gui_->endFrame(), 0);
        }
        const PanelItem* w = panel.item("values window");
        ASSERT_NE(w, nullptr) << at;
        // Inside the window's padding: a cell past it makes the table scroll sideways.
        const float right = w->x1 - ImGui::GetStyle().WindowPadding.x;
        const ValuesTable t = valuesTable(s.world(), std::nullopt, s.axes());
        for (const ValuesColumn& column : t.columns) {
            for (const std::string row : {"values 2 ", "values total "}) {
                const PanelItem* cell = panel.item(row + column.name);
                ASSERT_NE(cell, nullptr) << at << ": " << row << column.name;
                EXPECT_LE(cell->x1, right + 0.5f)
                    << at << ": " << row << column.name << " " << cell->x1 << " > " << right
                    << " is right of the table's window";
                EXPECT_LE(cell->y1, w->y1 + 0.5f)
                    << at << ": " << row << column.name << " is below the table's window";
            }
        }
    }
    gui_->setScale(1.f);
}

TEST_F(SectionValuesTest, UnitsUnderTheHeadersNeverRunIntoEachOther) {
    // At 200 % the momentum columns' units read as one: "kg m/skg m/s", the border between
    // them hidden under the letters (5 points apart, a space's width). Between two columns'
    // units there is at least the width of two spaces, in the lesson's table and in the ramp's
    // (its omega, rad/s), at every scale.
    Scene lesson;
    lesson.world.width = 10.0;
    lesson.world.height = 4.0;
    for (const auto& [x, vx, mass] : {std::tuple{2.0, 2.0, 1.0}, {7.0, -1.0, 3.0}}) {
        ParticleDef p;
        p.position = {x, 2.0};
        p.velocity = {vx, 0.0};
        p.radius = 0.3;
        p.mass = mass;
        lesson.particles.push_back(p);
    }
    const Scene ramp = loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / "12-ramp.json");
    for (const Scene* scene : std::initializer_list<const Scene*>{&lesson, &ramp}) {
        for (const float scale : {1.f, 1.5f, 2.f}) {
            const std::string at =
                std::string(scene == &lesson ? "lesson" : "ramp") + " at " + std::to_string(scale);
            SessionOptions so;
            so.paused = true;
            so.viewportWidth = 1600;
            so.viewportHeight = 1000;
            so.layout = windowLayout(*font_, 1600, 1000, controlsWidth(scale, 1600));
            so.controls = so.layout.controlsFit;
            Session s(makeWorld(*scene), SceneInfo{.name = "table", .dt = 1.0 / 60.0}, so);
            s.apply(cmd::SetShow{ShowOption::Values, true});
            gui_->setScale(scale);
            ControlPanel panel;
            for (int k = 0; k < 3; ++k) {
                gui_->beginFrame(1600.f, 1000.f);
                for (const Command& command : panel.build(s, FrameStats{}, 1000.f / scale, scale))
                    s.apply(command);
                EXPECT_EQ(gui_->endFrame(), 0);
            }
            const float air = 2.f * ImGui::CalcTextSize(" ").x;
            const ValuesTable t = valuesTable(s.world(), std::nullopt, s.axes());
            const PanelItem* before = nullptr;
            for (const ValuesColumn& column : t.columns) {
                const PanelItem* unit = panel.item(std::string("values unit ") + column.name);
                ASSERT_NE(unit, nullptr) << at << ": " << column.name;
                if (before != nullptr) {
                    EXPECT_GE(unit->x0 - before->x1, air - 0.5f)
                        << at << ": " << column.unit << " of " << column.name
                        << " against the one before";
                }
                before = unit;
            }
        }
    }
    gui_->setScale(1.f);
}

TEST_F(SectionValuesTest, TheRampsValuesTableKeepsEveryColumnAsWideAsItsNumbers) {
    // The ramp's table (its bodies turn: omega and KE rot join the columns) at 200 %: the KE
    // column was as narrow as "KE" at rest and its numbers ran into the next once the bodies
    // moved, and where the table scrolled sideways nothing said so. Each column is as wide
    // at rest as in motion and no cell runs into the next; where the window holds every
    // column none is out of sight, and where it cannot the table says which are and how to
    // reach them, the particles' numbers staying at the left.
    struct Case {
        int width, height;
        float scale;
    };
    for (const Case& c : {Case{1600, 1000, 2.f}, Case{1600, 1000, 1.5f}, Case{1920, 1200, 1.5f},
                          Case{1024, 768, 1.25f}}) {
        const std::string at = std::to_string(c.width) + "x" + std::to_string(c.height) + " at " +
                               std::to_string(c.scale);
        SessionOptions so;
        so.paused = true;
        so.viewportWidth = c.width;
        so.viewportHeight = c.height;
        so.layout = windowLayout(*font_, c.width, c.height, controlsWidth(c.scale, c.width));
        so.controls = so.layout.controlsFit;
        Session s(
            makeWorld(loadScene(std::filesystem::path(PSB_ASSETS_DIR) / "scenes" / "12-ramp.json")),
            SceneInfo{.name = "ramp", .dt = 0.002}, so);
        ASSERT_TRUE(s.world().rotationInUse());
        s.apply(cmd::SetShow{ShowOption::Values, true});
        gui_->setScale(c.scale);
        ControlPanel panel;
        const auto frames = [&] {
            for (int k = 0; k < 3; ++k) {
                gui_->beginFrame(static_cast<float>(c.width), static_cast<float>(c.height));
                for (const Command& command :
                     panel.build(s, FrameStats{}, static_cast<float>(c.height) / c.scale, c.scale))
                    s.apply(command);
                EXPECT_EQ(gui_->endFrame(), 0);
            }
        };
        const ValuesTable t = valuesTable(s.world(), std::nullopt, s.axes());
        const auto starts = [&] {
            std::vector<float> x;
            for (const ValuesColumn& column : t.columns) {
                const PanelItem* cell = panel.item(std::string("values 1 ") + column.name);
                x.push_back(cell != nullptr ? cell->x0 : -1.f);
            }
            return x;
        };
        frames();
        const std::vector<float> atRest = starts();
        // The race a second and a half on: 3.34 m/s, KE 6.31 J, omega -29.6 rad/s.
        for (const ParticleId id : s.world().ids()) {
            s.apply(cmd::EditParticle{id, ParticleField::Vx, "3.339"});
            s.apply(cmd::EditParticle{id, ParticleField::Vy, "-1.21"});
            s.apply(cmd::EditParticle{id, ParticleField::Omega, "-29.62"});
        }
        frames();
        EXPECT_EQ(starts(), atRest) << at << ": the columns moved as the numbers changed";
        const PanelItem* w = panel.item("values window");
        ASSERT_NE(w, nullptr) << at;
        const float right = w->x1 - ImGui::GetStyle().WindowPadding.x;
        const bool scrolls = panel.item("values more columns") != nullptr;
        for (const std::string row : {"values 1 ", "values 2 ", "values 3 ", "values total "}) {
            const PanelItem* before = nullptr;
            for (const ValuesColumn& column : t.columns) {
                const PanelItem* cell = panel.item(row + column.name);
                if (cell == nullptr) continue;  // the totals of x, y, vx, vy, omega: none
                if (before != nullptr) {
                    EXPECT_LE(before->x1, cell->x0 + 0.5f)
                        << at << ": " << row << "runs into " << column.name;
                }
                before = cell;
                if (!scrolls) {
                    EXPECT_LE(cell->x1, right + 0.5f)
                        << at << ": " << row << column.name << " out of sight, unsaid";
                }
            }
        }
        const PanelItem* number = panel.item("values row 1");
        ASSERT_NE(number, nullptr) << at;
        EXPECT_GE(number->x0, w->x0) << at << ": the particles' numbers stay";
        if (c.width == 1920) {
            EXPECT_FALSE(scrolls) << at << ": the window holds every column";
        }
    }
    gui_->setScale(1.f);
}

}  // namespace
}  // namespace psb::app

namespace psb::app {
namespace {

TEST(ValuesTableFrozenColumn, ItsCellsAreOpaqueTheRowsStripeOverTheWindow) {
    // Scrolled sideways, the table's numbers slid under the frozen "#" column and showed
    // through its translucent stripe (section_values.cpp fills its cells with this).
    const ImVec4 window{0.94f, 0.94f, 0.94f, 0.98f}, stripe{0.30f, 0.30f, 0.30f, 0.09f};
    const ImVec4 cell = widgets::opaqueOver(window, stripe);
    EXPECT_FLOAT_EQ(cell.w, 1.f) << "opaque";
    EXPECT_NEAR(cell.x, 0.94f * 0.91f + 0.30f * 0.09f, 1e-6f) << "the stripe over the window";
    const ImVec4 none = widgets::opaqueOver(window, ImVec4{0.f, 0.f, 0.f, 0.f});
    EXPECT_FLOAT_EQ(none.x, 0.94f);
    EXPECT_FLOAT_EQ(none.w, 1.f);
}

}  // namespace
}  // namespace psb::app
