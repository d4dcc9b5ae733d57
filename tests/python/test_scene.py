"""Scenes from Python: loaded by the core's loader, changed field by field, checked as files."""

import pickle

import pytest

import particle_sandbox as ps
from conftest import GAS, two_discs


def test_a_preset_loads_with_its_generate_block_expanded(preset):
    scene = preset("04-gas-in-a-box.json")
    assert len(scene.particles) == 4000
    assert scene.world.width == 7.0
    assert scene.dt == 0.01
    assert '"generate"' in scene.file_text


def test_overrides_are_the_runner_set_option(gas):
    changed = ps.parse_scene(GAS, "gas.json", {"world.restitution": 0.5, "generate.count": 50,
                                               "solver.mode": "substep"})
    assert changed.world.restitution == 0.5
    assert len(changed.particles) == 50
    assert changed.solver.mode == "substep"
    assert changed.overrides == [("world.restitution", "0.5"), ("generate.count", "50"),
                                 ("solver.mode", "substep")]


def test_an_unknown_override_key_names_the_nearest_known_one():
    with pytest.raises(ps.SceneError, match="restitution"):
        ps.parse_scene(GAS, "gas.json", {"world.restitutoin": 0.5})


def test_a_missing_file_is_a_scene_error_naming_it(tmp_path):
    with pytest.raises(ps.SceneError, match="nothing.json: cannot open"):
        ps.load_scene(tmp_path / "nothing.json")


def test_scene_errors_are_value_errors():
    assert issubclass(ps.SceneError, ValueError)


def test_a_changed_field_reaches_the_world(gas):
    gas.world.restitution = 0.9
    gas.world.gravity = (0.0, 9.81)
    gas.solver.mode = "substep"
    gas.solver.substeps = 4
    world = ps.World(gas)
    assert world.restitution == 0.9
    assert world.gravity == (0.0, 9.81)
    assert world.mode == "substep"
    assert world.substeps == 4


def test_a_bad_value_is_refused_with_the_scene_file_message():
    scene = two_discs()
    scene.particles[1].mass = -1.0
    with pytest.raises(ValueError, match=r"particles\[1\]\.mass: must be > 0 \(got -1\)"):
        ps.World(scene)


def test_a_bad_mode_name_lists_the_modes(gas):
    with pytest.raises(ValueError, match="'discrete', 'substep' or 'exact'"):
        gas.solver.mode = "fast"


def test_a_scene_survives_pickling_and_json(gas):
    again = pickle.loads(pickle.dumps(gas))
    assert again.to_json() == gas.to_json()
    assert again.file_text == gas.file_text
    assert ps.parse_scene(gas.to_json()).to_json() == gas.to_json()


def test_obstacles_and_droppers_are_lists_of_the_core_records(preset):
    galton = preset("09-galton-board.json")
    assert len(galton.world.obstacles) > 0
    assert {o.kind for o in galton.world.obstacles} <= {"peg", "segment"}
    assert len(galton.droppers) == 1
    galton.droppers[0].balls = 3
    assert galton.droppers[0].balls == 3
