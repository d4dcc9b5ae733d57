// The control panel without a window: a session, the panel built in an offscreen ImGui frame,
// mouse input fed through ImGui's io, and the commands it returns applied as the app applies
// them. Each test clicks or drags a control by its name and checks what changed.

#include "control_panel_fixture.hpp"

namespace psb::app {
namespace {

TEST_F(ControlPanelTest, EverySectionAndItsMainControlsAreThere) {
    click("section Tools");  // closed at first
    for (const char* name : {"section Time",
                             "Play/Pause",
                             "Step",
                             "Restart",
                             "Speed",
                             "section Scene",
                             "section Physics",
                             "mode Discrete",
                             "mode Substeps",
                             "mode Exact",
                             "Restitution",
                             "Friction",
                             "Roughness",
                             "Discs turn",
                             "Gravity",
                             "g",
                             "Walls",
                             "section Show",
                             "Velocity arrows",
                             "Labels",
                             "Spin",
                             "Momentum and centre of mass",
                             "Plots",
                             "Speed histogram",
                             "Trails",
                             "section Tools",
                             "tool Fling",
                             "tool Launch",
                             "tool Select",
                             "tool Pan",
                             "launch mass",
                             "launch radius",
                             "auto radius",
                             "launch colour",
                             "section Readouts",
                             "section Selected particle",
                             "section All particles",
                             "section Engine",
                             "fold panel"}) {
        EXPECT_NE(panel_.item(name), nullptr) << name;
    }
    // Every control is inside the panel's column.
    for (const PanelItem& i : panel_.items()) {
        EXPECT_LE(i.x1, kControlsWidth) << i.name;
        EXPECT_GE(i.x0, 0.f) << i.name;
    }
}

TEST_F(ControlPanelTest, TheOpenPanelTakesAShareOfTheWindowAndEveryControlFitsInIt) {
    // At 200 % in a 1600-pixel window the panel took 620 pixels, 39 % of it, and beside the
    // plots the box kept 510. Open it takes at most 30 % of the window, within 240 to 310
    // points; at its narrowest every section open, a particle selected, nothing runs past its
    // edge.
    EXPECT_FLOAT_EQ(controlsOpenPoints(1600.0, 2.0), 240.f) << "1600 pixels at 200 %";
    EXPECT_LE(controlsWidth(2.0, 1600).open, 0.3 * 1600 + 0.5);
    EXPECT_FLOAT_EQ(controlsOpenPoints(1280.0, 2.0), kControlsMinWidth) << "1280 at 200 %";
    EXPECT_FLOAT_EQ(controlsOpenPoints(1920.0, 2.0), 288.f) << "1920 at 200 %";
    // At 100 % the panel is as it was designed, whatever the window; a little bigger, never
    // narrower on screen.
    for (const double window : {600.0, 800.0, 1600.0})
        EXPECT_FLOAT_EQ(controlsOpenPoints(window, 1.0), kControlsWidth) << window;
    EXPECT_GE(controlsWidth(1.25, 800).open, 310.0 - 0.5);

    session_->apply(cmd::Select{session_->world().ids()[0]});
    // At 200 % in a window 1600 pixels wide and tall enough for every section open at once.
    constexpr float kScale = 2.f, kTall = 6000.f;
    gui_->setScale(kScale);
    ImGuiIO& io = gui_->io();
    const auto tallFrame = [&] {
        gui_->beginFrame(1600.f, kTall * kScale);
        for (const Command& c : panel_.build(*session_, FrameStats{}, kTall, kScale))
            session_->apply(c);
        EXPECT_EQ(gui_->endFrame(), 0);
    };
    tallFrame();
    tallFrame();
    for (const char* name : {"section Scene", "section Tools", "section Data", "section Video",
                             "section All particles", "section Engine", "section Readouts",
                             "section Selected particle", "section Last collision"}) {
        const PanelItem* header = panel_.item(name);
        if (header == nullptr) continue;
        io.MousePos = ImVec2(header->x0 + 20.f, (header->y0 + header->y1) / 2.f);
        tallFrame();
        io.MouseDown[0] = true;
        tallFrame();
        io.MouseDown[0] = false;
        tallFrame();
    }
    io.MousePos = ImVec2(795.f, kTall - 5.f);
    tallFrame();
    // The sections stay open in a window as high as the projector's (500 points): the panel
    // scrolls, its scroll bar at its right.
    for (int k = 0; k < 3; ++k) {
        gui_->beginFrame(1600.f, 1000.f);
        for (const Command& c : panel_.build(*session_, FrameStats{}, 500.f, kScale))
            session_->apply(c);
        EXPECT_EQ(gui_->endFrame(), 0);
    }
    const PanelItem* fold = panel_.item("fold panel");
    ASSERT_NE(fold, nullptr);
    EXPECT_LE(fold->x1, kControlsMinWidth + 0.5f) << "the panel's width";
    EXPECT_GT(fold->x1, kControlsMinWidth - 40.f) << "the panel's width";
    // Where ImGui clips the panel's content: half its padding left of the scroll bar (a
    // section's header reaches into the rest, as ImGui draws it).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float edge = kControlsMinWidth - style.ScrollbarSize - style.WindowPadding.x / 2.f;
    for (const PanelItem& i : panel_.items()) {
        if (i.name.rfind("values", 0) == 0) continue;  // the values table's own window
        const bool header = i.name.rfind("section ", 0) == 0;
        EXPECT_LE(i.x1, edge + (header ? style.WindowPadding.x / 2.f : 0.f) + 0.5f)
            << i.name << " runs past the panel's edge";
    }
    // No control is drawn over another: a row of three check boxes drew the next one over the
    // end of the label before it ("Velocity arro", "Labe", "Values tab").
    expectNoOverlap(panel_.items());
    gui_->setScale(1.f);
}

TEST_F(ControlPanelTest, NoControlOverlapsAnotherNorRunsPastTheEdgeAtAnyScaleOrWindow) {
    // The rows of the Show section at fixed fractions of the panel's width drew a check box
    // over the end of the label before it at 200 %; every row wraps now, at 100 to 250 % in a
    // window from 800 x 600 up, every section open and a particle selected.
    session_->apply(cmd::Select{session_->world().ids()[0]});
    session_->apply(cmd::SetShow{ShowOption::Collision, true});
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_NE(w, nullptr);
    for (const char* section : {"Scene", "Tools", "Video", "Data", "All particles", "Engine",
                                "Readouts", "Selected particle", "Last collision"})
        w->StateStorage.SetInt(ImHashStr(section, 0, w->ID), 1);
    const ImGuiStyle& style = ImGui::GetStyle();
    for (const float scale : {1.f, 1.25f, 1.5f, 2.f, 2.5f}) {
        for (const auto& [width, height] :
             {std::pair{800.f, 600.f}, std::pair{1024.f, 768.f}, std::pair{1600.f, 1000.f}}) {
            gui_->setScale(scale);
            for (int k = 0; k < 3; ++k) {
                gui_->beginFrame(width, height);
                for (const Command& c :
                     panel_.build(*session_, FrameStats{}, height / scale, scale))
                    session_->apply(c);
                EXPECT_EQ(gui_->endFrame(), 0);
            }
            w = ImGui::FindWindowByName("Controls");
            const float edge = w->Pos.x + w->Size.x - (w->ScrollbarY ? style.ScrollbarSize : 0.f) -
                               style.WindowPadding.x / 2.f;
            SCOPED_TRACE(::testing::Message() << width << " x " << height << " at " << scale);
            for (const PanelItem& i : panel_.items()) {
                if (i.name.rfind("values", 0) == 0) continue;
                const bool header = i.name.rfind("section ", 0) == 0;
                EXPECT_LE(i.x1, edge + (header ? style.WindowPadding.x / 2.f : 0.f) + 0.5f)
                    << i.name << " runs past the panel's edge";
            }
            expectNoOverlap(panel_.items());
        }
    }
    gui_->setScale(1.f);
}

TEST_F(ControlPanelTest, PlayPauseAndStepAreTheSessionsCommands) {
    ASSERT_TRUE(session_->paused());
    const double t0 = session_->world().time();
    click("Step");
    session_->update(0.0, 0.0);
    EXPECT_GT(session_->world().time(), t0);
    click("Play/Pause");
    EXPECT_FALSE(session_->paused());
    click("Play/Pause");
    EXPECT_TRUE(session_->paused());
}

TEST_F(ControlPanelTest, AButtonWhoseWordsChangeStaysTheSameControl) {
    // The keyboard's cursor holds a control by ImGui's identity: were it the words, Play
    // turning into Pause would leave the cursor on nothing and a second Space would do nothing.
    const auto idOf = [this](const std::string& name) {
        frame();
        const PanelItem* i = panel_.item(name);
        EXPECT_NE(i, nullptr) << name;
        return i != nullptr ? i->id : 0u;
    };
    const unsigned play = idOf("Play/Pause");
    const unsigned start = idOf("Stopwatch start");
    click("Play/Pause");
    ASSERT_FALSE(session_->paused());
    EXPECT_EQ(idOf("Play/Pause"), play) << "Pause is the Play button";
    click("Stopwatch start");
    ASSERT_TRUE(session_->stopwatch().running());
    EXPECT_EQ(idOf("Stopwatch start"), start) << "Stop is the Start button";

    // The Data section, below the window's bottom: opened, and recording started, directly.
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_NE(w, nullptr);
    w->StateStorage.SetInt(ImHashStr("Data", 0, w->ID), 1);
    const unsigned record = idOf("Record");
    session_->apply(cmd::SetRecording{true, 1});
    ASSERT_TRUE(session_->data().recording());
    EXPECT_EQ(idOf("Record"), record) << "Stop recording is the Record button";
}

TEST_F(ControlPanelTest, TabWalksThroughButtonsToPlayAndSpaceStartsAndStopsTime) {
    // ImGui 1.86 tabs through fields only (Tab from the box landed in Speed, typing its value)
    // and, from a button, goes back to the top: a keyboard user could not reach Play by Tab.
    const auto navId = [this] {
        (void)gui_->io();  // makes the context current
        return static_cast<unsigned>(ImGui::GetCurrentContext()->NavId);
    };
    const auto key = [this](SDL_Keycode k, Uint16 mod = KMOD_NONE) {  // Tab or Space
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.keysym.sym = k;
        e.key.keysym.scancode = k == SDLK_TAB ? SDL_SCANCODE_TAB : SDL_SCANCODE_SPACE;
        e.key.keysym.mod = mod;
        // Pressed and released between two frames, as a quick tap (or xdotool) does: ImGui
        // 1.86 reads the keys' state at the frame, and must still see the press.
        const bool taken = gui_->handleEvent(e);
        e.type = SDL_KEYUP;
        gui_->handleEvent(e);
        frame();
        frame();
        return taken;
    };
    const PanelItem* play = panel_.item("Play/Pause");
    ASSERT_NE(play, nullptr);
    int tabs = 0;
    while (navId() != play->id && tabs < 8) {
        EXPECT_TRUE(key(SDLK_TAB));
        ++tabs;
    }
    ASSERT_EQ(navId(), play->id) << "Tab did not reach Play in 8 presses";
    EXPECT_LE(tabs, 3) << "the fold button and the Time section come before Play";
    EXPECT_FALSE(gui_->io().WantTextInput) << "no field is being typed in";

    ASSERT_TRUE(session_->paused());
    EXPECT_TRUE(key(SDLK_SPACE)) << "Space is the focused button's";
    EXPECT_FALSE(session_->paused()) << "Space pressed Play";
    EXPECT_EQ(navId(), play->id) << "the cursor stays on the button, now Pause";
    EXPECT_TRUE(key(SDLK_SPACE));
    EXPECT_TRUE(session_->paused()) << "a second Space pressed Pause";

    // Tab goes on from the cursor (not back to the top), and Shift+Tab comes back.
    EXPECT_TRUE(key(SDLK_TAB));
    EXPECT_EQ(navId(), panel_.item("Step")->id);
    EXPECT_TRUE(key(SDLK_TAB));
    EXPECT_EQ(navId(), panel_.item("Restart")->id);
    EXPECT_TRUE(key(SDLK_TAB, KMOD_LSHIFT));
    EXPECT_EQ(navId(), panel_.item("Step")->id);
    // Space on Step: one step, the cursor still there.
    const double t0 = session_->world().time();
    EXPECT_TRUE(key(SDLK_SPACE));
    session_->update(0.0, 0.0);
    EXPECT_GT(session_->world().time(), t0);
    EXPECT_EQ(navId(), panel_.item("Step")->id);
}

TEST_F(ControlPanelTest, EnterAndTheKeypadsEnterPressTheFocusedButtonAsSpaceDoes) {
    // ImGui 1.86 gives Enter to fields only: on a focused button it did nothing.
    const auto navId = [this] {
        (void)gui_->io();
        return static_cast<unsigned>(ImGui::GetCurrentContext()->NavId);
    };
    const auto key = [this](SDL_Keycode k, SDL_Scancode code) {
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.keysym.sym = k;
        e.key.keysym.scancode = code;
        const bool taken = gui_->handleEvent(e);
        e.type = SDL_KEYUP;
        gui_->handleEvent(e);
        frame();
        frame();
        return taken;
    };
    const PanelItem* play = panel_.item("Play/Pause");
    ASSERT_NE(play, nullptr);
    for (int tabs = 0; navId() != play->id && tabs < 8; ++tabs)
        key(SDLK_TAB, SDL_SCANCODE_TAB);
    ASSERT_EQ(navId(), play->id);
    ASSERT_TRUE(session_->paused());
    EXPECT_TRUE(key(SDLK_RETURN, SDL_SCANCODE_RETURN));
    EXPECT_FALSE(session_->paused()) << "Enter pressed Play";
    EXPECT_EQ(navId(), play->id);
    EXPECT_TRUE(key(SDLK_KP_ENTER, SDL_SCANCODE_KP_ENTER));
    EXPECT_TRUE(session_->paused()) << "the keypad's Enter pressed Pause";
    EXPECT_TRUE(key(SDLK_RETURN, SDL_SCANCODE_RETURN));
    EXPECT_FALSE(session_->paused()) << "once per press, not held";
    EXPECT_FALSE(gui_->io().WantTextInput) << "a button starts no typing";
}

TEST_F(ControlPanelTest, NoLineOfThePanelRunsPastItsRightEdge) {
    // Every section open, its vertical scroll bar shown: a line wider than the room left
    // beside it was cut at the panel's edge ("...to see its va", a preset's description, the
    // saved file's path). ImGui keeps the right end of everything laid out in the window.
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_NE(w, nullptr);
    // Opened as a click would (their headers are below the window once the others are open).
    for (const char* section : {"Scene", "Tools", "Video", "Data", "All particles", "Engine"})
        w->StateStorage.SetInt(ImHashStr(section, 0, w->ID), 1);
    frame();
    frame();
    EXPECT_TRUE(w->ScrollbarY) << "the case: the scroll bar takes its width from the lines";
    EXPECT_LE(w->DC.CursorMaxPos.x, w->WorkRect.Max.x + 1.f)
        << "something is laid out " << w->DC.CursorMaxPos.x - w->WorkRect.Max.x
        << " points past the panel's right edge";
}

TEST_F(ControlPanelTest, ACheckboxSetsItsOption) {
    click("Walls");
    EXPECT_FALSE(session_->world().def().walls);
    click("Labels");
    EXPECT_TRUE(session_->view().labels);
    click("Gravity");
    EXPECT_EQ(session_->world().def().gravity, Vec2(0.0, 9.81));
}

TEST_F(ControlPanelTest, DraggingTheRestitutionSliderToItsLeftEndIsOneUserAction) {
    const PanelItem* r = panel_.item("Restitution");
    ASSERT_NE(r, nullptr);
    const auto actions = session_->userActions();
    drag("Restitution", ImVec2(r->x0 - 20.f, (r->y0 + r->y1) / 2.f));
    EXPECT_DOUBLE_EQ(session_->world().def().restitution, 0.0);
    EXPECT_EQ(session_->userActions(), actions + 1);
    EXPECT_EQ(session_->lastAction(), "set restitution");
}

TEST_F(ControlPanelTest, ModesAreChosenInEveryScene) {
    click("mode Substeps");
    EXPECT_EQ(session_->world().solver().mode, StepMode::Substep);
    EXPECT_EQ(session_->world().solver().substeps, 4);
    click("mode Exact");
    EXPECT_EQ(session_->world().solver().mode, StepMode::Exact);
    click("mode Discrete");

    World pegs(session_->world().def());
    pegs.addObstacle(Obstacle::peg(Vec2(3.5, 3.5), 0.2));
    session_->setWorld(std::move(pegs), SceneInfo{.name = "pegs", .dt = Scene{}.dt});
    frame();
    click("mode Exact");  // obstacles are in every mode
    EXPECT_EQ(session_->world().solver().mode, StepMode::Exact);
}

TEST_F(ControlPanelTest, ToolsAreChosenByTheirRadioButtons) {
    click("section Physics");
    click("section Show");
    click("section Tools");
    click("tool Pan");
    EXPECT_EQ(session_->tool(), cmd::Tool::Pan);
    click("tool Select");
    EXPECT_EQ(session_->tool(), cmd::Tool::Select);
    click("auto radius");  // untick: the radius field now sets the launch radius
    EXPECT_TRUE(session_->spawn().fixedRadius.has_value());
}

TEST_F(ControlPanelTest, TheObstacleToolsHaveRadioButtonsSizesAndADeleteButton) {
    click("section Physics");
    click("section Show");
    click("section Tools");
    click("tool Wall");
    EXPECT_EQ(session_->tool(), cmd::Tool::Wall);
    click("tool Peg");
    EXPECT_EQ(session_->tool(), cmd::Tool::Peg);
    EXPECT_NE(panel_.item("peg radius"), nullptr);
    EXPECT_NE(panel_.item("wall thickness"), nullptr);
    EXPECT_EQ(panel_.item("delete obstacle"), nullptr);  // nothing selected
    // A peg placed in an empty corner of the box and clicked with the Select tool.
    const Camera& c = session_->camera();
    const Vec2 at = c.worldToScreen(Vec2(1.0, 6.0));
    session_->apply(cmd::PointerDown{at, 1.0});
    session_->apply(cmd::PointerUp{at, 1.05});
    ASSERT_EQ(session_->world().obstacles().size(), 1u);
    click("tool Select");
    session_->apply(cmd::PointerDown{at, 2.0});
    session_->apply(cmd::PointerUp{at, 2.05});
    ASSERT_EQ(session_->selectedObstacle(), 0u);
    frame();
    click("delete obstacle");
    EXPECT_TRUE(session_->world().obstacles().empty());
}

TEST_F(ControlPanelTest, APresetIsOpenedByItsName) {
    click("section Scene");
    click("preset Newton's cradle");
    EXPECT_EQ(session_->meta().name, "Newton's cradle");
}

TEST_F(ControlPanelTest, OpeningAFileDoesNotMoveTheControlsBelowTheRecentList) {
    click("section Scene");
    ASSERT_TRUE(session_->recentFiles().empty());
    ASSERT_NE(panel_.item("Recent files"), nullptr) << "there, greyed, before any file";
    // Two files whose paths are as long: the second adds a recent file, and nothing moves.
    session_->apply(cmd::OpenFile{findAsset("scenes/02-newtons-cradle.json")});
    frame();
    frame();
    const PanelItem* physics = panel_.item("section Physics");
    ASSERT_NE(physics, nullptr);
    const float before = physics->y0;
    session_->apply(cmd::OpenFile{findAsset("scenes/03-billiards-break.json")});
    frame();
    frame();
    ASSERT_EQ(session_->recentFiles().size(), 2u);
    EXPECT_EQ(panel_.item("section Physics")->y0, before)
        << "the recent files take one line however many there are";
}

TEST_F(ControlPanelTest, EveryReadoutsNameEndsBeforeItsValueBegins) {
    // Under gravity (the "Mechanical energy" row), with text larger and larger against the
    // panel's width (as a narrower panel would be): the names' column is as wide as its widest
    // name, and the values wrap at spaces in the rest.
    const auto& presets = session_->presets();
    const auto galton = std::find_if(presets.begin(), presets.end(), [](const SceneListing& p) {
        return p.name == "Galton board";
    });
    ASSERT_NE(galton, presets.end());
    session_->apply(cmd::OpenPreset{static_cast<int>(galton - presets.begin())});
    for (const float pixels : {15.f, 19.f, 23.f}) {
        // A new context: ImGui keeps a table's column widths from the frames that laid it out.
        GuiOptions o;
        o.font = findAsset("fonts/DejaVuSans.ttf");
        o.fontPixels = pixels;
        gui_ = std::make_unique<GuiContext>(sdl_, o);
        frame();
        frame();
        for (const char* name :
             {"Time", "Particles", "Kinetic energy", "Mechanical energy", "Momentum", "  size"}) {
            const PanelItem* label = panel_.item(std::string("readout ") + name);
            const PanelItem* value = panel_.item(std::string("readout ") + name + " value");
            ASSERT_NE(label, nullptr) << name;
            ASSERT_NE(value, nullptr) << name;
            EXPECT_LT(label->x1, value->x0)
                << name << " at " << pixels << " px: its name runs into its value";
            EXPECT_LE(value->x1, kControlsWidth)
                << name << " at " << pixels << " px: its value runs out of the panel";
        }
    }
}

TEST_F(ControlPanelTest, AReadoutsValueKeepsMoreThanHalfTheRow) {
    // The gas at 200 %: the names' column, as wide as "Pressure, measured", left the value
    // "12.2 N/m \u00b1 0.362 N/m" a third of the panel, over three lines. The names take at
    // most 45 % now, a longer one wrapping in it; with the large text of a narrow panel too.
    const auto& presets = session_->presets();
    const auto galton = std::find_if(presets.begin(), presets.end(), [](const SceneListing& p) {
        return p.name == "Galton board";
    });
    ASSERT_NE(galton, presets.end());
    session_->apply(cmd::OpenPreset{static_cast<int>(galton - presets.begin())});
    GuiOptions o;
    o.font = findAsset("fonts/DejaVuSans.ttf");
    o.fontPixels = 23.f;
    gui_ = std::make_unique<GuiContext>(sdl_, o);
    frame();
    frame();
    const ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_NE(w, nullptr);
    const float room = w->ContentRegionRect.GetWidth();
    for (const char* name : {"Time", "Kinetic energy", "Mechanical energy", "Momentum"}) {
        const PanelItem* label = panel_.item(std::string("readout ") + name);
        const PanelItem* value = panel_.item(std::string("readout ") + name + " value");
        ASSERT_NE(label, nullptr) << name;
        ASSERT_NE(value, nullptr) << name;
        EXPECT_LE(value->x0 - label->x0, 0.45f * room + 2.f * ImGui::GetStyle().CellPadding.x + 1.f)
            << name << ": the names' column leaves its value less than half the row";
        EXPECT_LT(label->x1, value->x0) << name << ": its name runs into its value";
    }
}

TEST_F(ControlPanelTest, TheSelectedParticleTableAppearsWithEditableFields) {
    EXPECT_EQ(panel_.item("selected mass"), nullptr);
    session_->apply(cmd::Select{session_->world().ids().front()});
    frame();
    for (const char* f : {"selected x", "selected y", "selected vx", "selected vy", "selected mass",
                          "selected radius"}) {
        EXPECT_NE(panel_.item(f), nullptr) << f;
    }
    // Far down the panel: fold the sections above it.
    for (const char* section : {"section Physics", "section Show", "section Readouts"})
        click(section);
    click("deselect");
    EXPECT_FALSE(session_->selected());
}

TEST_F(ControlPanelTest, TextTypedForOneParticleGoesToItWhenAClickSelectsAnother) {
    const std::vector<ParticleId> ids = session_->world().ids();
    ASSERT_GE(ids.size(), 2u);
    const ParticleId first = ids.front(), second = ids.back();
    const double secondMass = session_->world().get(second).mass;
    for (const bool toAnother : {true, false}) {
        session_->apply(cmd::Select{first});
        frame();
        if (toAnother) {  // far down the panel: fold the sections above it, once
            for (const char* section : {"section Physics", "section Show", "section Readouts"})
                click(section);
        }
        ImGuiIO& io = gui_->io();
        io.MousePos = centre("selected mass");
        frame();
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
        const char* typed = toAnother ? "4" : "5";
        io.AddInputCharacter(static_cast<unsigned>(typed[0]));
        frame();
        // A click in the box: the session selects another particle (or none), and the click
        // leaves the field, which applies what was typed.
        session_->apply(cmd::Select{toAnother ? second : kNullParticle});
        io.MousePos = ImVec2(kSize - 5.f, kSize / 2.f);
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
        frame();
        EXPECT_EQ(session_->world().get(first).mass, toAnother ? 4.0 : 5.0)
            << "the text goes to the particle it was typed for";
        EXPECT_EQ(session_->world().get(second).mass, secondMass) << "not to the one clicked";
    }
}

TEST_F(ControlPanelTest, TheDescriptionReadsWrappedAndAClickEditsIt) {
    if (panel_.item("description") == nullptr) click("section Scene");
    ASSERT_NE(panel_.item("description"), nullptr);
    ASSERT_NE(panel_.item("description edit"), nullptr) << "shown as text, with an Edit button";
    const std::string before = session_->meta().description;
    click("description");
    EXPECT_EQ(panel_.item("description edit"), nullptr) << "now the field";
    ImGuiIO& io = gui_->io();
    frame();
    for (const char c : std::string(" More."))
        io.AddInputCharacter(static_cast<unsigned>(c));
    frame();
    io.MousePos = ImVec2(kSize - 5.f, kSize / 2.f);  // a click elsewhere keeps it
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    frame();
    EXPECT_NE(session_->meta().description, before);
    EXPECT_NE(session_->meta().description.find("More."), std::string::npos)
        << session_->meta().description;
    EXPECT_NE(panel_.item("description edit"), nullptr) << "back to the wrapped text";
}

TEST_F(ControlPanelTest, CtrlSInAFieldKeepsItsTextThenGoesToTheApp) {
    // Ctrl+S right after typing the description did nothing: the field took every key. Now the
    // field keeps its text first (as Enter would), and once that frame is built the app has
    // the shortcut; plain letters, S among them, stay the field's.
    if (panel_.item("description") == nullptr) click("section Scene");
    click("description");
    frame();
    const auto send = [this](Uint32 type, SDL_Keycode sym, Uint16 mod, const char* text) {
        SDL_Event e{};
        e.type = type;
        if (type == SDL_TEXTINPUT) {
            std::snprintf(e.text.text, sizeof e.text.text, "%s", text);
        } else {
            e.key.keysym.sym = sym;
            e.key.keysym.scancode = SDL_GetScancodeFromKey(sym);
            e.key.keysym.mod = mod;
        }
        return gui_->handleEvent(e);
    };
    for (const char c : std::string(" same mass")) {
        const char text[2] = {c, '\0'};
        const SDL_Keycode sym = c == ' ' ? SDLK_SPACE : static_cast<SDL_Keycode>(c);
        EXPECT_TRUE(send(SDL_KEYDOWN, sym, KMOD_NONE, nullptr)) << c << " is the field's";
        EXPECT_TRUE(send(SDL_TEXTINPUT, 0, KMOD_NONE, text));
        send(SDL_KEYUP, sym, KMOD_NONE, nullptr);
    }
    EXPECT_TRUE(send(SDL_KEYDOWN, SDLK_s, KMOD_LCTRL, nullptr)) << "not the app's at once";
    send(SDL_KEYUP, SDLK_s, KMOD_LCTRL, nullptr);
    std::vector<SDL_Event> forApp;
    for (int k = 0; k < 30 && forApp.empty(); ++k) {
        frame();
        forApp = gui_->takeAppKeys();
    }
    ASSERT_EQ(forApp.size(), 1u) << "the app has Ctrl+S";
    EXPECT_EQ(forApp[0].key.keysym.sym, SDLK_s);
    EXPECT_NE(forApp[0].key.keysym.mod & KMOD_CTRL, 0);
    EXPECT_NE(session_->meta().description.find(" same mass"), std::string::npos)
        << "kept before the app acts: " << session_->meta().description;
    frame();  // ImGui's flags tell of the frame before
    frame();
    EXPECT_FALSE(gui_->io().WantTextInput) << "the field is closed";
    EXPECT_NE(panel_.item("description edit"), nullptr) << "the description read as text again";
    // From the panel's cursor (no field typed in) the app has it at once.
    EXPECT_FALSE(send(SDL_KEYDOWN, SDLK_z, KMOD_LCTRL, nullptr) && gui_->hasKeyboard());
}

TEST_F(ControlPanelTest, TheDescriptionWrapsAsItIsTyped) {
    // The field did not wrap: typing, the start of the text went off its left edge.
    if (panel_.item("description") == nullptr) click("section Scene");
    click("description");
    frame();
    ImGuiIO& io = gui_->io();
    const std::string typed =
        " A long sentence typed at the end of the description goes on past the field's width.";
    for (const char c : typed) {
        io.AddInputCharacter(static_cast<unsigned>(c));
        frame();
    }
    const PanelItem* field = panel_.item("description");
    ASSERT_NE(field, nullptr);
    const ImGuiInputTextState* state = ImGui::GetInputTextState(field->id);
    ASSERT_NE(state, nullptr) << "still being typed in";
    EXPECT_EQ(state->ScrollX, 0.f) << "the start of the lines stays in view";
    std::string shown;
    for (int i = 0; i < state->CurLenA; ++i)
        shown += state->TextA[i];
    EXPECT_GE(std::count(shown.begin(), shown.end(), '\n'), 2) << shown;
    io.MousePos = ImVec2(kSize - 5.f, kSize / 2.f);  // a click elsewhere keeps it
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    frame();
    const std::string& kept = session_->meta().description;
    EXPECT_EQ(kept.find('\n'), std::string::npos) << "the lines' breaks are not the text's";
    EXPECT_NE(kept.find(typed), std::string::npos) << kept;
}

TEST_F(ControlPanelTest, TheCollisionCardsVectorsKeepOneLineAt200Percent) {
    // A gas's collision at 200 %: "(-0.236, -0.306)" wrapped onto two lines in the card's
    // columns, which "kinetic energy" in the names' column left too narrow. The names wrap to
    // their longest word instead. In a window wide enough for the whole panel (2400 pixels) a
    // vector keeps one line beside the other; in 1600 pixels, where the panel takes 30 % of
    // the window, it broke after its comma ("(0.694, / -0.0908)"): there before and after go
    // one under the other, each vector on one line.
    WorldDef def;
    def.width = def.height = 4.0;
    World w(def);
    w.add(
        {.position = Vec2(2.0, 2.0), .velocity = Vec2(-0.236, 0.306), .mass = 1.0, .radius = 0.1});
    w.add({.position = Vec2(1.85, 2.2),
           .velocity = Vec2(0.182, -0.0929),
           .mass = 1.0,
           .radius = 0.1});
    for (const int width : {2400, 1600}) {
        SessionOptions so;
        so.paused = true;
        so.viewportWidth = width;
        so.viewportHeight = 1000;
        so.layout = windowLayout(*font_, width, 1000, controlsWidth(2.0, width));
        Session s(World(w), SceneInfo{.name = "pair", .dt = 1.0 / 60.0}, so);
        s.apply(cmd::SetShow{ShowOption::Collision, true});
        s.apply(cmd::TogglePause{});
        for (int k = 1; k <= 60 && !s.lastCollision(); ++k)
            s.update(1.0 / 60.0, k / 60.0);
        ASSERT_TRUE(s.lastCollision());
        gui_->setScale(2.f);
        ControlPanel panel;
        for (int k = 0; k < 3; ++k) {
            gui_->beginFrame(static_cast<float>(width), 1000.f);
            for (const Command& command : panel.build(s, FrameStats{}, 500.f, 2.f))
                s.apply(command);
            EXPECT_EQ(gui_->endFrame(), 0);
        }
        const float line = ImGui::GetTextLineHeightWithSpacing();
        for (const char* name :
             {"collision v 1 before", "collision v 1 after", "collision v 2 before",
              "collision p 1 before", "collision total p after"}) {
            const PanelItem* cell = panel.item(name);
            ASSERT_NE(cell, nullptr) << name;
            EXPECT_LT(cell->y1 - cell->y0, 1.5f * line) << name << " wrapped in " << width;
        }
    }
    gui_->setScale(1.f);
}

TEST_F(ControlPanelTest, ASelectedParticlesValuesComeIntoViewInAnEightHundredPixelWindow) {
    // The Selected particle section is below Time, Physics, Show and Readouts, under the fold
    // of an 800-pixel window: a click on a particle scrolls the panel to it.
    for (const ParticleId id : {session_->world().ids()[1], session_->world().ids()[4]}) {
        session_->apply(cmd::Select{id});
        frame();
        frame();
        for (const char* name : {"section Selected particle", "deselect", "selected x",
                                 "selected mass", "selected radius"}) {
            const PanelItem* i = panel_.item(name);
            ASSERT_NE(i, nullptr) << name;
            EXPECT_GE(i->y0, 0.f) << name;
            EXPECT_LE(i->y1, static_cast<float>(kSize)) << name << " is below the window";
        }
        // The panel stays where the user scrolls it while the selection stays.
        ImGui::SetScrollY(ImGui::FindWindowByName("Controls"), 0.f);
        frame();
        frame();
        EXPECT_GT(panel_.item("selected radius")->y1, static_cast<float>(kSize));
    }
}

TEST_F(ControlPanelTest, ACollisionCardThatGrowsMovesNothingUnderThePointer) {
    // A student reaching for the Data section clicked the collision card instead: the panel
    // scrolled to the card when it was turned on, and the card, growing from "no collision yet"
    // to its table at the first collision, pushed everything below it down.
    const float scrolled = ImGui::FindWindowByName("Controls")->Scroll.y;
    session_->apply(cmd::SetShow{ShowOption::Collision, true});
    frame();
    frame();
    EXPECT_EQ(ImGui::FindWindowByName("Controls")->Scroll.y, scrolled)
        << "turned on, the card does not scroll the panel";
    for (const char* section : {"section Physics", "section Show"})
        click(section);
    ImGuiIO& io = gui_->io();
    io.MousePos = centre("section Data");
    frame();
    frame();
    const float before = panel_.item("section Data")->y0;
    ASSERT_FALSE(session_->lastCollision());
    ASSERT_TRUE(runToACollision());
    frame();
    frame();
    EXPECT_NEAR(panel_.item("section Data")->y0, before, 0.5f)
        << "the card grew and moved the section under the pointer";
}

TEST_F(ControlPanelTest, ACardThatGrowsUnderAFingerMovesNothingBelowItUntilTheFingerLifts) {
    // A tablet: a tap meant for the panel hit "Add a random particle" instead. The card grew a
    // line between the finger coming down and the press it makes at the lift, in a frame where
    // the pointer already counted as pressed: everything below moved under it. While a finger
    // is on the panel (GuiContext::fingerOnPanel: holdLayout), or a button is held over it,
    // nothing below the card moves.
    session_->apply(cmd::SetShow{ShowOption::Collision, true});
    for (const char* section : {"section Physics", "section Show", "section Tools"})
        click(section);
    ImGuiIO& io = gui_->io();
    const ImVec2 finger = centre("Add a random particle");
    const float before = panel_.item("Add a random particle")->y0;
    ASSERT_FALSE(session_->lastCollision());
    session_->apply(cmd::TogglePause{});
    io.MousePos = finger;
    panel_.holdLayout(true);  // the finger came down
    int moved = 0;
    for (int k = 1; k <= 1200 && !session_->lastCollision(); ++k) {
        session_->update(1.0 / 60.0, k / 60.0);
        // Half the frames with the button down, as the press of a tap is.
        io.MouseDown[0] = k % 2 == 0;
        frame();
        if (std::abs(panel_.item("Add a random particle")->y0 - before) > 0.5f) ++moved;
    }
    ASSERT_TRUE(session_->lastCollision());
    session_->apply(cmd::TogglePause{});
    for (int k = 0; k < 4; ++k) {
        io.MouseDown[0] = k % 2 == 0;
        frame();
        if (std::abs(panel_.item("Add a random particle")->y0 - before) > 0.5f) ++moved;
    }
    EXPECT_EQ(moved, 0) << "frames in which the button under the finger moved";
    // Lifted: the card shows whole again.
    io.MouseDown[0] = false;
    panel_.holdLayout(false);
    io.MousePos = ImVec2(kSize - 5.f, kSize - 5.f);
    frame();
    frame();
    EXPECT_NE(panel_.item("collision title"), nullptr);
    EXPECT_GT(panel_.item("Add a random particle")->y0, before + 40.f) << "the card below";
}

TEST_F(ControlPanelTest, OnATouchScreenEveryButtonAndBoxIsAFingersTarget) {
    // A tablet at the automatic scale: Step, Lap, Reset and the Show section's boxes were about
    // 20 pixels tall. On a touch screen each is at least kTouchTargetPoints (40) high and
    // wide, at any UI scale; with a mouse the panel is as it was.
    const auto sizes = [this](float scale) {
        session_->apply(cmd::SetUiScale{scale, false});
        gui_->setScale(scale);
        for (int k = 0; k < 3; ++k) {  // tall enough for every control
            gui_->beginFrame(kSize, 4000.f);
            for (const Command& c : panel_.build(*session_, FrameStats{}, 4000.f / scale, scale))
                session_->apply(c);
            EXPECT_EQ(gui_->endFrame(), 0);
        }
    };
    const char* targets[] = {"fold panel",    "Play/Pause",
                             "Step",          "Restart",
                             "Undo",          "Stopwatch start",
                             "Stopwatch lap", "Stopwatch reset",
                             "section Show",  "Velocity arrows",
                             "Labels",        "y up",
                             "Spin",          "Grid",
                             "Ruler",         "Auto"};
    sizes(1.f);  // the Show section is open from the start
    const PanelItem* mouseStep = panel_.item("Step");
    ASSERT_NE(mouseStep, nullptr);
    EXPECT_LT(mouseStep->y1 - mouseStep->y0, 30.f) << "with a mouse, as it was";
    session_->apply(cmd::SetTouch{true});
    for (const float scale : {1.f, 1.5f, 2.f}) {
        sizes(scale);
        for (const char* name : targets) {
            const std::string n = std::string(name) == "Auto" ? "UI scale auto" : name;
            const PanelItem* i = panel_.item(n);
            ASSERT_NE(i, nullptr) << n;
            EXPECT_GE((i->y1 - i->y0) * scale, kTouchTargetPoints - 0.5f) << n << " at " << scale;
            EXPECT_GE((i->x1 - i->x0) * scale, kTouchTargetPoints - 0.5f) << n << " at " << scale;
        }
        // Bigger boxes take a row's room: a box that no longer fits beside another goes below
        // it (the Labels box lay over "Velocity arrows", Spin's over "Values table").
        const char* boxes[] = {"Velocity arrows",
                               "Labels",
                               "y up",
                               "Momentum and centre of mass",
                               "Plots",
                               "Speed histogram",
                               "Values table",
                               "Spin",
                               "Grid",
                               "Last collision card",
                               "Ruler",
                               "Walls",
                               "Discs turn"};
        for (const char* a : boxes)
            for (const char* b : boxes) {
                const PanelItem *p = panel_.item(a), *q = panel_.item(b);
                if (p == nullptr || q == nullptr || p == q) continue;
                const bool overlap =
                    p->x0 < q->x1 && q->x0 < p->x1 && p->y0 < q->y1 && q->y0 < p->y1;
                EXPECT_FALSE(overlap) << a << " and " << b << " at " << scale;
            }
    }
    gui_->setScale(1.f);
}

TEST_F(ControlPanelTest, OnAPhoneAtAnyScaleThePanelAndItsCloseButtonStayOnScreen) {
    // A phone held upright at 150 %: the sheet ran off the right edge and its << was a 2-pixel
    // sliver a tap missed. The sheet is as wide as the window, and the scale in use is no more
    // than the window allows (mostUiScale): << is whole, at the right edge, at any scale
    // chosen, from 320 pixels wide up.
    for (const float window : {320.f, 390.f, 600.f}) {
        for (const double chosen : {1.0, 1.5, 2.0, 3.0}) {
            SessionOptions so;
            so.paused = true;
            so.touch = true;
            so.viewportWidth = static_cast<int>(window);
            so.viewportHeight = 844;
            Session s(makeWorld(defaultScene()), SceneInfo{.name = "default", .dt = 1.0 / 60.0},
                      so);
            s.apply(cmd::FitUiScale{mostUiScale(window)});
            s.apply(cmd::SetUiScale{chosen, false});
            const auto scale = static_cast<float>(s.view().uiScaleInUse());
            s.apply(cmd::Resize{
                static_cast<int>(window), 844,
                windowLayout(*font_, static_cast<int>(window), 844, controlsWidth(scale, window))});
            if (!s.controlsShown()) s.apply(cmd::ToggleControls{});
            ASSERT_TRUE(s.controlsShown());
            gui_->setScale(scale);
            for (int k = 0; k < 3; ++k) {
                gui_->beginFrame(window, 844.f);
                (void)panel_.build(s, FrameStats{}, 844.f / scale, scale);
                EXPECT_EQ(gui_->endFrame(), 0);
            }
            const PanelItem* fold = panel_.item("fold panel");
            ASSERT_NE(fold, nullptr);
            EXPECT_LE(fold->x1 * scale, window + 0.5f) << window << " at " << chosen;
            EXPECT_GE((fold->x1 - fold->x0) * scale, kTouchTargetPoints - 0.5f)
                << window << " at " << chosen << ": a sliver";
            EXPECT_LE(ImGui::FindWindowByName("Controls")->Size.x * scale, window + 0.5f);
        }
    }
    gui_->setScale(1.f);
}

TEST_F(ControlPanelTest, TheCloseButtonStaysInReachWhenThePanelIsScrolled) {
    // A phone: after scrolling the sheet down, << had scrolled away with it (six swipes back to
    // close it). The panel's top line stays put.
    for (const char* section : {"section Scene", "section Physics", "section Show"})
        click(section);
    const PanelItem* top = panel_.item("fold panel");
    ASSERT_NE(top, nullptr);
    const float y = top->y0;
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_GT(w->ScrollMax.y, 300.f);
    ImGui::SetScrollY(w, w->ScrollMax.y);
    frame();
    frame();
    ASSERT_GT(ImGui::FindWindowByName("Controls")->Scroll.y, 300.f);
    EXPECT_EQ(panel_.item("fold panel")->y0, y);
    click("fold panel");
    EXPECT_FALSE(session_->controlsShown());
}

TEST_F(ControlPanelTest, ACardThatGoesAwayLeavesNoBlankPanel) {
    // A trial at 200 %: after a collision, R took the card away and the panel stayed scrolled
    // past its end, blank, until the wheel brought it back. What the pointer was over went with
    // the card; the panel's scroll comes back within its content.
    session_->apply(cmd::SetShow{ShowOption::Collision, true});
    for (const char* section : {"section Physics", "section Show"})
        click(section);
    ASSERT_TRUE(runToACollision());
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    // Scrolled down to the card's diagram, the pointer on it.
    frame();
    const PanelItem* diagram = panel_.item("momenta diagram");
    ASSERT_NE(diagram, nullptr);
    ImGui::SetScrollY(w, std::min(w->ScrollMax.y, w->Scroll.y + diagram->y0 - w->Pos.y - 20.f));
    frame();
    frame();
    ImGuiIO& io = gui_->io();
    io.MousePos = centre("momenta diagram");
    frame();
    frame();
    session_->apply(cmd::Restart{});
    for (int k = 0; k < 4; ++k)
        frame();
    w = ImGui::FindWindowByName("Controls");
    EXPECT_LE(w->Scroll.y, w->ScrollMax.y + 0.5f);
    const PanelItem* data = panel_.item("section Data");
    ASSERT_NE(data, nullptr);
    EXPECT_LT(data->y0, w->Pos.y + w->Size.y) << "the panel shows nothing: scrolled past its end";
}

TEST_F(ControlPanelTest, AfterARestartTheNextCollisionLeavesThePanelWhereTheUserLeftIt) {
    // A trial at 200 %: the panel scrolled down to the Data section, the teacher pressed R and
    // worked in the box; at the next collision the panel had scrolled away from Data to the
    // card. Only J's own card may move the panel, and J opens it where it is.
    session_->apply(cmd::SetShow{ShowOption::Collision, true});
    for (const char* section : {"section Physics", "section Show"})
        click(section);
    ASSERT_TRUE(runToACollision());
    ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    frame();
    const PanelItem* data = panel_.item("section Data");
    ASSERT_NE(data, nullptr);
    ImGui::SetScrollY(w, std::min(w->ScrollMax.y, w->Scroll.y + data->y0 - w->Pos.y - 40.f));
    frame();
    frame();
    const float before = panel_.item("section Data")->y0;
    ASSERT_LT(before, static_cast<float>(kSize)) << "the case: Data in sight";
    ASSERT_GT(w->Scroll.y, 0.f) << "the case: the panel scrolled";
    // The pointer in the box, away from the panel.
    gui_->io().MousePos = ImVec2(kSize - 100.f, kSize / 2.f);
    frame();
    session_->apply(cmd::Restart{});
    for (int k = 0; k < 4; ++k)
        frame();
    // The card cleared, the panel's content nearly fits the window: Data as near as the scroll
    // can keep it.
    const float afterRestart = panel_.item("section Data")->y0;
    EXPECT_NEAR(afterRestart, before, 10.f) << "R moved the Data section";
    ASSERT_TRUE(runToACollision());
    frame();
    frame();
    EXPECT_NEAR(panel_.item("section Data")->y0, afterRestart, 0.5f)
        << "the next collision scrolled the Data section away";
}

TEST_F(ControlPanelTest, FoldedThePanelIsANarrowStripThatOpensAgain) {
    click("fold panel");
    EXPECT_FALSE(session_->controlsShown());
    frame();
    const PanelItem* open = panel_.item("open panel");
    ASSERT_NE(open, nullptr);
    EXPECT_LE(open->x1, kControlsFoldedWidth);
    // The button is as wide as its label: both ">" of ">>" show (the message says
    // "C or >> opens it"); it used to be cut to one ">" by the strip's width.
    const ImGuiStyle& style = ImGui::GetStyle();
    EXPECT_GE(open->x1 - open->x0, ImGui::CalcTextSize(">>").x + 2.f * style.FramePadding.x);
    EXPECT_GE(open->x0, 0.f);
    EXPECT_EQ(panel_.item("Play/Pause"), nullptr);
    click("open panel");
    EXPECT_TRUE(session_->controlsShown());
}

TEST_F(ControlPanelTest, ThePanelIsOpaqueAndDrawsNothingBesideItsColumn) {
    const int inside = static_cast<int>(kControlsWidth) - 12;
    const int beside = static_cast<int>(kControlsWidth) + 4;
    // Below the last control, the panel's background: opaque, not the black behind it.
    const SDL_Color bg = pixel(inside, kSize - 3);
    EXPECT_GT(bg.r + bg.g + bg.b, 30) << int(bg.r) << " " << int(bg.g) << " " << int(bg.b);
    for (int y = 0; y < kSize; y += 50) {
        const SDL_Color c = pixel(beside, y);
        EXPECT_EQ(c.r + c.g + c.b, 0) << y;
    }
}

TEST_F(ControlPanelTest, UndoRedoAndStepBackButtonsGoThroughTheSession) {
    const double e = session_->world().def().restitution;
    const PanelItem* r = panel_.item("Restitution");
    ASSERT_NE(r, nullptr);
    drag("Restitution", ImVec2(r->x0 - 20.f, (r->y0 + r->y1) / 2.f));
    ASSERT_DOUBLE_EQ(session_->world().def().restitution, 0.0);
    click("Undo");  // the whole drag is one edit
    EXPECT_DOUBLE_EQ(session_->world().def().restitution, e);
    click("Redo");
    EXPECT_DOUBLE_EQ(session_->world().def().restitution, 0.0);

    // Paused: three single steps, then one back shows the second one's time.
    const double dt = session_->meta().dt;
    for (int k = 0; k < 3; ++k) {
        click("Step");
        session_->update(0.0, 0.0);
    }
    ASSERT_NEAR(session_->world().time(), 3.0 * dt, 1e-12);
    click("Step back");
    EXPECT_NEAR(session_->world().time(), 2.0 * dt, 1e-12);
    EXPECT_TRUE(session_->timeline().viewingPast);
    click("Step forward");
    EXPECT_NEAR(session_->world().time(), 3.0 * dt, 1e-12);
}

TEST_F(ControlPanelTest, OnATouchScreenTheQuitDialogsShowTheirButtonsAndNoKeys) {
    // The dialog opens in one frame and is drawn in the next; what its keys line says.
    const auto keys = [&]() -> std::string {
        frame();
        frame();
        for (const auto& [name, text] : panel_.statusLines())
            if (name == "dialog keys") return text;
        return "none";
    };
    session_->apply(cmd::Back{});  // Esc: the quit question, nothing unsaved
    ASSERT_EQ(session_->dialog().kind, Dialog::Kind::Quit);
    EXPECT_EQ(keys(), "Enter: Quit, Esc: Stay");
    EXPECT_NE(panel_.item("dialog Quit"), nullptr);
    session_->apply(cmd::SetTouch{true});
    EXPECT_EQ(keys(), "none");
    EXPECT_NE(panel_.item("dialog Quit"), nullptr);
    EXPECT_NE(panel_.item("dialog Cancel"), nullptr);  // Stay
    session_->apply(cmd::AnswerQuit{cmd::AnswerQuit::Choice::Cancel});
    frame();

    session_->apply(cmd::SpawnRandom{});
    session_->apply(cmd::Back{});  // with unsaved changes: Save, Discard or Cancel
    ASSERT_TRUE(session_->dialog().unsaved);
    EXPECT_EQ(keys(), "none");
    EXPECT_NE(panel_.item("dialog Discard"), nullptr);
    session_->apply(cmd::SetTouch{false});
    EXPECT_EQ(keys(), "Enter: Save, D: Discard, Esc: Cancel");
}

TEST_F(ControlPanelTest, OnATouchScreenThePhysicsModesNameNoKey) {
    const auto said = [&]() -> std::string {
        frame();
        for (const auto& [name, text] : panel_.statusLines())
            if (name == "mode line") return text;
        return "none";
    };
    EXPECT_EQ(said(), "Mode (key T):");
    session_->apply(cmd::SetTouch{true});
    EXPECT_EQ(said(), "Mode:");
}

TEST_F(ControlPanelTest, DeleteAddAndViewButtonsNeedNoKey) {
    click("Keys");
    EXPECT_TRUE(session_->helpShown());
    session_->apply(cmd::Back{});
    session_->apply(cmd::Pan{Vec2(50.0, 0.0)});
    const Vec2 panned = session_->camera().worldToScreen(Vec2::Zero());
    click("Fit view");
    EXPECT_NE(session_->camera().worldToScreen(Vec2::Zero()).x(), panned.x());

    // Fold what is above the selected particle's section, so that it is in the window.
    for (const char* section : {"section Physics", "section Show", "section Readouts"})
        click(section);
    const std::size_t n = session_->world().size();
    const ParticleId id = session_->world().ids().front();
    session_->apply(cmd::Select{id});
    click("delete particle");
    EXPECT_EQ(session_->world().size(), n - 1);
    EXPECT_FALSE(session_->world().contains(id));
    EXPECT_FALSE(session_->selected().has_value());
    click("Undo");
    EXPECT_EQ(session_->world().size(), n);
    EXPECT_TRUE(session_->world().contains(id));

    click("section Tools");
    click("Add a random particle");
    EXPECT_EQ(session_->world().size(), n + 1);
}

}  // namespace
}  // namespace psb::app