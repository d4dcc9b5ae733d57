"""particle_sandbox: the Particle Sandbox engine from Python.

A scene is loaded (load_scene), changed if wanted (scene.world.restitution = 0.9), and made into
a World, which steps (world.step, world.run) and shows its particles as read-only NumPy views
of its own storage (world.positions, world.velocities, ...). Units are SI throughout: metres,
seconds, kilograms. docs/python.md describes the module.
"""

import json as _json
import math as _math

try:
    import numpy as _numpy  # noqa: F401  (the compiled module's arrays are NumPy's)
except ImportError as _error:
    import sys as _sys
    raise ImportError(
        f"particle_sandbox needs NumPy, which this Python ({_sys.executable}) cannot import: run "
        f"it with the Python the module was built for, Debian's /usr/bin/python3 with "
        f"python3-numpy (docs/python.md, 'Build and import')") from _error

from ._core import (
    Dropper,
    DropperList,
    Measured,
    Obstacle,
    ObstacleList,
    Observables,
    Particle,
    ParticleDef,
    ParticleDefList,
    Scene,
    SceneError,
    SolverSettings,
    World,
    WorldDef,
)
from ._core import _load_scene, _parse_scene

__all__ = [
    "Dropper", "Measured", "Obstacle", "Observables", "Particle", "ParticleDef", "Scene",
    "SceneError", "SolverSettings", "World", "WorldDef", "animate", "load_scene", "parse_scene",
    "plot", "sweep",
]


def _override_text(value, path="override"):
    """A Python value as the JSON text an override takes (a str is taken as it is written).
    A number that is not finite (NaN, infinity), which JSON cannot hold, is refused naming
    `path`."""
    if isinstance(value, str):
        return value
    if hasattr(value, "tolist"):  # NumPy scalars and arrays
        value = value.tolist()
    try:
        return _json.dumps(value, allow_nan=False)
    except ValueError:
        raise ValueError(f"{path}: must be a finite number (got {value!r})") from None


def _overrides(changes):
    if changes is None:
        return []
    if not hasattr(changes, "items"):
        raise TypeError(f"overrides: expected a dict {{path: value}}, such as "
                        f"{{'world.restitution': 0.9}} (got {type(changes).__name__} {changes!r})")
    return [(str(path), _override_text(value, str(path))) for path, value in changes.items()]


def load_scene(path, overrides=None):
    """Reads a scene file (docs/scenes.md), its generate blocks expanded.

    overrides: {path: value} applied to the file's JSON before it is read, as particle-sim's
    --set PATH=VALUE does ({"world.restitution": 0.9, "generate.seed": 7}). Raises SceneError
    (a ValueError) naming the file, the JSON path and the problem.
    """
    return _load_scene(str(path), _overrides(overrides))


def parse_scene(text, source="<string>", overrides=None):
    """A scene from scene-file JSON text; `source` names it in messages. As load_scene."""
    return _parse_scene(text, source, _overrides(overrides))


def plot(world, ax=None, **kwargs):
    """Draws the world's box, obstacles and particles with Matplotlib; returns the Axes."""
    from ._plot import plot as _plot
    return _plot(world, ax=ax, **kwargs)


def animate(world, duration, frames=50, ax=None, **kwargs):
    """A Matplotlib animation of `duration` seconds of the world, stepped as it plays.

    In a notebook: IPython.display.HTML(particle_sandbox.animate(world, 2.0).to_jshtml()).
    """
    from ._plot import animate as _animate
    return _animate(world, duration, frames=frames, ax=ax, **kwargs)


def sweep(scene, seeds=None, params=None, duration=1.0, warmup=0.0, mode=None, dt=None,
          client=None, observables=True):
    """Runs every combination of seeds and parameters on Dask; returns a pandas DataFrame.

    See particle_sandbox._sweep.sweep (docs/python.md).
    """
    from ._sweep import sweep as _sweep
    return _sweep(scene, seeds=seeds, params=params, duration=duration, warmup=warmup,
                  mode=mode, dt=dt, client=client, observables=observables)
