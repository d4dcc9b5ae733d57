"""The collision log as a NumPy structured array."""

import numpy as np
import pytest

import particle_sandbox as ps
from conftest import two_discs


def test_a_head_on_collision_is_one_pair_row_with_its_impulse():
    world = ps.World(two_discs("exact"))
    a, b = (int(i) for i in world.ids)
    world.record_collisions()
    world.run(5.0)
    log = world.take_collisions()
    pairs = log[log["with"] == 0]
    assert len(pairs) == 1
    row = pairs[0]
    # The discs' surfaces meet when the centres are 2 m apart: 8 m closed at 2 m/s.
    assert row["time"] == pytest.approx(4.0)
    assert {int(row["a"]), int(row["b"])} == {a, b}
    assert np.allclose(row["impulse"], 1.0 * (row["a_after"] - row["a_before"]))
    assert np.allclose(row["a_after"], row["b_before"])
    assert len(world.take_collisions()) == 0  # taken


def test_wall_rows_name_the_wall_and_no_second_particle():
    world = ps.World(two_discs("exact"))
    world.record_collisions()
    world.run(60.0)
    walls = world.take_collisions()
    walls = walls[walls["with"] == 1]
    assert len(walls) >= 2
    assert set(walls["where"].tolist()) <= {0, 1}  # left and right only
    assert (walls["b"] == ps.World.NO_PARTICLE).all()
