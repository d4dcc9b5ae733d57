"""World from Python: steps in the three modes, particles by id, boxes, obstacles, threads."""

import math
import os
import signal
import subprocess
import threading

import numpy as np
import pytest

import particle_sandbox as ps
from conftest import ASSETS, two_discs


@pytest.mark.parametrize("mode", ["discrete", "substep", "exact"])
def test_head_on_equal_masses_exchange_velocities_in_every_mode(mode):
    world = ps.World(two_discs(mode))
    a, b = (int(i) for i in world.ids)
    world.run(5.0)
    assert world.get(a).velocity[0] == pytest.approx(-1.0, abs=1e-9)
    assert world.get(b).velocity[0] == pytest.approx(1.0, abs=1e-9)


def test_run_takes_the_runner_number_of_steps():
    world = ps.World(two_discs())
    assert world.run(1.0, dt=0.01) == 100  # 1 / 0.01 is 100.00000000000001 in doubles
    assert world.run(0.015, dt=0.01) == 2
    assert world.time == pytest.approx(1.02)


def test_run_mode_becomes_the_world_mode():
    world = ps.World(two_discs())
    world.run(0.1, mode="substep", substeps=8)
    assert (world.mode, world.substeps) == ("substep", 8)
    with pytest.raises(ValueError, match="'discrete', 'substep' or 'exact'"):
        world.run(0.1, mode="quick")


def test_step_returns_the_seconds_simulated_and_refuses_a_bad_dt():
    world = ps.World(two_discs("exact"))
    assert world.step(0.25) == 0.25
    with pytest.raises(ValueError, match="dt"):
        world.step(-1.0)


def test_particles_are_added_and_removed_by_id():
    world = ps.World(two_discs())
    new = world.add((20.0, 20.0), velocity=(1.0, 0.0), mass=2.0, radius=0.5)
    assert new in world and len(world) == 3
    assert world.number(new) == 3
    assert world.get(new).mass == 2.0
    assert world.remove(new)
    assert new not in world
    assert not world.remove(new)
    with pytest.raises(ValueError):
        world.get(new)


def test_a_bad_particle_is_refused_with_the_core_message():
    world = ps.World(two_discs())
    with pytest.raises(ValueError, match=r"radius.*> 0"):
        world.add((1.0, 1.0), radius=-1.0)
    assert len(world) == 2


def test_add_many_adds_all_or_none():
    world = ps.World(two_discs())
    ids = world.add_many(np.array([[10.0, 10.0], [20.0, 10.0]]), masses=[1.0, 2.0], radii=0.5)
    assert len(world) == 4 and world.get(int(ids[1])).mass == 2.0
    with pytest.raises(ValueError, match="particle 1: .*mass"):
        world.add_many(np.array([[30.0, 30.0], [40.0, 30.0]]), masses=[1.0, -1.0])
    assert len(world) == 4


def test_a_periodic_box_wraps_and_keeps_unwrapped_positions():
    scene = ps.Scene()
    scene.world.width = scene.world.height = 10.0
    scene.world.periodic = True
    scene.world.walls = False
    d = ps.ParticleDef()
    d.position, d.velocity, d.radius = (9.0, 5.0), (1.0, 0.0), 0.5
    scene.particles.append(d)
    world = ps.World(scene)
    assert world.periodic
    world.run(2.0, dt=0.01)
    pid = int(world.ids[0])
    assert world.positions[0, 0] == pytest.approx(1.0)
    assert world.unwrapped_position(pid)[0] == pytest.approx(11.0)


def test_obstacles_are_fixed_pegs_the_discs_bounce_off():
    world = ps.World(two_discs())
    world.add_obstacle(ps.Obstacle.peg((45.0, 50.0), 1.0))
    assert world.obstacles[0].kind == "peg"
    world.run(5.0)
    assert world.counters["obstacle_collisions"] >= 2
    with pytest.raises(ValueError):
        world.add_obstacle(ps.Obstacle.peg((500.0, 50.0), 1.0))  # outside the box


def test_friction_turns_a_sliding_disc():
    scene = two_discs("exact", friction=0.5, gravity=(0.0, 9.81))
    scene.particles[1].position = (50.0, 99.0)  # on the floor, sliding
    world = ps.World(scene)
    world.run(0.5)
    assert world.rotation_in_use
    assert abs(world.spins[1]) > 0.0


def test_a_world_refuses_other_calls_while_it_runs_in_a_thread():
    # Proves the GIL is released: the main thread gets to call the world during the run.
    scene = ps.parse_scene('{"version": 1, "world": {"width": 40, "height": 40}, '
                           '"solver": {"mode": "exact"}, '
                           '"generate": {"count": 2000, "radius": 0.1, "temperature": 1}}')
    world = ps.World(scene)
    runner = threading.Thread(target=world.run, args=(200.0,))  # about a second
    runner.start()
    refused = None
    while runner.is_alive() and refused is None:
        try:
            world.time
        except RuntimeError as e:
            refused = str(e)
    runner.join()
    assert refused is not None and "busy" in refused
    assert world.time == pytest.approx(200.0)


def test_worlds_stepped_in_threads_match_worlds_stepped_one_after_the_other(gas):
    serial = [ps.World(gas) for _ in range(2)]
    for w in serial:
        w.run(0.5)
    threaded = [ps.World(gas) for _ in range(2)]
    runners = [threading.Thread(target=w.run, args=(0.5,)) for w in threaded]
    for t in runners:
        t.start()
    for t in runners:
        t.join()
    for s, t in zip(serial, threaded):
        assert np.array_equal(s.positions, t.positions)


def test_to_scene_is_a_snapshot_that_builds_the_same_world(gas):
    world = ps.World(gas)
    world.run(0.2)
    again = ps.World(world.to_scene())
    assert np.array_equal(again.positions, world.positions)
    assert math.isclose(again.kinetic_energy, world.kinetic_energy)


def test_ctrl_c_stops_a_run_between_steps():
    world = ps.World(ps.parse_scene('{"version": 1, "world": {"width": 40, "height": 40}, '
                                    '"generate": {"count": 500, "radius": 0.1, "temperature": 1}}'))
    timer = threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        world.run(1e9)  # years of stepping unless the signal stops it
    timer.join()
    assert 0.0 < world.time < 1e9
    assert world.step() > 0.0  # usable again


@pytest.mark.parametrize("mode", ["discrete", "exact"])
def test_a_run_ends_where_particle_sim_ends_bit_for_bit(tmp_path, preset, mode):
    sim = os.environ.get("PSB_SIM")
    if not sim:
        pytest.skip("PSB_SIM (the particle-sim to compare with) is not set")
    scene = ASSETS / "03-billiards-break.json"
    saved = tmp_path / "final.json"
    subprocess.run([sim, str(scene), "--duration", "2", "--mode", mode, "--save", str(saved)],
                   check=True, capture_output=True)
    world = ps.World(ps.load_scene(scene))
    world.run(2.0, mode=mode)
    by_number = sorted(range(len(world)), key=lambda row: world.number(int(world.ids[row])))
    expected = np.array([p.position for p in ps.load_scene(saved).particles])
    assert np.array_equal(world.positions[by_number], expected)
