#include "world/periodic_fit.hpp"

#include <algorithm>
#include <string>

#include "world/validate.hpp"

namespace psb::detail {

void requireFitsPeriodic(double radius, double width, double height, const char* where,
                         const char* what) {
    const double side = std::min(width, height);
    if (4.0 * radius > side) {
        fail(where, what,
             "is too large for the periodic " + csv::number(width) + " x " + csv::number(height) +
                 " m box " + got(radius) +
                 ": a periodic box must be at least two diameters of its largest particle wide "
                 "and high (radius at most " +
                 csv::number(0.25 * side) + " m)");
    }
}

void requireObstaclesClearOfEdges(const Obstacles& obstacles, double largestRadius, double width,
                                  double height, const char* where) {
    const double clearance = 2.0 * largestRadius;
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const Obstacle& o = obstacles[k];
        const double x0 = std::min(o.a.x(), o.b.x()) - o.radius;
        const double x1 = std::max(o.a.x(), o.b.x()) + o.radius;
        const double y0 = std::min(o.a.y(), o.b.y()) - o.radius;
        const double y1 = std::max(o.a.y(), o.b.y()) + o.radius;
        const double gap = std::min({x0, width - x1, y0, height - y1});
        if (gap < clearance) {
            const std::string what =
                "obstacle " + std::to_string(k) + (o.isPeg() ? " (peg)" : " (segment)");
            fail(where, what.c_str(),
                 "comes within " + csv::number(std::max(gap, 0.0)) +
                     " m of an edge of the periodic " + csv::number(width) + " x " +
                     csv::number(height) +
                     " m box: obstacles do not act across the edges, so each must stay the "
                     "largest particle's diameter (" +
                     csv::number(clearance) + " m) inside every edge");
        }
    }
}

}  // namespace psb::detail
