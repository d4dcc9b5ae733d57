# The web build's dependencies (Emscripten; scripts/web.sh configures it, docs/web.md).
#
# PSB_WEB_DEPS is what scripts/web/build-deps.sh made: prefix/ holds SDL2, FreeType and SDL2_ttf
# built for WebAssembly from Debian's source packages, and include/ links to the header-only
# libraries of the machine's Debian -dev packages (Eigen, nlohmann-json, CLI11, Boost, stb);
# src/imgui-*/ is Dear ImGui's Debian source, compiled here. The targets bear the names the
# desktop build's find_package() and pkg-config give, so that the project's CMake files use them
# unchanged. /usr/include itself is never on the include path: its C library is not
# Emscripten's.

set(PSB_WEB_DEPS "" CACHE PATH "The web build's dependencies (scripts/web/build-deps.sh's DIR)")
if(NOT IS_DIRECTORY "${PSB_WEB_DEPS}/prefix/include")
  message(FATAL_ERROR "PSB_WEB_DEPS='${PSB_WEB_DEPS}' holds no built dependencies: build through "
                      "scripts/web.sh build")
endif()
set(psb_web_include ${PSB_WEB_DEPS}/prefix/include)

function(psb_web_headers target)
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${ARGN}")
endfunction()
psb_web_headers(Eigen3::Eigen ${psb_web_include}/eigen3)
psb_web_headers(nlohmann_json::nlohmann_json ${psb_web_include})
psb_web_headers(CLI11::CLI11 ${psb_web_include})
psb_web_headers(Boost::headers ${psb_web_include})

if(PSB_BUILD_APP)
  list(PREPEND CMAKE_FIND_ROOT_PATH ${PSB_WEB_DEPS}/prefix)
  find_package(SDL2 REQUIRED CONFIG)
  find_package(SDL2_ttf REQUIRED CONFIG)
  if(NOT TARGET SDL2::SDL2)
    add_library(SDL2::SDL2 ALIAS SDL2::SDL2-static)
  endif()
  if(NOT TARGET SDL2_ttf::SDL2_ttf)
    add_library(SDL2_ttf::SDL2_ttf ALIAS SDL2_ttf::SDL2_ttf-static)
  endif()

  # stb_image_write: the header from Debian's libstb-dev, its implementation compiled here.
  set(psb_stb_impl ${CMAKE_BINARY_DIR}/web/stb_image_write.cpp)
  file(WRITE ${psb_stb_impl}
       "#define STB_IMAGE_WRITE_IMPLEMENTATION\n#include <stb_image_write.h>\n")
  add_library(psb_web_stb STATIC ${psb_stb_impl})
  target_include_directories(psb_web_stb SYSTEM PUBLIC ${psb_web_include}/stb)
  add_library(PkgConfig::STB ALIAS psb_web_stb)

  # Dear ImGui with its SDL2 platform backend, as Debian's libimgui-dev has it.
  file(GLOB psb_imgui_dir LIST_DIRECTORIES true ${PSB_WEB_DEPS}/src/imgui-[0-9]*)
  if(NOT EXISTS "${psb_imgui_dir}/imgui.cpp")
    message(FATAL_ERROR "No Dear ImGui source in ${PSB_WEB_DEPS}/src")
  endif()
  add_library(psb_web_imgui STATIC
    ${psb_imgui_dir}/imgui.cpp ${psb_imgui_dir}/imgui_draw.cpp ${psb_imgui_dir}/imgui_tables.cpp
    ${psb_imgui_dir}/imgui_widgets.cpp ${psb_imgui_dir}/backends/imgui_impl_sdl.cpp)
  target_include_directories(psb_web_imgui SYSTEM PUBLIC ${psb_imgui_dir})
  target_link_libraries(psb_web_imgui PUBLIC SDL2::SDL2)
  add_library(PkgConfig::IMGUI ALIAS psb_web_imgui)
endif()

# C++ exceptions are caught (a bad scene file is a message, not a crash): Emscripten's
# JavaScript-based exceptions, the kind its prebuilt C++ library has.
add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fexceptions>)
add_link_options(-fexceptions)
