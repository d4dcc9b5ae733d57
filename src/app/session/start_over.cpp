#include "session/start_over.hpp"

#include "session/document.hpp"
#include "session/history.hpp"
#include "session/instruments.hpp"
#include "session/monitor.hpp"
#include "session/notices.hpp"
#include "session/scene_view.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"

namespace psb::app {

void StartOver::world(const Document& doc, bool newScene) {
    const bool wasRecording = newScene && instruments.data.recording();
    tools.startOver();
    history.startOver();
    clock.restart();
    monitor.restart(doc.world, newScene, doc.meta.dt);
    instruments.startOver(doc.world, newScene, monitor.series().back());
    if (newScene) view.startOver(doc.world);
    if (wasRecording) {
        // Never without a word: a preset's key while recording dropped what was recorded. Two
        // lines at 200 %, under the scene's own line.
        const DataRecorder& data = instruments.data;
        const std::size_t hits = data.collisions().size();
        notices.sayLast(
            fmt("Recording stopped: its %zu samples and %zu collision%s stay in the "
                "Data section to export",
                data.trajectory().samples().size(), hits, hits == 1 ? "" : "s"));
    }
}

void StartOver::scene(const Document& doc) {
    world(doc, true);
    instruments.ruler.place(doc.world.def().width, doc.world.def().height);
    tools.followScene(doc.world);
    view.fit(doc, notices);
}

}  // namespace psb::app
