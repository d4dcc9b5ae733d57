"""The core's observables with their errors, from Python."""

import math

import pytest

import particle_sandbox as ps


def test_a_gas_temperature_is_measured_with_an_error(gas):
    world = ps.World(gas)
    kT = world.kinetic_energy / len(world)  # two degrees of freedom: kT = E / N
    result = world.measure(5.0)
    assert result.temperature.value == pytest.approx(kT, rel=1e-9)  # elastic: E is conserved
    assert result.blocks >= 8
    assert result.compressibility_factor.error > 0.0
    z, dz = result.compressibility_factor
    assert abs(z - result.henderson_compressibility_factor) < 5 * dz + 0.05
    row = result.as_dict()
    assert row["temperature"] == result.temperature.value
    assert math.isnan(row["pressure_walls_error"]) or row["pressure_walls_error"] > 0.0
    assert len(result.msd) == len(result.lag_time) > 1
