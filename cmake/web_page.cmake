# The web page's program (Emscripten): particle-sandbox.js and .wasm, with the fonts and preset
# scenes preloaded into /assets of the page's file system (particle-sandbox.data). The page
# itself is web/index.html, copied beside them; scripts/web.sh builds all of it into build/web.
set(psb_web_dir ${PROJECT_SOURCE_DIR}/web)
target_link_options(particle-sandbox PRIVATE
  -sALLOW_MEMORY_GROWTH=1
  -sINITIAL_MEMORY=64MB
  -sENVIRONMENT=web
  # main() returns once the browser runs the loop; the program lives on with the page.
  -sEXIT_RUNTIME=0
  # The page calls psb_web_uploaded() (a scene picked with Open), psb_web_type() and
  # psb_web_backspace() (an on-screen keyboard, platform/text_input.hpp), psb_web_copied() (the
  # browser's answer to a copy, platform/clipboard.hpp), and reads the file system.
  "-sEXPORTED_FUNCTIONS=_main,_psb_web_uploaded,_psb_web_type,_psb_web_backspace,_psb_web_copied"
  "-sEXPORTED_RUNTIME_METHODS=FS,ccall"
  # The settings live in IndexedDB (platform/browser_settings.hpp).
  -lidbfs.js
  -sMIN_WEBGL_VERSION=1
  -sMAX_WEBGL_VERSION=2
  # SHELL: keeps each option with its value (CMake drops repeated options otherwise).
  "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/assets/fonts/DejaVuSans.ttf@/assets/fonts/DejaVuSans.ttf"
  "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/assets/fonts/DejaVuSansMono.ttf@/assets/fonts/DejaVuSansMono.ttf"
  "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/assets/scenes@/assets/scenes")
# A preset changed is a page to build again.
file(GLOB psb_web_scenes ${PROJECT_SOURCE_DIR}/assets/scenes/*.json)
set_property(TARGET particle-sandbox APPEND PROPERTY LINK_DEPENDS ${psb_web_scenes}
             ${PROJECT_SOURCE_DIR}/web/index.html)
add_custom_command(TARGET particle-sandbox POST_BUILD
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${psb_web_dir}/index.html
          $<TARGET_FILE_DIR:particle-sandbox>/index.html
  VERBATIM)

# Emscripten's C++ exceptions are JavaScript ones: every call that may throw inside a function
# with something to destroy goes out through a JavaScript trampoline. The drawing and the view
# throw only when they cannot start (a font, a texture) or a screenshot fails, and catch nothing:
# compiled without landing pads they draw faster, and a throw still reaches the app's catch
# (what their frames held is not freed then; the program stops or goes on without that file).
target_compile_options(psb_app_render PRIVATE -fignore-exceptions)
target_compile_options(psb_app_view PRIVATE -fignore-exceptions)
