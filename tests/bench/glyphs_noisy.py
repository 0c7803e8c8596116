#!/usr/bin/python3
"""glyphs_noisy.py: splinefit -e on noisy glyph contours (issue 23).

    glyphs_noisy.py TRUTH WORKDIR

TRUTH: the designer's outlines of tests/glyphs.py.  The first 100 are
sampled at 400 points even in arc length, with Gaussian noise of 0.1,
0.25 or 0.5% of the contour's size (sigma), and fitted one by one by
splinefit -e 4*sigma (no corners given); printed: the fits that fail,
the curves that cross themselves (their polyline of 30 points a
segment), the Hausdorff distance to the true outline in sigmas, and the
segments, at the median and 90th percentile."""
import random
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree


def records(text):
    recs, cur = [], []
    for line in text.splitlines() + [""]:
        w = line.split()
        if not w:
            if cur:
                recs.append(np.array(cur))
            cur = []
        elif w[0][0] in "-.0123456789":
            cur.append([float(w[0]), float(w[1])])
    return recs


def crosses(p):
    """Whether the closed polyline p has two edges, not neighbours, that
    cross."""
    n = len(p)
    q = np.roll(p, -1, axis=0)

    def o(a, b, c):
        return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - \
            (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])
    for i in range(n):
        j = np.arange(i + 2, n)
        if i == 0:
            j = j[j != n - 1]
        if len(j) and np.any((o(p[i], q[i], p[j]) * o(p[i], q[i], q[j]) < 0) &
                             (o(p[j], q[j], p[i]) * o(p[j], q[j], q[i]) < 0)):
            return True
    return False


def main():
    truth = records(open(sys.argv[1]).read())[:100]
    work = sys.argv[2]
    rng = random.Random(23)
    fails = loops = 0
    dist, nseg = [], []
    for k, t in enumerate(truth):
        tt = np.r_[t, t[:1]]
        d = np.r_[0, np.cumsum(np.hypot(*np.diff(tt, axis=0).T))]
        sigma = [0.001, 0.0025, 0.005][k % 3] * np.ptp(t, axis=0).max()
        u = np.linspace(0, d[-1], 400, endpoint=False)
        pts = "".join("%.4f %.4f\n" % (x + rng.gauss(0, sigma),
                                       y + rng.gauss(0, sigma))
                      for x, y in zip(np.interp(u, d, tt[:, 0]),
                                      np.interp(u, d, tt[:, 1])))
        fit = subprocess.run(["bin/splinefit", "-e", "%g" % (4 * sigma)],
                             input=pts, capture_output=True, text=True)
        if fit.returncode != 0:
            fails += 1
            continue
        nseg.append(len(fit.stdout.strip().splitlines()) - 1)
        c = records(subprocess.run(["bin/sample", "-n", "30"], input=fit.stdout,
                                   capture_output=True, text=True).stdout)[0]
        if np.allclose(c[0], c[-1]):
            c = c[:-1]
        loops += crosses(c)
        dense = np.concatenate([np.linspace(tt[i], tt[i + 1], 20,
                                            endpoint=False)
                                for i in range(len(t))])
        dist.append(max(cKDTree(dense).query(c)[0].max(),
                        cKDTree(c).query(dense)[0].max()) / sigma)
    dist.sort()
    nseg.sort()
    print("splinefit -e 4 sigma on %d noisy glyph contours (400 points, "
          "sigma 0.1-0.5%% of the size, no corners given)" % len(truth))
    print("failures %d, self-crossing curves %d; Hausdorff distance to the "
          "true outline in sigmas: median %.1f, 90%% %.1f, worst %.1f; "
          "segments: median %d" % (fails, loops, dist[len(dist) // 2],
                                   dist[int(0.9 * (len(dist) - 1))], dist[-1],
                                   nseg[len(nseg) // 2]))


if __name__ == "__main__":
    main()
