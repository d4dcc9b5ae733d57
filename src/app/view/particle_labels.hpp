#pragma once
// A particle's label (S) as the box shows it: one compact form for every label, its values in
// two lines ("particle 3, 12.0 kg" over "v (1.80, -1.20) m/s"), or, where the values leave a
// label out that its name alone would not, every label its name alone ("particle 3"); and the
// ask it makes of view/label_places.hpp, measured in the labels' font. The drawing layer
// (render/renderer.cpp) draws what these say; the tests place labels with the same asks.

#include <array>
#include <cstdint>
#include <string>

#include "view/label_places.hpp"
#include "view/pixel_rect.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

struct ParticleLabelText {
    /// "particle 3, 12.0 kg" over "v (1.80, -1.20) m/s".
    std::array<std::string, 2> values;
    /// "particle 3": the form where the values find no place for every label.
    std::string name;
};

/// Particle `number`'s label: its mass (kg) and velocity (m/s, its y component as the user
/// reads it: the y up option), two decimals, what rounds to zero "0.00", never "-0.00".
[[nodiscard]] ParticleLabelText particleLabelText(std::uint64_t number, double mass, double vx,
                                                  double vy);

/// The label `text` for the disc whose bounding square with kLabelGap round it is `disc`
/// (`inBox`: inside the walled box), its forms measured in `font`: 2 pixels of background
/// either side of the text and one under it.
[[nodiscard]] LabelAsk particleLabelAsk(const ParticleLabelText& text, const PixelRect& disc,
                                        const TextMeasure& font, bool inBox);

}  // namespace psb::app
