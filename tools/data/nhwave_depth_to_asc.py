#!/usr/bin/env python3
"""An NHWAVE depth grid (whitespace-separated rows, row 1 the south edge, depth positive
down) as an ESRI ASCII grid (rows from the north edge, GDAL's dx/dy header for cells
that are not square), values rounded to centimetres.

    nhwave_depth_to_asc.py DEPTH.txt DX DY OUT.asc
"""
import sys


def main(argv):
    if len(argv) != 5:
        sys.exit(__doc__)
    src, dx, dy, out = argv[1], float(argv[2]), float(argv[3]), argv[4]
    with open(src) as f:
        rows = [line.split() for line in f if line.strip()]
    ncols = len(rows[0])
    if any(len(r) != ncols for r in rows):
        sys.exit(f"{src}: rows of different lengths")
    with open(out, "w") as f:
        f.write(f"ncols {ncols}\nnrows {len(rows)}\nxllcorner 0\nyllcorner 0\n")
        f.write(f"dx {dx!r}\ndy {dy!r}\n")
        for r in reversed(rows):  # ESRI ASCII grids start at the north edge
            f.write(" ".join(f"{float(v):.2f}" for v in r) + "\n")


if __name__ == "__main__":
    main(sys.argv)
