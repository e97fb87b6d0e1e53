#!/usr/bin/env python3
"""Draws the nearshore comparisons (measured against Tidewater) as SVG.

Usage: python3 tools/plot_nearshore.py CSV_DIR OUT_DIR

CSV_DIR holds berkhoff.csv and hansen_svendsen.csv, written by
TIDEWATER_NEARSHORE_CSV=CSV_DIR tidewater_core_tests --gtest_filter='NearshoreMeasurements.*'.
Writes OUT_DIR/nearshore_berkhoff.svg and OUT_DIR/nearshore_hansen_svendsen.svg.
Standard library only.
"""
import csv
import sys
from pathlib import Path

WIDTH, HEIGHT, PAD = 300, 190, 36


def panel(title, xlabel, ylabel, points_measured, line_model, x_range, y_range, ox, oy):
    """One small plot: measured points as circles, Tidewater as a line."""
    (x0, x1), (y0, y1) = x_range, y_range
    w, h = WIDTH - 2 * PAD, HEIGHT - 2 * PAD

    def sx(x):
        return ox + PAD + (x - x0) / (x1 - x0) * w

    def sy(y):
        return oy + PAD + h - (y - y0) / (y1 - y0) * h

    out = [f'<rect x="{ox + PAD}" y="{oy + PAD}" width="{w}" height="{h}" fill="none" stroke="#888"/>',
           f'<text x="{ox + WIDTH / 2}" y="{oy + PAD - 8}" text-anchor="middle" font-size="12">{title}</text>',
           f'<text x="{ox + WIDTH / 2}" y="{oy + HEIGHT - 6}" text-anchor="middle" font-size="10">{xlabel}</text>',
           f'<text x="{ox + 10}" y="{oy + HEIGHT / 2}" font-size="10" transform="rotate(-90 {ox + 10} {oy + HEIGHT / 2})"'
           f' text-anchor="middle">{ylabel}</text>']
    for frac in (0.0, 0.5, 1.0):
        xv, yv = x0 + frac * (x1 - x0), y0 + frac * (y1 - y0)
        out.append(f'<text x="{sx(xv)}" y="{oy + PAD + h + 12}" text-anchor="middle" font-size="9">{xv:g}</text>')
        out.append(f'<text x="{ox + PAD - 3}" y="{sy(yv) + 3}" text-anchor="end" font-size="9">{yv:g}</text>')
    line = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in sorted(line_model))
    out.append(f'<polyline points="{line}" fill="none" stroke="#1f5fa8" stroke-width="1.5"/>')
    for x, y in points_measured:
        out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="2.2" fill="none" stroke="#c0392b"/>')
    return out


def svg(parts, columns, rows, legend):
    total_w, total_h = columns * WIDTH, rows * HEIGHT + 20
    head = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{total_w}" height="{total_h}" font-family="sans-serif">',
            f'<rect width="{total_w}" height="{total_h}" fill="white"/>',
            f'<circle cx="20" cy="{total_h - 10}" r="2.2" fill="none" stroke="#c0392b"/>',
            f'<text x="28" y="{total_h - 6}" font-size="10">measured</text>',
            f'<line x1="90" y1="{total_h - 10}" x2="110" y2="{total_h - 10}" stroke="#1f5fa8" stroke-width="1.5"/>',
            f'<text x="114" y="{total_h - 6}" font-size="10">{legend}</text>']
    return "\n".join(head + parts + ["</svg>"]) + "\n"


def berkhoff(rows, out):
    names = {1: "section 1 (x = 1 m)", 2: "section 2 (x = 3 m)", 3: "section 3 (x = 5 m)", 4: "section 4 (x = 7 m)",
             5: "section 5 (x = 9 m)", 6: "section 6 (y = -2 m)", 7: "section 7 (y = 0 m)", 8: "section 8 (y = 2 m)"}
    parts = []
    for n in range(1, 9):
        sel = [r for r in rows if int(float(r["section"])) == n]
        pts = [(float(r["coordinate"]), float(r["measured"])) for r in sel]
        line = [(float(r["coordinate"]), float(r["tidewater"])) for r in sel]
        xr = (-5.0, 5.0) if n <= 5 else (0.0, 11.0)
        xlabel = "y (m)" if n <= 5 else "x behind the shoal (m)"
        parts += panel(names[n], xlabel, "H/H0", pts, line, xr, (0.0, 2.5), ((n - 1) % 4) * WIDTH, ((n - 1) // 4) * HEIGHT)
    out.write_text(svg(parts, 4, 2, "Tidewater (at the gauges)"))


def hansen_svendsen(rows, out):
    pts = [(float(r["x"]), 100.0 * float(r["measured"])) for r in rows]
    line = [(float(r["x"]), 100.0 * float(r["tidewater"])) for r in rows]
    parts = panel("Hansen & Svendsen, spilling", "x from the toe (m)", "H (cm)", pts, line, (0.0, 11.0), (0.0, 12.0), 0, 0)
    out.write_text(svg(parts, 1, 1, "Tidewater"))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, dst = Path(sys.argv[1]), Path(sys.argv[2])
    with open(src / "berkhoff.csv", newline="") as f:
        berkhoff(list(csv.DictReader(f)), dst / "nearshore_berkhoff.svg")
    with open(src / "hansen_svendsen.csv", newline="") as f:
        hansen_svendsen(list(csv.DictReader(f)), dst / "nearshore_hansen_svendsen.svg")


if __name__ == "__main__":
    main()
