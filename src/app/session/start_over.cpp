#include "session/start_over.hpp"

#include "session/document.hpp"
#include "session/history.hpp"
#include "session/instruments.hpp"
#include "session/monitor.hpp"
#include "session/scene_view.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"

namespace psb::app {

void StartOver::world(const Document& doc, bool newScene, bool keepRecorded) {
    tools.startOver();
    history.startOver();
    clock.restart();
    monitor.restart(doc.world, newScene, doc.meta.dt);
    instruments.startOver(doc.world, newScene, keepRecorded, monitor.series().back());
    if (newScene) view.startOver(doc.world);
}

void StartOver::scene(const Document& doc) {
    world(doc, true);
    instruments.ruler.place(doc.world.def().width, doc.world.def().height);
    tools.followScene(doc.world);
    view.fit(doc, notices);
}

}  // namespace psb::app
