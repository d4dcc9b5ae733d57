#!/usr/bin/env python3
"""A 64-seed sweep: serial, on a local Dask cluster, and (optionally) on a running scheduler.

    PYTHONPATH=build/test/python /usr/bin/python3 bench/python_sweep.py \
        [--seeds 64] [--duration 20] [--scheduler tcp://127.0.0.1:8786]

Serial: each run in turn in this process (particle_sandbox._core._run_scene, what a worker
runs). Two processes without Dask: the same runs split between 2 processes of a
multiprocessing pool, in 2 chunks (no scheduler, one message each way per process): what the
machine gives two processes at the moment, the ceiling of any 2-worker speed-up. Local: sweep()
on a LocalCluster of 2 single-threaded worker processes, and sweep()'s default (no client:
threads in this process). --scheduler: sweep() through a scheduler whose
workers were started apart (dask scheduler; dask worker ADDRESS, with PYTHONPATH naming the
module). Prints each one's wall seconds and speed-up over serial; the CPU seconds its processes
used, and from them the speed-up two free cores would give (serial CPU seconds over half the
workers', and over the busiest one's): on a shared machine the wall-clock speed-up says as much
about the other work as about the sweep. And whether every table equals the serial one bit for
bit.
"""

import argparse
import multiprocessing
import os
import time

import numpy as np
import pandas as pd

import particle_sandbox as ps
from particle_sandbox import _core

GAS = """{"version": 1, "world": {"width": 8.0, "height": 8.0},
 "solver": {"mode": "exact", "dt": 0.01},
 "generate": {"count": 1000, "radius": 0.05, "mass": 1.0, "temperature": 1.0, "seed": 1}}"""


def _runs(seeds, duration):
    return [_core._run_scene(GAS, "gas.json", [], duration, 0.0, s) for s in seeds]


def _timed_runs(seeds, duration):
    cpu = time.process_time()
    rows = _runs(seeds, duration)
    return rows, time.process_time() - cpu


def same(a, b):
    return a.shape == b.shape and all(
        np.array_equal(a[c].to_numpy(), b[c].to_numpy(), equal_nan=a[c].dtype.kind == "f")
        for c in a.columns)


def _worker_cpu(client):
    return client.run(time.process_time)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=64)
    parser.add_argument("--duration", type=float, default=20.0)
    parser.add_argument("--scheduler")
    args = parser.parse_args()
    scene = ps.parse_scene(GAS, "gas.json")
    seeds = list(range(1, args.seeds + 1))
    print(f"load average {os.getloadavg()[0]:.2f} (1 min) on {os.cpu_count()} cores at the start")

    # Each way: wall seconds, the table, and the CPU seconds of each process that ran the runs
    # (the workers' own, Dask's work in them included). CPU seconds depend little on what else
    # the machine runs: serial CPU over half the workers' CPU is the speed-up two free cores
    # would give with the runs shared evenly (Dask shares them by how fast each worker gets
    # through them, so on a loaded machine the busiest worker's share says more about the load
    # than about the sweep; it is printed beside).
    start = time.perf_counter()
    rows, serial_cpu = _timed_runs(seeds, args.duration)
    serial_s = time.perf_counter() - start
    serial = pd.DataFrame([{"seed": s, **r} for s, r in zip(seeds, rows)])
    runs = []

    with multiprocessing.get_context("spawn").Pool(2) as pool:
        pool.map(abs, [0, 0])  # processes up before the clock starts
        start = time.perf_counter()
        halves = pool.starmap(_timed_runs, [(seeds[0::2], args.duration),
                                            (seeds[1::2], args.duration)])
        split_s = time.perf_counter() - start
    split_rows = [None] * len(seeds)
    split_rows[0::2], split_rows[1::2] = halves[0][0], halves[1][0]
    runs.append(("2 processes, no Dask", pd.DataFrame(
        [{"seed": s, **r} for s, r in zip(seeds, split_rows)]), split_s, [h[1] for h in halves]))

    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.run(lambda: None)  # workers up before the clock starts
        before = _worker_cpu(client)
        start = time.perf_counter()
        table = ps.sweep(scene, seeds=seeds, duration=args.duration, client=client)
        seconds = time.perf_counter() - start
        after = _worker_cpu(client)
        runs.append(("2 worker processes", table, seconds, [after[w] - before[w] for w in after]))
    cpu = time.process_time()
    start = time.perf_counter()
    table = ps.sweep(scene, seeds=seeds, duration=args.duration)
    seconds = time.perf_counter() - start
    total = time.process_time() - cpu  # the whole process: both threads and the scheduler
    runs.append(("default (threads)", table, seconds, [total / 2, total / 2]))
    if args.scheduler:
        with Client(args.scheduler) as client:
            before = _worker_cpu(client)
            start = time.perf_counter()
            table = ps.sweep(scene, seeds=seeds, duration=args.duration, client=client)
            seconds = time.perf_counter() - start
            after = _worker_cpu(client)
            runs.append((f"scheduler {len(after)} workers", table, seconds,
                         [after[w] - before[w] for w in after]))

    print(f"{'':21s} {'wall s':>7s} {'speed-up':>8s} {'CPU s':>7s} {'free cores':>10s} "
          f"{'busiest':>7s}  same as serial")
    print(f"{'serial':21s} {serial_s:7.2f} {1:8.2f} {serial_cpu:7.2f} {1:10.2f} {1:7.2f}")
    for name, table, seconds, cpus in runs:
        print(f"{name:21s} {seconds:7.2f} {serial_s / seconds:8.2f} {sum(cpus):7.2f} "
              f"{serial_cpu * len(cpus) / sum(cpus):10.2f} {serial_cpu / max(cpus):7.2f}  "
              f"{same(table, serial)}")
    print(f"load average {os.getloadavg()[0]:.2f} (1 min) at the end")


if __name__ == "__main__":
    main()
