#!/usr/bin/env python3
"""A 64-seed sweep: serial, on a local Dask cluster, and (optionally) on a running scheduler.

    PYTHONPATH=build/test/python /usr/bin/python3 bench/python_sweep.py \
        [--seeds 64] [--duration 20] [--scheduler tcp://127.0.0.1:8786]

Serial: each run in turn in this process (particle_sandbox._core._run_scene, what a worker
runs). Local: sweep() on a LocalCluster of 2 single-threaded worker processes, and sweep()'s
default (no client: threads in this process). --scheduler: sweep() through a scheduler whose
workers were started apart (dask scheduler; dask worker ADDRESS, with PYTHONPATH naming the
module). Prints each one's seconds and speed-up over serial, and whether every table equals
the serial one bit for bit.
"""

import argparse
import time

import numpy as np
import pandas as pd

import particle_sandbox as ps
from particle_sandbox import _core

GAS = """{"version": 1, "world": {"width": 8.0, "height": 8.0},
 "solver": {"mode": "exact", "dt": 0.01},
 "generate": {"count": 1000, "radius": 0.05, "mass": 1.0, "temperature": 1.0, "seed": 1}}"""


def same(a, b):
    return a.shape == b.shape and all(
        np.array_equal(a[c].to_numpy(), b[c].to_numpy(), equal_nan=a[c].dtype.kind == "f")
        for c in a.columns)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=64)
    parser.add_argument("--duration", type=float, default=20.0)
    parser.add_argument("--scheduler")
    args = parser.parse_args()
    scene = ps.parse_scene(GAS, "gas.json")
    seeds = list(range(1, args.seeds + 1))

    start = time.perf_counter()
    rows = [_core._run_scene(GAS, "gas.json", [], args.duration, 0.0, s) for s in seeds]
    serial_s = time.perf_counter() - start
    serial = pd.DataFrame([{"seed": s, **r} for s, r in zip(seeds, rows)])
    print(f"serial              {serial_s:7.2f} s")

    from dask.distributed import Client, LocalCluster
    runs = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.run(lambda: None)  # workers up before the clock starts
        start = time.perf_counter()
        runs.append(("2 worker processes", ps.sweep(scene, seeds=seeds, duration=args.duration,
                                                    client=client), time.perf_counter() - start))
    start = time.perf_counter()
    runs.append(("default (threads)", ps.sweep(scene, seeds=seeds, duration=args.duration),
                 time.perf_counter() - start))
    if args.scheduler:
        with Client(args.scheduler) as client:
            start = time.perf_counter()
            runs.append((f"scheduler {len(client.scheduler_info()['workers'])} workers",
                         ps.sweep(scene, seeds=seeds, duration=args.duration, client=client),
                         time.perf_counter() - start))
    for name, table, seconds in runs:
        print(f"{name:19s} {seconds:7.2f} s  speed-up {serial_s / seconds:4.2f}  "
              f"same as serial: {same(table, serial)}")


if __name__ == "__main__":
    main()
