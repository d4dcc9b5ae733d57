"""World.positions and the other arrays: read-only views of the world's storage, no copy."""

import gc
import tracemalloc

import numpy as np
import pytest

import particle_sandbox as ps
from conftest import two_discs


def address(a):
    return a.__array_interface__["data"][0]


def test_rows_are_the_particles_as_get_reports_them(gas):
    world = ps.World(gas)
    world.run(0.1)
    positions, velocities, ids = world.positions, world.velocities, world.ids
    assert positions.shape == (100, 2) and velocities.shape == (100, 2) and ids.shape == (100,)
    for row in (0, 57, 99):
        p = world.get(int(ids[row]))
        assert tuple(positions[row]) == p.position
        assert tuple(velocities[row]) == p.velocity
        assert world.masses[row] == p.mass
        assert world.radii[row] == p.radius


@pytest.mark.parametrize("mode", ["discrete", "substep", "exact"])
def test_a_view_is_the_same_memory_before_and_after_a_step_and_sees_the_new_state(gas, mode):
    gas.solver.mode = mode
    world = ps.World(gas)
    positions = world.positions
    before = positions.copy()
    world.step()
    assert address(world.positions) == address(positions)
    assert not np.array_equal(positions, before)  # the held view shows the step's result
    assert np.array_equal(positions, world.positions)


def test_views_are_read_only_and_own_nothing(gas):
    world = ps.World(gas)
    for name in ("positions", "velocities", "masses", "radii", "angles", "spins", "ids"):
        a = getattr(world, name)
        assert not a.flags.writeable, name
        assert not a.flags.owndata, name
    with pytest.raises(ValueError, match="read-only"):
        world.positions[0, 0] = 1.0


def test_writes_go_through_setters_that_validate(gas):
    world = ps.World(gas)
    first = int(world.ids[0])
    world.set_position(first, (1.0, 1.5))
    assert tuple(world.positions[0]) == (1.0, 1.5)
    with pytest.raises(ValueError, match="mass"):
        world.set_mass(first, -1.0)


def test_reading_a_view_copies_no_particle_data():
    scene = ps.parse_scene('{"version": 1, "world": {"width": 100, "height": 100}, '
                           '"generate": {"count": 10000, "radius": 0.1, "temperature": 1}}')
    world = ps.World(scene)
    world.positions  # the first read may reserve room for droppers' balls (none here)
    tracemalloc.start()
    kept = [world.positions for _ in range(100)]
    size, _ = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    # A copy would be 160 kB each, 16 MB in all; a view is an object of a few hundred bytes.
    assert size < 100 * 1024, size
    assert len({address(a) for a in kept}) == 1


def test_a_view_keeps_its_world_alive(gas):
    world = ps.World(gas)
    positions = world.positions.copy()
    view = world.positions
    del world
    gc.collect()
    assert np.array_equal(view, positions)


def test_adding_past_the_capacity_while_a_view_lives_is_refused_not_a_dangling_view():
    scene = two_discs()
    world = ps.World(scene)
    view = world.positions
    with pytest.raises(BufferError, match="view"):
        for k in range(100):
            world.add((1.0 + k, 1.0), radius=0.1)
    del view
    world.add((3.0, 3.0), radius=0.1)  # no view: the storage may move


def test_reserve_makes_room_for_adding_while_a_view_lives():
    world = ps.World(two_discs())
    world.reserve(200)
    view = world.positions
    for k in range(100):
        world.add((1.0 + 0.5 * k, 20.0), radius=0.1)
    assert address(world.positions) == address(view)


def test_droppers_balls_never_move_the_storage_under_a_view(preset):
    world = ps.World(preset("09-galton-board.json"))
    world.run(0.5)
    view = world.positions
    assert len(view) > 0
    world.run(3.0)
    assert len(world) > len(view)
    assert address(world.positions) == address(view)


def test_angles_read_zero_until_the_world_keeps_rotation():
    world = ps.World(two_discs())
    assert world.angles.tolist() == [0.0, 0.0]
    world.set_spin(int(world.ids[1]), 3.0)
    assert world.rotation_in_use
    assert world.spins.tolist() == [0.0, 3.0]


def test_a_view_of_angles_made_after_friction_began_survives_the_droppers_balls(preset):
    world = ps.World(preset("09-galton-board.json"))
    world.run(0.5)
    positions = world.positions  # room reserved for every ball, in the arrays there are
    world.friction = 0.3
    world.run(0.1)  # the rotation arrays are made, with room for the particles alone
    assert world.rotation_in_use
    angles = world.angles
    n = len(angles)
    world.run(3.0)
    assert len(world) > n
    assert address(world.angles) == address(angles)
    assert address(world.positions) == address(positions)
