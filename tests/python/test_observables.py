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


def test_a_periodic_gas_has_liu_beside_henderson_and_the_row_keeps_the_notes():
    scene = ps.parse_scene("""{
      "version": 6,
      "world": {"width": 40.0, "height": 40.0, "walls": false, "periodic": true},
      "solver": {"mode": "exact", "dt": 0.1},
      "generate": {"count": 200, "radius": 0.5, "temperature": 1.0, "seed": 2}
    }""", "periodic.json")
    result = ps.World(scene).measure(0.2)  # too short for errors: the notes say so
    liu, henderson = result.liu_compressibility_factor, result.henderson_compressibility_factor
    assert liu == pytest.approx(henderson, rel=0.01)  # the two agree to 1 % below 0.3
    row = result.as_dict()
    assert row["liu_compressibility_factor"] == result.liu_compressibility_factor
    assert math.isnan(row["compressibility_factor_error"])
    assert row["notes"] == "; ".join(result.notes)
    assert "too short for errors" in row["notes"]
