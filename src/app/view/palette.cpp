#include "view/palette.hpp"

#include <algorithm>
#include <cmath>

namespace psb::app {

namespace {

// The Okabe–Ito colours (sRGB), by name.
constexpr Rgba kBlack{0, 0, 0}, kOrange{230, 159, 0}, kSkyBlue{86, 180, 233},
    kBluishGreen{0, 158, 115}, kBlue{0, 114, 178}, kVermillion{213, 94, 0},
    kReddishPurple{204, 121, 167};

constexpr Palette kDark{
    .background = {0, 0, 0},
    .walls = {255, 255, 255},
    .openWalls = {70, 70, 70},
    .text = {230, 230, 230},
    .panel = {0, 0, 0, 255},  // opaque: nothing drawn under a panel shows through its text
    .axis = {150, 150, 150},
    .tickText = {200, 200, 200},
    .labelBox = {0, 0, 0, 150},
    .labelText = {255, 255, 255},
    .highlight = {255, 230, 0},
    .warning = {255, 110, 100},
    .obstacle = {190, 195, 205},
    .preview = {105, 108, 115},
    .dropper = {150, 165, 185},
    .dropperText = {200, 210, 225},
    .ghost = {200, 200, 200, 90},
    .launchArrow = {200, 200, 200},
    .momentumArrow = {255, 150, 30},
    .totalMomentum = {255, 255, 0},
    .centreOfMass = {0, 230, 255},
    .energyPlot = {255, 90, 90},
    .pxPlot = {90, 200, 255},
    .pyPlot = {120, 255, 120},
    .ratePlot = {255, 200, 60},
    .histogramBar = {70, 130, 230},
    .theoryCurve = {255, 255, 255},
    .binBar = {230, 160, 60},
    .normalCurve = {90, 200, 255},
    .controls = {23, 26, 31},
    .caution = {255, 204, 77},
    .grid = {55, 66, 84},
    .gridStrong = {84, 100, 126},
    .ruler = {250, 215, 110},
    .mapParticles = false,
};

constexpr Palette kLight{
    .background = {255, 255, 255},
    .walls = {0, 0, 0},
    .openWalls = {160, 160, 160},
    .text = {17, 17, 17},
    .panel = {242, 242, 242, 255},
    .axis = {90, 90, 90},
    .tickText = {40, 40, 40},
    .labelBox = {255, 255, 255, 200},
    .labelText = {0, 0, 0},
    .highlight = {0, 0, 0},
    .warning = {170, 51, 0},  // a dark vermillion: 6:1 on white, where the bright one is 3.8:1
    .obstacle = {100, 100, 110},
    .preview = {185, 185, 195},
    .dropper = {90, 100, 120},
    .dropperText = {40, 45, 60},
    .ghost = {0, 0, 0, 110},  // the launch preview: a grey disc that reads on white
    .launchArrow = {60, 60, 60},
    .momentumArrow = kOrange,
    .totalMomentum = kBlue,
    .centreOfMass = kReddishPurple,
    .energyPlot = kVermillion,
    .pxPlot = kBlue,
    .pyPlot = kBluishGreen,
    .ratePlot = kOrange,
    .histogramBar = kSkyBlue,
    .theoryCurve = kBlack,
    .binBar = kOrange,
    .normalCurve = kBlue,
    .controls = {250, 250, 250},
    .caution = {140, 75, 0},  // a dark amber: 6:1 on the panel
    .grid = {222, 226, 232},
    .gridStrong = {184, 192, 204},
    .ruler = {0, 114, 178},  // Okabe-Ito blue: 5:1 on white
    .mapParticles = true,
};

double linear(std::uint8_t channel) {
    const double c = channel / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double luminance(Rgba c) {
    return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

}  // namespace

Rgba readableText(Rgba colour, Rgba background) {
    const Rgba bg{background.r, background.g, background.b};
    const Rgba start{colour.r, colour.g, colour.b};
    if (contrastRatio(start, bg) >= 4.5) return colour;
    const bool darken = luminance(bg) > 0.18;  // where black gives more contrast than white
    const auto mix = [&](std::uint8_t c, double t) {
        const double target = darken ? 0.0 : 255.0;
        return static_cast<std::uint8_t>(std::lround(c + (target - c) * t));
    };
    Rgba out = colour;
    for (int step = 1; step <= 20; ++step) {
        const double t = step / 20.0;
        out = {mix(colour.r, t), mix(colour.g, t), mix(colour.b, t), colour.a};
        if (contrastRatio(Rgba{out.r, out.g, out.b}, bg) >= 4.5) break;
    }
    return out;
}

const Palette& palette(Theme theme) {
    return theme == Theme::Light ? kLight : kDark;
}

Color lightColour(Color c) {
    const int hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    const auto out = [](Rgba o) { return Color{o.r, o.g, o.b}; };
    // Grey, white and black: no hue to keep.
    if (hi == 0 || hi - lo < 0.25 * hi) return out(kBlack);
    // The hue in degrees, as HSV's.
    const double d = hi - lo;
    double hue = 0.0;
    if (hi == c.r) {
        hue = 60.0 * std::fmod((c.g - c.b) / d + 6.0, 6.0);
    } else if (hi == c.g) {
        hue = 60.0 * ((c.b - c.r) / d + 2.0);
    } else {
        hue = 60.0 * ((c.r - c.g) / d + 4.0);
    }
    // Each Okabe–Ito colour's hue: the nearest wins, round the circle. Sky blue and blue share
    // one; the lighter colour takes sky blue.
    struct Entry {
        double hue;
        Rgba colour;
    };
    constexpr Entry kHues[] = {{15.0, kVermillion},
                               {45.0, kOrange},
                               {160.0, kBluishGreen},
                               {205.0, kSkyBlue},
                               {325.0, kReddishPurple}};
    const Entry* best = &kHues[0];
    double bestDistance = 360.0;
    for (const Entry& e : kHues) {
        const double a = std::abs(hue - e.hue), distance = std::min(a, 360.0 - a);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = &e;
        }
    }
    if (best->colour == kSkyBlue && (c.r + c.g + c.b) < 3 * 150) return out(kBlue);
    return out(best->colour);
}

double contrastRatio(Rgba a, Rgba b) {
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

}  // namespace psb::app
