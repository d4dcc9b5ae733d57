// Must not compile: the session is below the view, and the view's include root is not the
// session's (cmake/app_layer.cmake). app_layers.TheSessionCannotIncludeTheView builds it and
// expects the compiler to say the header is not found.
#include <view/frame_view.hpp>
