#!/usr/bin/env python3
"""world.run(T) from Python against particle-sim on the same scene, mode and thread count.

    PYTHONPATH=build/test/python /usr/bin/python3 bench/python_vs_cli.py \
        build/test/src/cli/particle-sim [--count 10000] [--duration 10] [--repeats 3] \
        [--packing 0.3] [--modes discrete,substep,exact]

For each mode, alternately: particle-sim --duration T --threads 1 (its report's wall_seconds,
the stepping loop alone) and World(scene).run(T) with threads = 1 (time.perf_counter around
run). Prints the best of each and their ratio (Python / particle-sim); docs/python.md keeps the
figures.
"""

import argparse
import json
import pathlib
import subprocess
import tempfile
import time

import particle_sandbox as ps


def scene_text(count, mode, packing):
    # Discs 0.2 m across at kT = 1 J in a square box filled to the packing fraction.
    side = (count * 3.141592653589793 * 0.1 ** 2 / packing) ** 0.5
    return json.dumps({
        "version": 1,
        "world": {"width": side, "height": side},
        "solver": {"mode": mode, "dt": 0.01},
        "generate": {"count": count, "radius": 0.1, "mass": 1.0, "temperature": 1.0, "seed": 1},
    })


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("particle_sim")
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--packing", type=float, default=0.3)
    parser.add_argument("--modes", default="discrete,substep,exact")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for mode in args.modes.split(","):
            path = pathlib.Path(tmp) / f"gas-{mode}.json"
            path.write_text(scene_text(args.count, mode, args.packing))
            cli, py = [], []
            for _ in range(args.repeats):
                out = subprocess.run([args.particle_sim, str(path), "--duration",
                                      str(args.duration), "--threads", "1"],
                                     check=True, capture_output=True, text=True).stdout
                cli.append(json.loads(out)["wall_seconds"])
                world = ps.World(ps.load_scene(path))
                world.threads = 1
                start = time.perf_counter()
                world.run(args.duration)
                py.append(time.perf_counter() - start)
            print(f"{mode:9s} {args.count} discs at {args.packing:g}, {args.duration:g} s: particle-sim "
                  f"{min(cli):.3f} s, Python {min(py):.3f} s, ratio {min(py) / min(cli):.3f}")


if __name__ == "__main__":
    main()
