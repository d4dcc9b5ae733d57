"""Shared fixtures of the Python module's tests (tests/python/CMakeLists.txt runs them)."""

import pathlib

import pytest

import particle_sandbox as ps

ASSETS = pathlib.Path(__file__).resolve().parents[2] / "assets" / "scenes"

# A small hard-disc gas with a generate block (so that a seed regenerates it).
GAS = """{
  "version": 1,
  "world": {"width": 2.0, "height": 2.0},
  "solver": {"mode": "exact", "dt": 0.01},
  "generate": {"count": 100, "radius": 0.025, "mass": 1.0, "temperature": 0.1, "seed": 1}
}"""


@pytest.fixture
def gas():
    return ps.parse_scene(GAS, "gas.json")


@pytest.fixture
def preset():
    """A preset scene by its file name."""
    return lambda name: ps.load_scene(ASSETS / name)


def two_discs(mode="discrete", **world):
    """Two unit discs 10 m apart in a 100 m box, closing at 2 m/s."""
    scene = ps.Scene()
    scene.world.width = 100.0
    scene.world.height = 100.0
    for key, value in world.items():
        setattr(scene.world, key, value)
    scene.solver.mode = mode
    scene.dt = 0.01
    for x, vx in ((40.0, 1.0), (50.0, -1.0)):
        d = ps.ParticleDef()
        d.position = (x, 50.0)
        d.velocity = (vx, 0.0)
        scene.particles.append(d)
    return scene
