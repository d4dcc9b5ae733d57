#pragma once
// Each bin's number marked on the board just under the bins' top line (the chart's x axis), as
// the view places them: the grid's distances keep off them (buildFrame), and
// render/bin_marks.cpp draws them where this says.

#include <string>
#include <vector>

#include <particle_sandbox/bins.hpp>

#include "session/camera.hpp"
#include "view/pixel_rect.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

/// One bin's number on the board: its text and the rectangle it takes, pixels.
struct BinNumber {
    PixelRect at;
    std::string text;
};

/// The numbers of `bins` on a board whose floor is at y = `floor` metres, seen through
/// `camera`, in `font`: centred between each bin's edges just under the top line, at whole
/// pixels; a bin narrower than its number and two pixels either side, or a board shorter than
/// two lines, has none.
[[nodiscard]] std::vector<BinNumber> binNumbers(const Camera& camera, const Bins& bins,
                                                double floor, const TextMeasure& font);

}  // namespace psb::app
