#pragma once
// The web build's loop. A page must never block, so instead of App::run()'s loop the browser
// calls one pass of it per animation frame (emscripten_set_main_loop_arg): App::loopOnce without
// waiting, then the files saved are offered as downloads (platform/browser_files.hpp). A
// benchmark (the page's ?bench=N, the desktop's --bench) runs one of its frames per animation
// frame and adds the frame rate the browser reached to its line.
//
// The page calls back into the app through psb_web_uploaded() (a file picked with Open) and
// learns that the app has ended through psbEnded(line) (web/index.html).

#include <memory>

#include "app.hpp"

namespace psb::app {

/// Hands `app` to the browser's loop; returns at once (main() then returns, the page lives on).
/// `folder` is where the app saves (AppOptions::screenshotDir).
void runInBrowser(std::unique_ptr<App> app, const std::filesystem::path& folder, bool benchmark);

}  // namespace psb::app
