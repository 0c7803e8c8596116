#!/usr/bin/python3
"""glyphs_cmp.py: the Hausdorff distance of each sampled curve record of
CURVES to the designer's outline of the same record of TRUTH (both as
written by tests/glyphs.py and sample -n), by nearest sample points
(scipy's cKDTree), in font units (thousandths of an em for these fonts).

    glyphs_cmp.py TRUTH NAME CURVES [NAME CURVES ...]

prints one line per NAME: median, 90th percentile and worst."""
import sys

import numpy as np
from scipy.spatial import cKDTree


def records(path):
    recs, cur = [], []
    for line in open(path):
        w = line.split()
        if not w:
            if cur:
                recs.append(np.array(cur))
            cur = []
        elif len(w) >= 2 and w[0][0] in "-.0123456789":
            cur.append([float(w[0]), float(w[1])])
    if cur:
        recs.append(np.array(cur))
    return recs


def main():
    truth = records(sys.argv[1])
    print("%-22s %8s %8s %8s %8s" % ("method", "contours", "median", "90%",
                                     "worst"))
    for name, path in zip(sys.argv[2::2], sys.argv[3::2]):
        curves = records(path)
        d = []
        for t, c in zip(truth, curves):
            a = cKDTree(t).query(c)[0].max()
            b = cKDTree(c).query(t)[0].max()
            d.append(max(a, b))
        d = np.sort(d)
        print("%-22s %8d %8.2f %8.2f %8.2f" % (name, len(d), d[len(d) // 2],
              d[int(0.9 * (len(d) - 1))], d[-1]))


if __name__ == "__main__":
    main()
