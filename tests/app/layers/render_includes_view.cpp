// Compiles: the render layer links the view, whose include root it then has. The control for
// app_layers.TheSessionCannotIncludeTheView (the same include, the same build command).
#include <view/frame_view.hpp>
