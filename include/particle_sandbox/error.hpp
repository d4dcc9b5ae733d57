#pragma once
/// \file
/// The one exception type the core throws for bad arguments.

#include <stdexcept>
#include <string>

namespace psb {

/// Thrown by the core's public API when an argument is out of range (NaN, infinity, zero or
/// negative mass or radius, restitution outside [0, 1], an unknown particle id, ...). The message
/// names the argument and the offending value; the world is left unchanged.
class InvalidArgument : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace psb
