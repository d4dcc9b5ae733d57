#pragma once
// The exact stepper's slides: particles in continuous contact with a segment's face, moving
// along it with a constant acceleration. Why and how: slides.cpp.
//
// The record (Slide, body.hpp) is per particle, in the stepper's order, kept only in a world
// with gravity and obstacles or rough contacts (else empty). It is read where a particle's
// flags say kSliding (the face, the acceleration along it) or kRolling (rolls.hpp: the
// acceleration along the face or wall it rolls on, and when its slip ends): the motion of such
// a particle (motion.hpp) takes its acceleration from here.

#include <cstdint>
#include <vector>

#include "exact/body.hpp"
#include "exact/obstacle_cells.hpp"

namespace psb::exact {

class Slides {
  public:
    /// Sizes the records for n particles (0 in a world without slides or rolls), none sliding.
    void reset(std::uint32_t n) { slide_.assign(n, Slide{}); }
    [[nodiscard]] bool empty() const { return slide_.empty(); }
    [[nodiscard]] Slide& operator[](std::uint32_t i) { return slide_[i]; }
    [[nodiscard]] const Slide& operator[](std::uint32_t i) const { return slide_[i]; }

    /// At a rebound of particle i (record `a`, `c`) off the face of segment k that gravity
    /// presses it into (nx, ny: the face's normal towards the centre): starts it sliding there,
    /// at contact and moving along the face, and true; false if it is not at contact, too near
    /// an end of the face, or held across an axis (Cold::pinX, pinY). Its acceleration is
    /// then the block's (setBlockAcceleration) or, for a disc that turns, a roll's (rolls.hpp).
    bool start(std::uint32_t i, Body& a, const Cold& c, const ObstacleCells& obstacles,
               std::uint32_t k, double nx, double ny);
    /// The acceleration along its face of particle i (record `a`) sliding as a block: gravity's
    /// share along the face less kinetic friction against the motion, or, at rest, none while
    /// static friction holds it.
    void setBlockAcceleration(std::uint32_t i, const Body& a, const ObstacleCells& obstacles,
                              const Gravity& g, double friction);
    /// The slide's own events of particle i (record `a`, at `m` at time `now`), if earlier than
    /// `best`: the end of the face (either end) and, where friction decelerates a block, the
    /// instant it stops (Kind::Slide, side 0 and 1 the ends, 2 the stop).
    void predict(std::uint32_t i, const Body& a, const ObstacleCells& obstacles, const Motion& m,
                 double now, Event& best) const;
    /// Off end `end` (0, 1) of segment o's face: the centre put a hair past the end, at contact
    /// distance on the side it slid on (the particle flies from there).
    static void leaveEnd(Body& a, const Obstacle& o, int end);
    /// Whether particle i (record `a`), sliding until a pair hit it just now, is still on its
    /// face: not moving away from it.
    [[nodiscard]] bool stillOnFace(std::uint32_t i, const Body& a,
                                   const ObstacleCells& obstacles) const;

    /// Follows a renumbering of the particles: particle i is now to[i].
    void renumber(const std::vector<std::uint32_t>& to) {
        if (!slide_.empty()) exact::renumber(slide_, to);
    }
    [[nodiscard]] std::size_t memoryBytes() const { return sizeof(Slide) * slide_.capacity(); }

  private:
    std::vector<Slide> slide_;
};

}  // namespace psb::exact
