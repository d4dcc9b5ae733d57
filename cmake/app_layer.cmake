# Each layer of the app (docs/app.md, "How it is built") exports its own include root, so that a
# layer's headers are found only from the layers that link it: "view/frame_view.hpp" compiles in
# the render layer, which links the view, and is not found from the session, angle brackets or
# quotes alike. The root is a folder in the build tree holding one link, named after the layer,
# to the layer's sources; includes keep naming their layer ("session/session.hpp").
#   psb_app_layer(TARGET LAYER): TARGET's public include root for src/app/LAYER.
function(psb_app_layer target layer)
  set(root ${PROJECT_BINARY_DIR}/app_include/${layer})
  file(MAKE_DIRECTORY ${root})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/app/${layer} ${root}/${layer} SYMBOLIC)
  target_include_directories(${target} PUBLIC ${root})
endfunction()
