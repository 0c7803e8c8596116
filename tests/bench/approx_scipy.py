"""splinefit -e beside scipy's smoothing spline on noisy outlines.

A corpus of closed outlines (the insole of man/figures/insole.knots,
ellipses, blobs), 150 to 1200 points with Gaussian noise of 0.05 to
0.5 mm, made by bin/test/noisy, which also gives the truth.  Each is
approximated by `splinefit -e TOL` (TOL = TOLSIG sigma) and by
scipy.interpolate.splprep with s = n sigma^2, per=1, and both are
measured here, by this script's own evaluation (the cubic record's
Hermite rows, scipy's splev), never by loft's:

  knots    the curve's knots (spans) round the outline
  dist     the largest distance from an input point to the curve
  infl     inflexions (sign changes of the curvature), the truth's after /
  energy   the bending energy, the integral of curvature squared, over
           the truth's
  truth    the Hausdorff distance between the curve and the truth

usage: python3 approx_scipy.py [-q] [-n CASES] [BIN]
  -q: only the summary and the checks; -n: the first CASES cases;
  BIN: the directory of splinefit and test/noisy (default bin).
Exit status 1 if a check fails: every loft curve within TOL of its
points, no more knots than scipy's and at the median at most 0.4 of
them, no inflexion the truth lacks, energy within 10% of the truth's,
as near the truth as scipy's or nearer at the median.
"""
import os
import subprocess
import sys

import numpy as np
from scipy.interpolate import splev, splprep
from scipy.spatial import cKDTree

TOLSIG = 4.0            # the tolerance, in sigmas of the noise
DENSE = 40000           # samples of each curve for the measures


def corpus(ncases):
    rng = np.random.default_rng(14)
    cases = []
    for i in range(60):
        kind = ("insole", "ellipse", "blob")[i % 3]
        n = int(rng.integers(150, 1201))
        sigma = float(np.exp(rng.uniform(np.log(0.05), np.log(0.5))))
        if kind == "insole":
            args = ["insole", "man/figures/insole.knots"]
        elif kind == "ellipse":
            a = rng.uniform(60, 150)
            args = ["ellipse", "%.3f" % a, "%.3f" % (a * rng.uniform(0.3, 0.8))]
        else:
            args = ["blob", "%.3f" % rng.uniform(40, 80),
                    "%.3f" % rng.uniform(0.03, 0.12), str(int(rng.integers(3, 6)))]
        cases.append((args, n, round(sigma, 3), i + 1))
    return cases[:ncases]


def run(cmd, data=None):
    return subprocess.run(cmd, input=data, capture_output=True, text=True,
                          check=False)


def rows(text):
    out = []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line and not line[0].isalpha():
            out.append([float(w) for w in line.split()])
    return np.array(out)


def hermite(seg, u):
    """Points, first and second derivatives of the cubic rows at u."""
    pa, pb, da, db = seg[:, 0:2], seg[:, 2:4], seg[:, 4:6], seg[:, 6:8]
    u = u[None, :, None]
    pa, pb, da, db = (x[:, None, :] for x in (pa, pb, da, db))
    h00, h10 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u
    h01, h11 = -2 * u**3 + 3 * u**2, u**3 - u**2
    p = h00 * pa + h10 * da + h01 * pb + h11 * db
    d1 = (6 * u**2 - 6 * u) * (pa - pb) + (3 * u**2 - 4 * u + 1) * da + \
        (3 * u**2 - 2 * u) * db
    d2 = (12 * u - 6) * (pa - pb) + (6 * u - 4) * da + (6 * u - 2) * db
    return (x.reshape(-1, 2) for x in (p, d1, d2))


def measures(p, d1, d2, du):
    """Inflexions and energy of a closed curve sampled at even steps du
    of its parameter (periodic trapezoid rule)."""
    v = np.hypot(d1[:, 0], d1[:, 1])
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    k = cross / v**3
    length = np.sum(v) * du
    sign = np.sign(np.where(np.abs(k) * length < 1e-9, 0, k))
    sign = sign[sign != 0]
    infl = int(np.sum(sign != np.roll(sign, 1))) if len(sign) else 0
    return infl, float(np.sum(k * k * v) * du)


def polyline_dist(poly, pts):
    """Distance of each of pts to the closed polyline poly."""
    tree = cKDTree(poly)
    _, j = tree.query(pts)
    best = np.full(len(pts), np.inf)
    for a, b in ((j - 1, j), (j, (j + 1) % len(poly))):
        pa, pb = poly[a % len(poly)], poly[b]
        e = pb - pa
        t = np.clip(np.sum((pts - pa) * e, 1) / np.maximum(np.sum(e * e, 1),
                                                          1e-300), 0, 1)
        q = pa + t[:, None] * e
        best = np.minimum(best, np.hypot(*(pts - q).T))
    return best


def judge(curve, d1, d2, du, pts, truth, knots):
    infl, energy = measures(curve, d1, d2, du)
    dist = float(np.max(polyline_dist(curve, pts)))
    haus = max(float(np.max(polyline_dist(truth, curve))),
               float(np.max(polyline_dist(curve, truth))))
    return dict(knots=knots, dist=dist, infl=infl, energy=energy, truth=haus)


def loft(bindir, text, tol, pts, truth):
    r = run([os.path.join(bindir, "splinefit"), "-e", repr(tol)], text)
    if r.returncode != 0:
        return None, r.stderr.strip()
    seg = rows(r.stdout)
    per = max(4, DENSE // len(seg))
    u = np.arange(per) / per
    p, d1, d2 = hermite(seg, u)
    return judge(p, d1, d2, 1.0 / per, pts, truth, len(seg)), None


def scipy_fit(pts, sigma, truth):
    n = len(pts)
    tck, _ = splprep([pts[:, 0], pts[:, 1]], s=n * sigma**2, per=1, k=3,
                     quiet=2)
    t = tck[0]
    knots = len(np.unique(t[3:len(t) - 3])) - 1
    u = np.arange(DENSE) / DENSE
    x, y = splev(u, tck)
    dx, dy = splev(u, tck, der=1)
    ddx, ddy = splev(u, tck, der=2)
    p = np.column_stack([x, y])
    return judge(p, np.column_stack([dx, dy]), np.column_stack([ddx, ddy]),
                 1.0 / DENSE, pts, truth, knots)


def main():
    args = sys.argv[1:]
    quiet = "-q" in args
    args = [a for a in args if a != "-q"]
    ncases = 60
    if args and args[0] == "-n":
        ncases = int(args[1])
        args = args[2:]
    bindir = args[0] if args else "bin"
    noisy = os.path.join(bindir, "test", "noisy")
    out, fails, res = [], [], []
    hdr = ("%-3s %-7s %5s %5s | %5s %6s %5s %6s %6s | %5s %6s %5s %6s %6s"
           % ("#", "shape", "n", "sigma", "knots", "dist", "infl", "energy",
              "truth", "knots", "dist", "infl", "energy", "truth"))
    out.append("%-23s | %-35s | %s" % ("", "splinefit -e %g sigma" % TOLSIG,
                                       "scipy splprep s = n sigma^2"))
    out.append(hdr)
    for args_, n, sigma, seed in corpus(ncases):
        text = run([noisy, "-n", str(n), "-s", str(sigma), "-r", str(seed)]
                   + args_).stdout
        pts = rows(text)
        truth = rows(run([noisy, "-t"] + args_).stdout)
        info = run([noisy, "-i"] + args_).stdout.split()
        tinfl, tenergy = int(info[5]), float(info[3])
        tol = TOLSIG * sigma
        lo, why = loft(bindir, text, tol, pts, truth)
        sp = scipy_fit(pts, sigma, truth)
        name = args_[0]
        if lo is None:
            fails.append("case %d (%s): splinefit -e failed: %s"
                         % (seed, name, why))
            continue
        lo["e"], sp["e"] = lo["energy"] / tenergy, sp["energy"] / tenergy
        res.append((lo, sp, tinfl, sigma, tol))
        row = "%-3d %-7s %5d %5.3f |" % (seed, name, n, sigma)
        for r in (lo, sp):
            row += " %5d %6.3f %2d/%-2d %6.3f %6.3f |" % (
                r["knots"], r["dist"], r["infl"], tinfl,
                r["energy"] / tenergy, r["truth"])
        out.append(row.rstrip(" |"))
        if lo["dist"] > tol * (1 + 1e-6):
            fails.append("case %d: a point %.4g from the curve, tolerance %g"
                         % (seed, lo["dist"], tol))
        if lo["knots"] > sp["knots"]:
            fails.append("case %d: %d knots, scipy %d" % (seed, lo["knots"],
                                                          sp["knots"]))
        if lo["infl"] > tinfl:
            fails.append("case %d: %d inflexions, the truth %d"
                         % (seed, lo["infl"], tinfl))
        if abs(lo["energy"] / tenergy - 1) > 0.1:
            fails.append("case %d: energy %.4g of the truth's"
                         % (seed, lo["energy"] / tenergy))
    if res:
        ratio = np.median([lo["knots"] / sp["knots"] for lo, sp, *_ in res])
        med = lambda k, w: float(np.median([r[w][k] for r in res]))
        lt, st = med("truth", 0), med("truth", 1)
        out.append("")
        out.append("%d outlines: median knots %g (loft) %g (scipy), ratio %.3f;"
                   % (len(res), med("knots", 0), med("knots", 1), ratio))
        out.append("  inflexions beyond the truth's: loft %d, scipy %d;"
                   % (sum(lo["infl"] > t for lo, sp, t, *_ in res),
                      sum(sp["infl"] > t for lo, sp, t, *_ in res)))
        out.append("  a point beyond the tolerance: loft %d, scipy %d; beyond"
                   " 3 sigma: scipy %d;"
                   % (sum(lo["dist"] > tol * (1 + 1e-6) for lo, sp, t, s, tol
                          in res),
                      sum(sp["dist"] > tol for lo, sp, t, s, tol in res),
                      sum(sp["dist"] > 3 * s for lo, sp, t, s, tol in res)))
        out.append("  energy off the truth's by more than 10%%: loft %d, "
                   "scipy %d; median distance to the truth %.3f (loft) "
                   "%.3f (scipy)"
                   % (sum(abs(lo["e"] - 1) > 0.1 for lo, *_ in res),
                      sum(abs(sp["e"] - 1) > 0.1 for lo, sp, *_ in res),
                      lt, st))
        if ratio > 0.4:
            fails.append("median knots ratio %.3f above 0.4" % ratio)
        if lt > st:
            fails.append("median distance to the truth %.4g, scipy %.4g"
                         % (lt, st))
    for line in out if not quiet else out[-4:]:
        print(line)
    for f in fails:
        print("FAIL " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
