"""What a careless hand types: each refusal is a Python exception that names the argument or the
scene's JSON path and says what is wrong, before anything runs (found by a new user's trial: a
negative warm-up in a sweep ran for ever, NaN read as "a string", a seed of 1.5 ran as 1)."""

import math

import pytest

import particle_sandbox as ps
from particle_sandbox import _core
from conftest import GAS


@pytest.mark.parametrize("kwargs, message", [
    ({"warmup": -5.0}, "sweep: warmup must be a finite number of seconds >= 0 (got -5.0)"),
    ({"duration": -1.0}, "sweep: duration must be a finite number of seconds >= 0 (got -1.0)"),
    ({"duration": math.nan}, "sweep: duration must be a finite number of seconds >= 0 (got nan)"),
    ({"dt": -0.01}, "sweep: dt must be a finite number of seconds > 0 (got -0.01)"),
    ({"seeds": [-1]}, "sweep: seeds must be whole numbers >= 0 (got -1)"),
    ({"seeds": [1.5]}, "sweep: seeds must be whole numbers >= 0 (got 1.5)"),
    ({"params": {"world.restitution": [math.nan]}},
     "world.restitution: must be a finite number (got nan)"),
])
def test_a_sweep_refuses_bad_arguments_before_it_starts(gas, kwargs, message):
    with pytest.raises(ValueError) as refused:
        ps.sweep(gas, **{"duration": 0.1, **kwargs})
    assert str(refused.value) == message


def test_a_run_with_a_negative_time_is_refused_by_the_runner_itself():
    # Below the sweep: the runner refused nothing and counted the steps of -5 s as 2^64 - 500.
    with pytest.raises(ValueError, match=r"^warmup: must be finite and >= 0 seconds \(got -5\)$"):
        _core._run_scene(GAS, "gas.json", [], 1.0, -5.0)
    with pytest.raises(ValueError, match=r"^duration: must be finite and >= 0 seconds \(got nan\)$"):
        _core._run_scene(GAS, "gas.json", [], math.nan, 0.0)


def test_overrides_that_json_cannot_hold_or_that_are_not_a_dict_are_refused():
    with pytest.raises(ValueError, match=r"^world.restitution: must be a finite number \(got inf\)$"):
        ps.parse_scene(GAS, "gas.json", {"world.restitution": math.inf})
    with pytest.raises(TypeError, match=r"^overrides: expected a dict \{path: value\}"):
        ps.parse_scene(GAS, "gas.json", "world.restitution=0.9")


def test_a_scene_changed_to_a_number_json_cannot_hold_names_the_place(gas):
    gas.world.restitution = math.nan
    with pytest.raises(ps.SceneError, match=r"^gas.json: world.restitution is not finite$"):
        ps.World(gas)
    scene = ps.parse_scene(GAS, "gas.json")
    particle = scene.particles[3]
    particle.velocity = (math.nan, 0.0)
    scene.particles[3] = particle
    with pytest.raises(ps.SceneError, match=r"^gas.json: particles\[3\].vx is not finite$"):
        ps.World(scene)
