#pragma once
// The exact stepper's rolls: each disc's rotation, and a disc that turns in continuous contact
// with a surface (the face it slides on, the wall it rests on), slipping under kinetic friction
// until the slip-to-roll instant, then rolling. Why and how: rolls.cpp.
//
// The rotation (Turn, body.hpp) is per particle, in the stepper's order, kept only in a world
// that keeps rotation (else empty): its angle at the time of its last spin change, its angular
// velocity and acceleration since. Rough impulses change it through spinAt (contact.hpp's
// Spin refers to the record's angular velocity). A roll's acceleration along its surface and
// the end of its slip are kept in the particle's surface record (Slide, slides.hpp), where its
// motion reads them as a slide's.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "contact/contact.hpp"
#include "exact/body.hpp"
#include "exact/motion.hpp"
#include "exact/obstacle_cells.hpp"
#include "exact/slides.hpp"

namespace psb::exact {

class Rolls {
  public:
    /// Each particle's rotation as `p` has it (none unless `p` keeps rotation), on a clock
    /// that starts at 0; contacts are rough if it keeps rotation and `friction` > 0.
    void reset(const ParticleArrays& p, double friction);
    /// Contacts are rough (contact.hpp): the world keeps rotation and has friction.
    [[nodiscard]] bool rough() const { return rough_; }
    /// With rough contacts, particle i is a disc that turns (its spin weight is not 0).
    [[nodiscard]] bool turns(std::uint32_t i) const { return rough_ && turn_[i].q > 0.0; }

    /// Particle i's rotation (radius r) for a rough contact at time `now`: its angle brought up
    /// to now first, since the contact may change its angular velocity.
    [[nodiscard]] Spin spinAt(std::uint32_t i, double r, double now) {
        Turn& t = turn_[i];
        advanceTurn(t, now);
        return Spin{t.omega, r, t.q};
    }
    /// Particle i falls asleep at `now`: a disc that turns stops turning (its contacts'
    /// friction would stop it).
    void stopTurning(std::uint32_t i, double now);

    /// Gives particle i (record `a`, `c`, at its time a.t) the phase its contact calls for:
    /// on the face it slides on or the one wall it rests on, slipping until the slip-to-roll
    /// instant, rolling, or slipping for good where friction cannot hold a rolling disc; a
    /// disc that does not turn, on a wall, sliding as a block until it stops. Elsewhere (or a
    /// block on a face, slides.hpp's) it ends any roll. Writes the acceleration along the
    /// surface and the end of the slip into slides[i]. Nothing without rough contacts.
    void set(std::uint32_t i, Body& a, const Cold& c, Slides& slides,
             const ObstacleCells& obstacles, const Gravity& g, double friction);
    /// Ends particle i's roll (record `a`): its spin brought to a.t, back to plain turning.
    void end(std::uint32_t i, Body& a);
    /// The slip-to-roll event of particle i, if earlier than `best`.
    void predict(std::uint32_t i, const Slides& slides, double now, Event& best) const {
        const double t = std::max(now, slides[i].slipEnds);
        if (t < best.time) best = {t, 0, 0, Kind::Roll, 0};
    }
    /// At the slip-to-roll instant `now` of particle i (record `a` brought to it): a disc that
    /// turns rolls from here (or slips the other way where friction cannot hold it); a block
    /// stops (velocity zero, no roll), and true: what holds it decides whether it rests.
    bool endSlip(std::uint32_t i, Body& a, const Cold& c, Slides& slides,
                 const ObstacleCells& obstacles, const Gravity& g, double friction, double now);

    /// Writes every particle's angle and angular velocity at time t into `p` (order: the
    /// storage index of each of the stepper's particles). Nothing without rotation.
    void sync(ParticleArrays& p, const std::vector<std::uint32_t>& order, double t) const;
    /// Follows a renumbering of the particles: particle i is now to[i].
    void renumber(const std::vector<std::uint32_t>& to) {
        if (!turn_.empty()) exact::renumber(turn_, to);
    }
    [[nodiscard]] std::size_t memoryBytes() const { return sizeof(Turn) * turn_.capacity(); }

  private:
    // The outward normal of the surface particle i rolls on: the face it slides on, or the one
    // wall gravity presses it into; false if none.
    [[nodiscard]] bool surface(std::uint32_t i, const Body& a, const Cold& c, const Slides& slides,
                               const ObstacleCells& obstacles, const Gravity& g, double& nx,
                               double& ny) const;

    std::vector<Turn> turn_;
    bool rough_ = false;
};

}  // namespace psb::exact
