#include "session/session.hpp"

#include <type_traits>

#include <particle_sandbox/diagnostics.hpp>

#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

Session::Session(World world, SceneMeta meta, SessionOptions options)
    : options_(std::move(options)),
      doc_(std::move(world), std::move(meta),
           psb::app::sceneFile(options_.sceneFile, options_.presets)),
      view_(options_),
      history_(options_.undo, options_.timeline),
      dataOut_(options_.exportDir, options_.inPage) {
    tools_.rng.seed(options_.seed);
    clock_.paused = options_.paused;
    for (const auto& file : options_.presets)
        presets_.push_back(describeScene(file));
    sceneOpened();
    showSceneTrails(doc_.meta.trails);
    if (options_.sceneFile) {
        doc_.rememberFile(*options_.sceneFile);
        if (clock_.paused) {
            notices_.say("Opened " + options_.sceneFile->filename().string() + ": " +
                         doc_.meta.name + ", paused: Space starts it");
        }
    }
    if (!view_.controlsShown())
        notices_.say("The control panel is folded in this narrow window: C or >> opens it");
}

void Session::setWorld(World world, SceneMeta meta, SceneFile file) {
    // Replacing unsaved changes is undoable, as every change is; it is said, so that a scene
    // opened by a stray key (a digit opens a preset) is not taken for lost.
    const bool unsaved = doc_.dirty;
    const std::string was = doc_.meta.name;
    doc_.replace(std::move(world), std::move(meta), std::move(file));
    sceneOpened();
    if (unsaved) {
        notices_.say("The unsaved changes to " + (was.empty() ? std::string("the scene") : was) +
                         " were replaced: Ctrl+Z brings them back",
                     Notice::Level::Warning);
    }
}

void Session::sceneOpened() {
    startOver(true);
    tools_.followScene(doc_.world);
    view_.fit(doc_, notices_);
}

void Session::startOver(bool newScene, bool keepRecorded) {
    tools_.startOver();
    history_.startOver();
    clock_.restart();
    monitor_.restart(doc_.world, newScene, doc_.meta.dt);
    instruments_.startOver(doc_.world, newScene, keepRecorded, monitor_.series().back());
    if (newScene) view_.startOver(doc_.world);
}

std::vector<Notice> Session::takeNotices() {
    return notices_.take();
}

// ---------------------------------------------------------------------------------------------
// The one place commands are applied.

namespace {

/// `Part` has a handler for command `C`: `Part::handle(const C&, Part::Context&)`.
template <class Part, class C>
concept Handles = requires(Part& part, const C& c, typename Part::Context& x) {
    part.handle(c, x);
};

/// Whether `c` may edit: its type's trait, except that a command continuing a slider drag
/// belongs to the drag's first (which kept the state before it).
template <class T>
bool mayEdit(const T& c) {
    if constexpr (requires { c.continues; }) {
        return T::traits.edits && !c.continues;
    } else {
        return T::traits.edits;
    }
}

}  // namespace

template <class C>
void Session::route(const C& c) {
    if constexpr (Handles<SimClock, C>) {
        SimClock::Context x{doc_, history_, monitor_, notices_, edit_};
        clock_.handle(c, x);
    } else if constexpr (Handles<History, C>) {
        History::Context x{doc_, clock_, monitor_, tools_, notices_};
        history_.handle(c, x);
    } else if constexpr (Handles<Tools, C>) {
        Tools::Context x{doc_, view_, instruments_.ruler, clock_, monitor_, notices_, edit_};
        tools_.handle(c, x);
    } else if constexpr (Handles<SceneView, C>) {
        SceneView::Context x{doc_, tools_, instruments_, notices_};
        view_.handle(c, x);
    } else if constexpr (Handles<Instruments, C>) {
        Instruments::Context x{doc_, tools_, view_, clock_, notices_};
        instruments_.handle(c, x);
    } else if constexpr (Handles<DataOut, C>) {
        DataOut::Context x{doc_, instruments_, view_, notices_};
        dataOut_.handle(c, x);
    } else {
        handle(c);
    }
}

void Session::apply(const Command& command) {
    std::visit(
        [this](const auto& c) {
            constexpr cmd::Traits traits = std::decay_t<decltype(c)>::traits;
            // A dialog holds everything but its answers until it closes.
            if (dialog_.open() && !traits.whileDialog) return;
            // While the edit prompt is open it takes the keyboard.
            if (tools_.prompt.active() && !traits.whilePrompt) return;
            // The state before an edit, for the undo history. A press keeps the state before
            // it until its release or the deletion of what it holds: the gesture (grab, drag,
            // fling or delete) is one edit.
            const bool edits = mayEdit(c);
            history_.before.reset();
            if (traits.gesture == cmd::Gesture::Release ||
                (traits.gesture == cmd::Gesture::EndsHold && tools_.holding())) {
                history_.before = std::move(history_.pressBefore);
                history_.pressBefore.reset();
            } else if (edits) {
                history_.before = snapshot(doc_.world);
            }
            edit_ = EditReport{};
            route(c);
            file(edit_);
            if (traits.gesture == cmd::Gesture::Press && tools_.gestureUnderWay()) {
                history_.pressBefore = std::move(history_.before);
            }
            history_.before.reset();
            // Whatever changed the world other than the timeline's setters makes its frame a
            // keyframe (a press and a release set a particle kinematic and free).
            if (edits || traits.gesture == cmd::Gesture::Release) history_.timeline.edited();
        },
        command);
}

}  // namespace psb::app
