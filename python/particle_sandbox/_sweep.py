"""sweep(): ensembles of runs on Dask, one row per run in a pandas DataFrame.

Each run is particle-sim's (the core's runner, with --observables): the scene's JSON with the
run's parameters applied as --set overrides and its seed as --seed, a warm-up, then the
measured run on one thread. A run depends only on its inputs, so the table is the same
whichever workers ran it, in whatever order.
"""

import itertools
import math
import numbers

from . import _core


def _base(scene, regenerates):
    """(text, source, overrides) every run starts from.

    The text the scene was read from when the scene is still what it gave, so that its generate
    blocks are there for seeds and generate.* parameters; the scene as it is (its particles
    listed) when it was changed since, which seeds and generate.* parameters cannot apply to.
    """
    if isinstance(scene, (str, bytes)) or hasattr(scene, "__fspath__"):
        scene = _core._load_scene(str(scene), [])
    unchanged = scene.file_text is not None and _core._parse_scene(
        scene.file_text, scene.source, scene.overrides).to_json() == scene.to_json()
    if unchanged:
        return scene.file_text, scene.source, list(scene.overrides)
    if regenerates:
        why = ("was changed after it was read" if scene.file_text is not None
               else "was not read from a file or text")
        raise ValueError(f"sweep: seeds and generate.* parameters regenerate the particles from "
                         f"the scene file's generate block, but this scene {why}; load it with "
                         f"load_scene or parse_scene and give the changes as params "
                         f"(params={{'world.restitution': [0.9]}})")
    return scene.to_json(), scene.source, []


def _run(text, source, overrides, duration, warmup, seed, mode, dt, observables):
    return _core._run_scene(text, source, overrides, duration, warmup, seed, mode, dt,
                            observables)


def sweep(scene, seeds=None, params=None, duration=1.0, warmup=0.0, mode=None, dt=None,
          client=None, observables=True):
    """Runs every combination of `seeds` and `params` and returns a pandas DataFrame.

    scene: a Scene or a scene file's path. seeds: generate-block seeds (as particle-sim
    --seed), or None for the scene as it is. params: {override path: [values]} (as --set
    PATH=VALUE: "world.restitution", "solver.mode", "generate.packing_fraction", ...).
    duration and warmup: simulated seconds; mode and dt: as particle-sim --mode and --dt.
    client: a dask.distributed.Client to run on; None starts a local cluster in this process
    for the sweep's length, one thread per core (each run releases the GIL, so the threads
    run side by side; and a script needs no `if __name__ == "__main__":` guard, as worker
    processes would).

    The table has one row per run, in the order of itertools.product(seeds, *params values):
    a column per parameter (and `seed`), then each observable and its standard error
    (`temperature`, `temperature_error`, `pressure_virial`, ...; NaN where not measured), then
    theory's values, the step and collision counts; for a scene with bins (a Galton board),
    `bins` (the counts at the end, left to right), `bins_counted`, `bins_outside` and
    `bins_above`. observables=False leaves the observables out (as particle-sim without
    --observables): a scene that starts empty, a Galton board's, has none to measure.
    """
    import pandas as pd

    params = dict(params or {})
    names = list(params)
    for name in names:
        if isinstance(params[name], (str, bytes)) or not hasattr(params[name], "__iter__"):
            raise ValueError(f"sweep: params[{name!r}] must be a list of values")
    seed_list = list(seeds) if seeds is not None else [None]
    for seed in seed_list if seeds is not None else []:
        if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
            raise ValueError(f"sweep: seeds must be whole numbers >= 0 (got {seed!r})")
    for name, value, zero in (("duration", duration, True), ("warmup", warmup, True),
                              ("dt", dt, False)):
        if name == "dt" and value is None:
            continue
        if (isinstance(value, bool) or not isinstance(value, numbers.Real)
                or not math.isfinite(value) or value < 0 or (not zero and value == 0)):
            raise ValueError(f"sweep: {name} must be a finite number of seconds "
                             f"{'>= 0' if zero else '> 0'} (got {value!r})")
    text, source, base = _base(scene, seeds is not None or any(
        n == "generate" or n.startswith(("generate.", "generate[")) for n in names))
    combos = list(itertools.product(seed_list, *(list(params[n]) for n in names)))

    from . import _override_text

    def args(combo):
        seed, values = combo[0], combo[1:]
        overrides = base + [(n, _override_text(v, n)) for n, v in zip(names, values)]
        return (text, source, overrides, float(duration), float(warmup),
                None if seed is None else int(seed), mode, dt, bool(observables))

    if client is None:
        import os

        from dask.distributed import Client, LocalCluster
        # The dashboard on a free port: Debian's distributed serves it even when asked not to,
        # on 8787 by default, and warns when another cluster has that port.
        with LocalCluster(n_workers=1, threads_per_worker=os.cpu_count() or 1, processes=False,
                          dashboard_address=":0") as cluster, Client(cluster) as c:
            rows = _gather(c, [args(k) for k in combos])
    else:
        rows = _gather(client, [args(k) for k in combos])

    table = []
    for combo, row in zip(combos, rows):
        entry = {}
        if seeds is not None:
            entry["seed"] = combo[0]
        entry.update(zip(names, combo[1:]))
        entry.update(row)
        table.append(entry)
    return pd.DataFrame(table)


def _gather(client, arg_list):
    futures = [client.submit(_run, *a, pure=False) for a in arg_list]
    return client.gather(futures)
