#pragma once
/// \file
/// What the app exports and particle-sim writes, as tables (csv.hpp): the columns of each,
/// named with their units, in one place so that a file from either reads the same.
///
/// A particle is named by its number, the slot of its id (ParticleId::slot): for a scene as
/// loaded, its index in the file's particle list; the number the app shows as #N.

#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/collision_log.hpp>
#include <particle_sandbox/csv.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/trajectory.hpp>

namespace psb {

class World;

// Every table takes the axes its numbers are in (axes.hpp): the world's, y down from the box's
// top edge, by default; with y up each column of a y component is named with "_up" (y_up_m,
// vy_up_m_per_s) and each of turning with "_ccw" (positive counterclockwise on screen).

/// Every particle's state now, one row each in order of number: particle, x_m, y_m,
/// vx_m_per_s, vy_m_per_s, (omega_rad_per_s,) px_kg_m_per_s, py_kg_m_per_s, kinetic_energy_J,
/// (rotational_energy_J,) mass_kg, radius_m; the bracketed ones in a world that keeps rotation
/// (World::rotationInUse).
[[nodiscard]] std::string valuesTable(const World& world, csv::Separator separator,
                                      const Axes& axes = {});

/// The observables over time (time_series.hpp), one row per sample: time_s,
/// kinetic_energy_J, momentum_x_kg_m_per_s, momentum_y_kg_m_per_s, com_x_m, com_y_m,
/// collisions, collision_rate_per_s (empty where the sample has none: ObservablesSample;
/// named collision_rate_per_s_last_W_s when the rate is counted over the last
/// `rateWindowSeconds` W rather than since the row before),
/// with `gravity` potential_energy_J and
/// mechanical_energy_J (kinetic + rotational + potential), and with `rotation` (a world that
/// keeps rotation: World::rotationInUse) rotational_energy_J and
/// angular_momentum_kg_m2_per_s (orbital + spin, about the box's top-left corner; with y up,
/// about its bottom-left corner).
[[nodiscard]] std::string timeSeriesTable(const std::vector<ObservablesSample>& samples,
                                          bool gravity, csv::Separator separator,
                                          bool rotation = false, const Axes& axes = {},
                                          double rateWindowSeconds = 0.0);
/// The samples `series` holds, oldest first.
[[nodiscard]] std::vector<ObservablesSample> samplesOf(const TimeSeries& series);

/// One row per particle per instant: time_s, particle, x_m, y_m, vx_m_per_s, vy_m_per_s, and
/// with `rotation` omega_rad_per_s.
[[nodiscard]] std::string trajectoryTable(const Trajectory& trajectory, csv::Separator separator,
                                          bool rotation = false, const Axes& axes = {});

/// One row per collision (collision_log.hpp): time_s, particle, with (particle, wall or
/// obstacle), other (the other particle's number, the wall: left, right, top, bottom, or the
/// obstacle's index), vx_before_m_per_s, vy_before_m_per_s, vx_after_m_per_s,
/// vy_after_m_per_s, the same four of the other particle (empty for a wall or an obstacle),
/// impulse_x_N_s, impulse_y_N_s (on the particle).
[[nodiscard]] std::string collisionTable(const std::vector<Collision>& collisions,
                                         csv::Separator separator, const Axes& axes = {});

/// "left", "right", "top", "bottom".
[[nodiscard]] const char* wallName(WallSide side);

}  // namespace psb
