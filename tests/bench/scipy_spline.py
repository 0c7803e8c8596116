"""The benchmark's scipy baseline: for each record of knots on standard
input (or the file named), a periodic cubic spline per coordinate over
chord-length parameters (scipy.interpolate.CubicSpline), sampled at PER
equal steps of each segment's parameter interval plus the closing point,
written with numpy.savetxt at 6 significant digits.

usage: python3 scipy_spline.py PER [FILE]
"""
import sys

import numpy as np
from scipy.interpolate import CubicSpline


def records(lines):
    rows = []
    for line in lines:
        line = line.split("#", 1)[0].strip()
        if not line:
            if rows:
                yield np.array(rows)
            rows = []
            continue
        rows.append([float(w) for w in line.split()])
    if rows:
        yield np.array(rows)


def main():
    per = int(sys.argv[1])
    src = open(sys.argv[2]) if len(sys.argv) > 2 else sys.stdin
    out = sys.stdout
    for knots in records(src):
        closed = np.vstack([knots, knots[:1]])
        chord = np.linalg.norm(np.diff(closed, axis=0), axis=1)
        t = np.concatenate([[0.0], np.cumsum(chord)])
        spline = CubicSpline(t, closed, bc_type="periodic")
        steps = np.arange(per) / per
        u = (t[:-1, None] + chord[:, None] * steps).ravel()
        u = np.append(u, t[-1])
        np.savetxt(out, spline(u), fmt="%.6g")
        out.write("\n")


main()
