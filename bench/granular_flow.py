#!/usr/bin/env python3
"""Dense frictional flow: the exact mode against the substep mode at 16 substeps.

For each granular scene the exact mode must flow through as real grains do, at real time:
  - the Galton board with friction 0.2, and with friction 0.5 and restitution 0.5 (balls that
    turn), 20 s: balls released and binned, and the bins' chi-square test;
  - the funnel and the hourglass, with grains that turn and with fixed rotation: grains past
    the neck at 0.5, 1 and 2 s;
and the CPU time per simulated second of each run (1 or less is real time on this machine).

    bench/granular_flow.py BUILD_DIR [--only NAME] [--seconds-scale F]

BUILD_DIR holds src/cli/particle-sim and bench/exact-flow (a Release build). Prints a Markdown
table. --seconds-scale shortens every run (0.25: a quarter of the simulated time) for a quick
look; the figures in docs come from the full runs.
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parent.parent
SCENES = REPO / "assets" / "scenes"


def variant(preset, world=None, generate=None):
    scene = json.loads((SCENES / preset).read_text())
    scene["world"].update(world or {})
    if generate:
        scene["generate"].update(generate)
    return scene


def as_mode(scene, mode):
    s = json.loads(json.dumps(scene))
    s["solver"]["mode"] = mode
    if mode == "substep":
        s["solver"]["substeps"] = 16
    return s


# name, scene, simulated seconds, neck line (None: a board with bins)
CASES = [
    ("galton-friction-0.2", variant("09-galton-board.json", {"friction": 0.2}), 20.0, None),
    ("galton-friction-0.5-e-0.5",
     variant("09-galton-board.json", {"friction": 0.5, "restitution": 0.5}), 20.0, None),
    ("funnel-turning", variant("10-funnel.json", generate={"fixed_rotation": False}), 2.0, 0.5),
    ("funnel-fixed-rotation", variant("10-funnel.json"), 2.0, 0.5),
    ("hourglass-turning", variant("11-hourglass.json", generate={"fixed_rotation": False}), 2.0,
     0.45),
    ("hourglass-fixed-rotation", variant("11-hourglass.json"), 2.0, 0.45),
]


def run_board(sim, path, seconds):
    with tempfile.NamedTemporaryFile(suffix=".json") as report:
        subprocess.run([str(sim), str(path), "--duration", str(seconds), "--report",
                        report.name], check=True, capture_output=True)
        r = json.loads(pathlib.Path(report.name).read_text())
    bins = r["bins"]
    released = sum(d["released"] for d in r.get("droppers", []))
    chi = bins["chi_square"]
    return {"released": released, "binned": bins["counted"], "passes": chi["passes"],
            "cpu_per_s": r["wall_seconds"] / seconds}


def run_neck(flow, path, seconds, below, mode):
    out = subprocess.run([str(flow), str(path), "--duration", str(seconds), "--every", "0.5",
                          "--below", str(below), "--mode", mode], check=True,
                         capture_output=True, text=True).stdout
    past, cpu = {}, 0.0
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 7 and cells[0].replace(".", "").isdigit():
            past[float(cells[0])] = int(cells[6])
        if line.startswith("total:"):
            cpu = float(line.rsplit(",", 1)[1].split()[0])
    return {"past": past, "cpu_per_s": cpu / seconds}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("--only")
    parser.add_argument("--seconds-scale", type=float, default=1.0)
    a = parser.parse_args()
    sim = a.build / "src" / "cli" / "particle-sim"
    flow = a.build / "bench" / "exact-flow"
    for tool in (sim, flow):
        if not tool.exists():
            sys.exit(f"granular_flow: {tool} not found (build the particle-sim and exact-flow "
                     "targets first)")
    print("| scene | mode | released / binned (bins pass χ²) or past the neck at 0.5 / 1 / 2 s "
          "| CPU s per simulated s |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, scene, seconds, below in CASES:
            if a.only and a.only != name:
                continue
            seconds *= a.seconds_scale
            for mode in ("exact", "substep"):
                path = pathlib.Path(tmp) / f"{name}-{mode}.json"
                path.write_text(json.dumps(as_mode(scene, mode)))
                label = "exact" if mode == "exact" else "substep ×16"
                if below is None:
                    r = run_board(sim, path, seconds)
                    what = (f"{r['released']} / {r['binned']} "
                            f"({'passes' if r['passes'] else 'fails'})")
                else:
                    r = run_neck(flow, path, seconds, below, mode)
                    what = " / ".join(str(r["past"].get(t, "–")) for t in (0.5, 1.0, 2.0))
                print(f"| {name} ({seconds:g} s) | {label} | {what} | {r['cpu_per_s']:.2f} |",
                      flush=True)


if __name__ == "__main__":
    main()
