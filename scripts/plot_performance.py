#!/usr/bin/env python3
"""Turns Google Benchmark JSON from bench_gas (and bench_box2d) into the figures of
docs/performance.md: a log-log SVG of nanoseconds per particle-step against N, and Markdown
tables on standard output. Standard library only.

    scripts/plot_performance.py OUT.svg RESULTS.json [MORE.json ...] > tables.md

With --benchmark_repetitions, the median of the repetitions is used and the spread
(min..max over repetitions) is printed next to it.
"""
import json
import math
import re
import sys
from collections import defaultdict

NAME = re.compile(r"^(?P<family>[a-z0-9-]+)/(?P<rest>.*?)(/iterations:\d+)?(/real_time)?$")


def load(paths):
    """{name: [ns per particle-step, one per repetition]} and {name: counters}."""
    runs, counters = defaultdict(list), {}
    global cpu_runs
    cpu_runs = defaultdict(list)
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        for b in data["benchmarks"]:
            if b.get("run_type") == "aggregate" or "error_occurred" in b:
                continue
            m = NAME.match(b["run_name"] if "run_name" in b else b["name"])
            if not m or "items_per_second" not in b:
                continue
            name = m.group("family") + "/" + m.group("rest")
            runs[name].append(1e9 / b["items_per_second"])
            n = int(name.rsplit("/n:", 1)[1])
            scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
            cpu_runs[name].append(b["cpu_time"] * scale / n)
            counters[name] = b
    return runs, counters


def median(v):
    s = sorted(v)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def parse(name):
    """('gas', series, N) or ('box2d', 'box2d', N) or ('feature', label, N)."""
    parts = name.split("/")
    n = int(parts[-1].split(":")[1])
    if parts[0] == "gas":
        t = int(parts[2].replace("threads:", ""))
        return "gas", f"{parts[1]}, {t} thread" + ("s" if t > 1 else ""), n
    if parts[0] == "spread":
        return "spread", f"{parts[1]}", n
    if parts[0] == "box2d":
        return "box2d", "Box2D 2.4.1, 1 thread", n
    return "feature", parts[1], n


def svg(series, path):
    w, h, left, right, top, bottom = 760, 480, 70, 230, 20, 50
    xs = [n for pts in series.values() for n, _ in pts]
    ys = [y for pts in series.values() for _, y in pts]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    px = lambda n: left + (math.log10(n) - x0) / (x1 - x0) * (w - left - right)
    py = lambda v: h - bottom - (math.log10(v) - y0) / (y1 - y0) * (h - top - bottom)
    # One colour per broadphase; dashed lines for more than one thread.
    colours = {"grid": "#1f77b4", "quadtree": "#2ca02c", "all-pairs": "#d62728",
               "Box2D 2.4.1": "#444444"}
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>']
    for e in range(x0, x1 + 1):
        x = px(10 ** e)
        out.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{h - bottom}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{h - bottom + 16}" text-anchor="middle">1e{e}</text>')
    for e in range(y0, y1 + 1):
        for m in (1, 2, 5):
            v = m * 10 ** e
            if v > 10 ** y1:
                break
            y = py(v)
            out.append(f'<line x1="{left}" y1="{y:.1f}" x2="{w - right}" y2="{y:.1f}" '
                       f'stroke="{"#ccc" if m == 1 else "#eee"}"/>')
            out.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{v:g}</text>')
    out.append(f'<text x="{(left + w - right) / 2}" y="{h - 12}" text-anchor="middle">'
               f'particles N</text>')
    out.append(f'<text transform="translate(16,{(top + h - bottom) / 2}) rotate(-90)" '
               f'text-anchor="middle">ns per particle-step (lower is better)</text>')
    for k, (label, pts) in enumerate(sorted(series.items())):
        c = colours.get(label.split(",")[0], "#9467bd")
        dash = ' stroke-dasharray="6,4"' if "threads" in label else ""
        pts = sorted(pts)
        d = " ".join(f"{px(n):.1f},{py(v):.1f}" for n, v in pts)
        out.append(f'<polyline points="{d}" fill="none" stroke="{c}" stroke-width="2"{dash}/>')
        for n, v in pts:
            out.append(f'<circle cx="{px(n):.1f}" cy="{py(v):.1f}" r="3" fill="{c}"/>')
        ly = top + 14 + 18 * k
        out.append(f'<line x1="{w - right + 10}" y1="{ly - 4}" x2="{w - right + 30}" '
                   f'y2="{ly - 4}" stroke="{c}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{w - right + 36}" y="{ly}">{label}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs, counters = load(sys.argv[2:])
    series = defaultdict(list)
    table = defaultdict(dict)
    global label_names
    label_names = {}
    features = {}
    spreads = {}
    for name, values in runs.items():
        kind, label, n = parse(name)
        med = median(values)
        if kind == "feature":
            features[label] = (med, min(values), max(values), counters[name])
            continue
        if kind == "spread":
            spreads[(label, n)] = (med, min(values), max(values), counters[name])
            continue
        series[label].append((n, med))
        label_names[(label, n)] = name
        table[label][n] = (med, min(values), max(values), counters[name])
    if series:
        svg(series, sys.argv[1])

    sizes = sorted({n for row in table.values() for n in row})
    if sizes:
        print("Million particle-steps per second (median; min..max over repetitions in "
              "brackets)\n")
        print("| broadphase, threads | " + " | ".join(f"N = {n:,}" for n in sizes) + " |")
        print("|---|" + "---|" * len(sizes))
        for label in sorted(table):
            cells = []
            for n in sizes:
                if n in table[label]:
                    med, lo, hi, _ = table[label][n]
                    cells.append(f"{1e3 / med:.1f} [{1e3 / hi:.1f}..{1e3 / lo:.1f}]")
                else:
                    cells.append("")
            print(f"| {label} | " + " | ".join(cells) + " |")

        print("\nOne thread, from the benchmark thread's CPU time instead of wall-clock time (time the "
              "thread spent descheduled by other processes is not counted), million particle-steps "
              "per second, median\n")
        print("| broadphase | " + " | ".join(f"N = {n:,}" for n in sizes) + " |")
        print("|---|" + "---|" * len(sizes))
        for label in sorted(table):
            if "threads" in label:
                continue
            cells = []
            for n in sizes:
                if n in table[label]:
                    cpu = median(cpu_runs[label_names[(label, n)]])
                    cells.append(f"{1e3 / cpu:.1f}")
                else:
                    cells.append("")
            print(f"| {label.split(',')[0]} | " + " | ".join(cells) + " |")

        print("\nBytes per particle (World::memoryBytes() / N: particle arrays, id table, step scratch)\n")
        print("| broadphase | " + " | ".join(f"N = {n:,}" for n in sizes) + " |")
        print("|---|" + "---|" * len(sizes))
        for label in sorted(table):
            if "threads" in label or "bytes_per_particle" not in next(iter(table[label].values()))[3]:
                continue
            cells = [f"{table[label][n][3]['bytes_per_particle']:.1f}" if n in table[label] else ""
                     for n in sizes]
            print(f"| {label.split(',')[0]} | " + " | ".join(cells) + " |")

    grid = next((table[l] for l in table if l.startswith("grid, 1 ")), None)
    if grid and 10000 in grid and 1000000 in grid:
        print(f"\nGrid, 1 thread, wall clock: cost per particle-step at N = 1e6 / at N = 1e4 = "
              f"{grid[1000000][0] / grid[10000][0]:.2f}")
    gname = {n: label_names.get(("grid, 1 thread", n)) for n in (10000, 1000000)}
    if all(gname.values()):
        ratio = median(cpu_runs[gname[1000000]]) / median(cpu_runs[gname[10000]])
        print(f"Grid, 1 thread, by CPU time: cost per particle-step at N = 1e6 / at N = 1e4 = "
              f"{ratio:.2f}")
    grid2 = next((table[l] for l in table if l.startswith("grid, 2 ")), None)
    if grid2 and 10000 in grid2 and 1000000 in grid2:
        print(f"Grid, 2 threads, wall clock: cost per particle-step at N = 1e6 / at N = 1e4 = "
              f"{grid2[1000000][0] / grid2[10000][0]:.2f}")
    box = next((table[l] for l in table if l.startswith("Box2D")), None)
    if box and grid:
        print("\nSpeed-up over Box2D 2.4.1 (same gas scene): " + ", ".join(
            f"N = {n:,}: grid 1 thread {box[n][0] / grid[n][0]:.1f}x"
            + (f", 2 threads {box[n][0] / grid2[n][0]:.1f}x" if grid2 and n in grid2 else "")
            for n in sorted(box) if n in grid))

    if spreads:
        ns = sorted({n for _, n in spreads})
        print("\nRadii log-uniform over 1000x (largest 10 m), packing fraction 0.1, 1 thread: "
              "million particle-steps per second, median [min..max] (label: broadphase used)\n")
        print("| broadphase | " + " | ".join(f"N = {n:,}" for n in ns) + " |")
        print("|---|" + "---|" * len(ns))
        for label in sorted({l for l, _ in spreads}):
            cells = []
            for n in ns:
                med, lo, hi, b = spreads[(label, n)]
                cells.append(f"{1e3 / med:.2f} [{1e3 / hi:.2f}..{1e3 / lo:.2f}]"
                             + (f" ({b.get('label', '')})" if label == "auto" else ""))
            print(f"| {label} | " + " | ".join(cells) + " |")

    if features:
        print("\nFeature cost (N = 100,000, grid, 1 thread; ms per step, median [min..max]; "
              "stage column = that stage's own time)\n")
        print("| feature | step ms | stage µs per step |")
        print("|---|---|---|")
        stage = {"gravity": "gravity_us", "walls": "walls_us", "friction": "resolve_separate_us"}
        for label in sorted(features):
            med, lo, hi, b = features[label]
            n = 100000
            key = stage[label.split(":")[0]]
            print(f"| {label} | {med * n / 1e6:.2f} [{lo * n / 1e6:.2f}..{hi * n / 1e6:.2f}] "
                  f"| {b.get(key, 0.0):.1f} ({key[:-3]}) |")


if __name__ == "__main__":
    main()
