#include "view/gas_lines.hpp"

#include <cmath>
#include <cstdio>

#include "session/units.hpp"

namespace psb::app {

std::vector<GasLine> gasLines(const GasReading& r) {
    std::vector<GasLine> lines;
    const std::string seconds = plainNumber(r.window, 3) + " s";
    lines.push_back({"Temperature kT", quantity(r.kT, "J"),
                     "In two dimensions each particle has, on average, kT of kinetic energy "
                     "(\u00bd kT for each of its two directions): kT is the mean \u00bd m v\u00b2. "
                     "In joules, since these are balls of grams to kilograms: in kelvin, kT / k, "
                     "they would read some 10\u00b2\u00b2 K."});
    if (r.pressure) {
        lines.push_back(
            {"Pressure, measured",
             // One unit for both, once, no prefix: "11.70 \u00b1 0.15 N/m" (with the unit twice
             // the value wrapped over three lines at 200 %).
             withError(*r.pressure, r.pressureError, "N/m"),
             (r.periodic
                  ? std::string("From the collisions (a periodic box has no walls to push): "
                                "N kT plus half of each collision's impulse times the distance "
                                "between the two centres, summed per second, over the box's "
                                "area (a 2-D pressure is a force per length), over the last ")
                  : std::string("The momentum the particles give the walls each second, per "
                                "metre of the line their centres reach, a radius inside the "
                                "walls (a 2-D pressure is a force per length), over the last ")) +
                 seconds + " of simulated time; \u00b1 one standard error."});
    } else {
        lines.push_back({"Pressure, measured", "measuring...",
                         r.periodic ? "The collisions' push is averaged over at least half a "
                                      "second of simulated time: run the world."
                                    : "The walls' push is averaged over at least half a second "
                                      "of simulated time: run the world."});
    }
    lines.push_back({"  ideal gas", quantity(r.idealPressure, "N/m"),
                     "N kT / A: what point particles at this temperature would press, A the "
                     "area their centres move in."});
    char covered[16];
    std::snprintf(covered, sizeof covered, "%.0f %%", 100.0 * r.coverage);
    lines.push_back({"  hard discs", quantity(r.hardDiskPressure, "N/m"),
                     std::string("Henderson's equation of state for discs covering ") + covered +
                         " of the box: N kT / A (1 + \u03b7\u00b2/8) / (1 - \u03b7)\u00b2. "
                         "Discs of a size take room, so they press harder than points."});
    if (r.pressure) {
        lines.push_back(
            {"Collisions",
             r.periodic ? quantity(r.pairRate, "pair/s", false)
                        : quantity(r.pairRate, "pair/s", false) + ", " +
                              quantity(r.wallRate, "wall/s", false),
             std::string(r.periodic ? "Particle-particle collisions per second of simulated time"
                                    : "Particle-particle collisions and wall rebounds per second "
                                      "of simulated time") +
                 ", over the last " + seconds + "."});
        // The window the rates are counted over, as the plot's title says its own ("last
        // 0.5 s"): the rates read as if they were the plot's.
        lines.push_back({"  over the last", plainNumber(r.window, 2) + " s",
                         "The stretch of simulated time the pressure and the collision rates "
                         "above are averaged over: the last 3.75 to 5 s (all of it in the first "
                         "five seconds). The rate plot (K) counts over its own, shorter window, "
                         "as its title says."});
    }
    return lines;
}

}  // namespace psb::app
