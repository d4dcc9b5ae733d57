#pragma once
/// \file
/// The parameters of a world.

#include <particle_sandbox/math.hpp>
#include <particle_sandbox/obstacle.hpp>

namespace psb {

/// The box, its fixed obstacles and the material laws of a world. All values are validated by
/// World.
struct WorldDef {
    double width = 700.0;   ///< box width, metres, finite and > 0
    double height = 700.0;  ///< box height, metres, finite and > 0
    bool walls = true;      ///< whether the four walls of the box exist
    /// Whether the box's opposite edges are joined (periodic boundaries): a particle leaving
    /// by one edge comes back by the opposite one, and pairs meet across the edges (the
    /// minimum image). There are no walls then: World ignores `walls` and keeps it false.
    /// Every particle must fit twice across the box (its diameter at most half the width and
    /// half the height), and every obstacle must stay a largest particle's diameter inside
    /// every edge (World::setPeriodic).
    bool periodic = false;
    Vec2 gravity = Vec2::Zero();  ///< m/s²; y points down, so (0, 9.81) is Earth's pull
    double restitution = 1.0;     ///< coefficient of restitution e in [0, 1], pairs and walls
    double friction = 0.0;        ///< Coulomb coefficient for tangential impulses, >= 0
    /// Tangential restitution β in [−1, 1]: a sticking contact (its tangential impulse below
    /// friction·normal impulse) turns the contact points' tangential relative velocity into −β
    /// times itself. 0 stops the slip; 1 is the perfectly rough, energy-conserving disc.
    double tangentialRestitution = 0.0;
    Obstacles obstacles{};  ///< fixed pegs and segments (see World::setObstacles)
};

}  // namespace psb
