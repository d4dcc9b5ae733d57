#!/usr/bin/env python3
"""Draws the work-precision plot of docs/accuracy.md from accuracy-table's CSV, as SVG.

    scripts/accuracy_plot.py accuracy.csv accuracy.svg

One row of panels per scene, one column per error measure; x is the cost (wall seconds per
simulated second), y the error, both logarithmic; one series per mode. An error of zero (or
below the floor of the axis) is drawn at the floor as a hollow marker. The exact mode is the
reference, so its errors are zero by definition except the overlap (rounding only); its cost is
also drawn as a dashed vertical line. Standard library only.
"""
import csv
import math
import sys

FLOOR = 1e-6
METRICS = [
    ("|collisions / exact - 1|", lambda r: abs(num(r["collisions_vs_exact"]) - 1.0)),
    ("missed / exact collisions", lambda r: num(r["missed"]) / r["_exact_collisions"]
     if r["_exact_collisions"] > 0 else float("nan")),
    ("max overlap / radius", lambda r: num(r["max_overlap_over_r"])),
    ("KE error (of KE(0))", lambda r: num(r["ke_error"])),
    ("|pressure / exact - 1|", lambda r: abs(num(r["pressure_vs_exact"]) - 1.0)),
]
# Chaotic (many-particle) scenes agree with exact only statistically: a dotted grey line marks 1/sqrt(count),
# the relative noise of a count of independent events, for the count the measure rests on.
NOISE = {0: "collisions", 4: "wall_collisions"}
COLORS = {"discrete": "#d62728", "substep": "#1f77b4", "exact": "#2ca02c"}
PW, PH = 230, 170          # panel size
ML, MT, MR, MB = 55, 22, 12, 32  # panel margins
LEFT, TOP = 130, 60


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def log_range(values):
    vals = [v for v in values if v > 0 and math.isfinite(v)]
    if not vals:
        return -1, 1
    lo, hi = math.floor(math.log10(min(vals))), math.ceil(math.log10(max(vals)))
    return (lo, hi) if hi > lo else (lo, lo + 1)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: accuracy_plot.py accuracy.csv out.svg\n")
        return 2
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    exact_coll = {r["scene"]: num(r["collisions"]) for r in rows if r["mode"] == "exact"}
    exact_rows = {r["scene"]: r for r in rows if r["mode"] == "exact"}
    for r in rows:
        r["_exact_collisions"] = exact_coll.get(r["scene"], 0.0)
        r["_cost"] = num(r["wall_s_per_sim_s"])

    width = LEFT + len(METRICS) * PW + 20
    height = TOP + len(scenes) * PH + 50
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="10">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="18" text-anchor="middle" font-size="14">Work-precision: '
           'error against cost (wall s per simulated s), log-log</text>']
    # Legend.
    lx = LEFT
    for mode, color in COLORS.items():
        out.append(f'<circle cx="{lx}" cy="36" r="4" fill="{color}"/>'
                   f'<text x="{lx + 8}" y="40">{mode}</text>')
        lx += 90
    out.append(f'<text x="{lx}" y="40">hollow: zero or below {FLOOR:g} (drawn at the floor); '
               'grey dotted: 1/sqrt(exact count), the statistical noise of a count</text>')
    for mi, (title, _) in enumerate(METRICS):
        out.append(f'<text x="{LEFT + mi * PW + ML + (PW - ML - MR) / 2}" y="{TOP - 4}" '
                   f'text-anchor="middle" font-size="11">{title}</text>')

    for si, scene in enumerate(scenes):
        srows = [r for r in rows if r["scene"] == scene]
        out.append(f'<text x="{LEFT - 8}" y="{TOP + si * PH + PH / 2}" text-anchor="end" '
                   f'font-size="11">{scene}</text>')
        xlo, xhi = log_range([r["_cost"] for r in srows])
        for mi, (_, fn) in enumerate(METRICS):
            x0 = LEFT + mi * PW + ML
            y0 = TOP + si * PH + MT
            w, h = PW - ML - MR, PH - MT - MB
            vals = [fn(r) for r in srows]
            ylo, yhi = log_range([max(v, FLOOR) for v in vals if math.isfinite(v)] + [FLOOR])
            ylo = max(ylo, int(math.log10(FLOOR)))

            def px(v):
                return x0 + (math.log10(v) - xlo) / (xhi - xlo) * w

            def py(v):
                return y0 + h - (math.log10(v) - ylo) / (yhi - ylo) * h

            out.append(f'<rect x="{x0}" y="{y0}" width="{w}" height="{h}" fill="none" '
                       'stroke="#999"/>')
            # Only many-particle scenes are chaotic; a few discs on a line are deterministic.
            if mi in NOISE and scene in exact_rows and num(exact_rows[scene]["particles"]) >= 100:
                count = num(exact_rows[scene][NOISE[mi]])
                if count > 0 and 10.0 ** ylo <= count ** -0.5 <= 10.0 ** yhi:
                    y = py(count ** -0.5)
                    out.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x0 + w}" y2="{y:.1f}" '
                               'stroke="#888" stroke-dasharray="1,2"/>')
            xstep = max(1, (xhi - xlo + 3) // 4)
            for e in range(xlo, xhi + 1, xstep):
                x = px(10.0 ** e)
                out.append(f'<line x1="{x}" y1="{y0 + h}" x2="{x}" y2="{y0 + h + 3}" '
                           'stroke="#999"/>'
                           f'<text x="{x}" y="{y0 + h + 13}" text-anchor="middle">1e{e}</text>')
            ystep = max(1, (yhi - ylo + 3) // 4)
            for e in range(ylo, yhi + 1, ystep):
                y = py(10.0 ** e)
                out.append(f'<line x1="{x0 - 3}" y1="{y}" x2="{x0}" y2="{y}" stroke="#999"/>'
                           f'<text x="{x0 - 5}" y="{y + 3}" text-anchor="end">1e{e}</text>')
            for mode, color in COLORS.items():
                pts = []
                for r, v in zip(srows, vals):
                    if r["mode"] != mode or not math.isfinite(v) or not r["_cost"] > 0:
                        continue
                    pts.append((px(r["_cost"]), py(max(v, FLOOR)), v >= FLOOR))
                if mode == "exact":
                    for x, _, _ in pts:
                        out.append(f'<line x1="{x}" y1="{y0}" x2="{x}" y2="{y0 + h}" '
                                   f'stroke="{color}" stroke-dasharray="3,3"/>')
                pts.sort()
                if len(pts) > 1:
                    path = " ".join(f"{x:.1f},{y:.1f}" for x, y, _ in pts)
                    out.append(f'<polyline points="{path}" fill="none" stroke="{color}" '
                               'stroke-opacity="0.6"/>')
                for x, y, solid in pts:
                    fill = color if solid else "white"
                    out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3" fill="{fill}" '
                               f'stroke="{color}"/>')
    out.append(f'<text x="{LEFT + len(METRICS) * PW / 2}" y="{height - 12}" '
               'text-anchor="middle" font-size="11">cost: wall seconds per simulated second '
               '(lower is cheaper)</text>')
    out.append("</svg>")
    with open(argv[2], "w") as f:
        f.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
