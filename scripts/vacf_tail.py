#!/usr/bin/env python3
"""Draws the velocity autocorrelation's long-time tail (docs/observables.md) from particle-sim's
--vacf CSV, as SVG, and prints the log-log slope over the fitted lags.

    scripts/vacf_tail.py vacf.csv vacf-tail.svg [T_FROM T_TO]

x is the lag t, y is C(t)/C(0), both logarithmic; lags where C is not positive (noise at long
lags) are left out. The dashed line is A/t, with A the median of t·C(t)/C(0) over
[T_FROM, T_TO] (default 4 to 40 s), the decade where a 2-D fluid's tail is 1/t (Alder and
Wainwright, 1970); the slope printed is the least-squares one of log C against log t there.
Standard library only.
"""
import csv
import math
import statistics
import sys

W, H = 560, 400
ML, MT, MR, MB = 70, 30, 20, 50


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    t_from, t_to = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) == 5 else (4.0, 40.0)
    with open(sys.argv[1], newline="") as f:
        rows = [(float(r["t_s"]), float(r["vacf_m2_per_s2"])) for r in csv.DictReader(f)]
    if len(rows) < 3 or rows[0][1] <= 0.0:
        sys.exit(f"{sys.argv[1]}: needs a VACF with C(0) > 0 and at least three lags")
    c0 = rows[0][1]
    points = [(t, c / c0) for t, c in rows[1:] if c > 0.0]
    window = [(t, c) for t, c in points if t_from <= t <= t_to]
    if len(window) < 3:
        sys.exit(f"fewer than three positive lags in [{t_from}, {t_to}] s")
    amplitude = statistics.median(t * c for t, c in window)
    lx = [math.log(t) for t, _ in window]
    ly = [math.log(c) for _, c in window]
    mx, my = statistics.fmean(lx), statistics.fmean(ly)
    slope = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
    print(f"slope of log C against log t over [{t_from:g}, {t_to:g}] s: {slope:.3f}; "
          f"A = median t C(t)/C(0) = {amplitude:.4f} s")

    x0, x1 = math.log10(points[0][0]), math.log10(points[-1][0])
    y0 = math.floor(math.log10(min(c for _, c in points)))
    y1 = 0.0
    px = lambda t: ML + (math.log10(t) - x0) / (x1 - x0) * (W - ML - MR)
    py = lambda c: MT + (y1 - math.log10(c)) / (y1 - y0) * (H - MT - MB)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           'font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<rect x="{ML}" y="{MT}" width="{W - ML - MR}" height="{H - MT - MB}" '
           'fill="none" stroke="#444"/>']
    for k in range(int(math.floor(x0)), int(math.ceil(x1)) + 1):
        for m in range(1, 10):
            t = m * 10.0 ** k
            if not (x0 <= math.log10(t) <= x1):
                continue
            out.append(f'<line x1="{px(t):.1f}" y1="{MT}" x2="{px(t):.1f}" y2="{H - MB}" '
                       f'stroke="#ddd"/>')
            if m == 1:
                out.append(f'<text x="{px(t):.1f}" y="{H - MB + 16}" text-anchor="middle">'
                           f'{t:g}</text>')
    for k in range(int(y0), int(y1) + 1):
        c = 10.0 ** k
        out.append(f'<line x1="{ML}" y1="{py(c):.1f}" x2="{W - MR}" y2="{py(c):.1f}" '
                   f'stroke="#ddd"/>')
        out.append(f'<text x="{ML - 6}" y="{py(c) + 4:.1f}" text-anchor="end">1e{k}</text>')
    fit = [(t, amplitude / t) for t in (points[0][0], points[-1][0])]
    out.append(f'<line x1="{px(fit[0][0]):.1f}" y1="{py(fit[0][1]):.1f}" '
               f'x2="{px(fit[1][0]):.1f}" y2="{py(fit[1][1]):.1f}" stroke="#d62728" '
               'stroke-dasharray="6 4"/>')
    for t, c in points:
        inside = t_from <= t <= t_to
        out.append(f'<circle cx="{px(t):.1f}" cy="{py(c):.1f}" r="2" '
                   f'fill="{"#1f77b4" if inside else "#9ab"}"/>')
    out.append(f'<text x="{(ML + W - MR) / 2}" y="{H - 12}" text-anchor="middle">'
               'lag t (s)</text>')
    out.append(f'<text x="16" y="{(MT + H - MB) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {(MT + H - MB) / 2})">C(t) / C(0)</text>')
    out.append(f'<text x="{W - MR - 8}" y="{MT + 18}" text-anchor="end" fill="#d62728">'
               f'{amplitude:.3f} s / t</text>')
    out.append(f'<text x="{W - MR - 8}" y="{MT + 34}" text-anchor="end" fill="#1f77b4">'
               f'slope {slope:.2f} over {t_from:g} to {t_to:g} s</text>')
    out.append("</svg>")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
