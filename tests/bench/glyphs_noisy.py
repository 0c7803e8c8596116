#!/usr/bin/python3
"""glyphs_noisy.py: splinefit -e on noisy glyph contours (issue 23),
beside potrace tracing the same points rasterised.

    glyphs_noisy.py TRUTH WORKDIR [KNOTS]
    glyphs_noisy.py --check K,K... TRUTH [--knots KNOTS] [--seed S]
                    [--points N] [OPTION...]

TRUTH: the designer's outlines of tests/glyphs.py (200 points a
segment); KNOTS: its knot records, whose corners= name the true
corners.  The first 100 contours are sampled at 400 points even in arc
length, with Gaussian noise of 0.1, 0.25 or 0.5% of the contour's size
(sigma), and fitted one by one by splinefit -e 4*sigma (no corners
given: the default finds them, -C finds none).  Where Debian's potrace
is installed, the polygon of the same noisy points is filled on a raster
of pixels sigma wide and traced by potrace (its defaults) to SVG; its
largest path is read back.  Printed for each: the fits that fail, the
curves that cross themselves (their polyline of 30 points a segment),
the Hausdorff distance to the true outline in sigmas (splinefit's curve
sampled a quarter sigma apart at most, potrace's short segments 30 times
each), and the segments, at the median and 90th percentile; for
splinefit also the true corners kept (a corner= joint of the fit within
2 TOL of a true corner that turns by CORNER or more) and its false
corners (a corner= joint farther than 2 TOL from every true corner the
outline has): how many lie within 4 TOL of a true corner,
how many where the true outline turns by CORNER or more within TOL
either side (a bend that turns as a corner does at the scale of the
tolerance), and the rest, and of all the false ones, those where it
turns by CORNER or more within two spacings of the points (or TOL, if
longer) either side (a bend the points cannot tell from a corner); and
the same of potrace's corners (the joints of its path where the tangent
turns by more than KINK).  For splinefit
also what reading the points backwards changes: the contours with a
corner that has none within TOL in the other reading, such corners
(counted from both readings), and the contours whose count of corners
differs.

With --check, only contours K (from 0) are fitted, by splinefit -e
(and the OPTIONs), and a line is printed for each: K, whether the
curve crosses itself (1) or not (0), its Hausdorff distance to the
true outline in sigmas (its curve sampled densely enough, a quarter
sigma apart, for that distance to be the curve's, not its samples'),
the spans splinefit -v says are astray (0 where it says none), the
corners of the curve (its corners= joints), and the least angle its
tangent turns by at one, in degrees (- where it has none); with
--knots, also the true corners kept, how many there are and the false
corners, as above; last, the least radius of curvature of the curve,
in TOLs (0 at a cusp).
--seed draws the noise from seed S instead of the corpus's own, 23;
--points samples each contour at N points instead of 400."""
import math
import os
import random
import re
import shutil
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree

CORNER = math.radians(30)   # a true corner sharper than this must be kept
SEG = 200                   # truth points a segment (tests/glyphs.py)
PER = 30                    # samples a segment of each curve
KINK = math.radians(5)      # a turn between potrace's segments: a corner


def records(text):
    """(header, rows) of each record of a loft stream."""
    recs, cur, head = [], [], ""
    for line in text.splitlines() + [""]:
        w = line.split()
        if not w:
            if cur:
                recs.append((head, np.array(cur)))
            cur = []
        elif w[0][0] in "-.0123456789":
            cur.append([float(x) for x in w])
        else:
            head = line
    return recs


def crosses(p):
    """Whether the closed polyline p has two edges, not neighbours, that
    cross (edges compared in blocks of rows against all).  A point
    within rounding of an edge's line is on it: the samples of a
    straight segment are collinear, and rounding must not make two of
    its edges cross."""
    n = len(p)
    a, b = p, np.roll(p, -1, axis=0)
    eps = 1e-12 * np.ptp(p, axis=0).max() ** 2     # rounding, not a side

    def o(a, b, c):
        s = (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - \
            (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])
        return np.where(abs(s) > eps, s, 0)
    idx = np.arange(n)
    for lo in range(0, n, 256):
        i = idx[lo:lo + 256, None]
        ai, bi = a[lo:lo + 256, None], b[lo:lo + 256, None]
        x = (o(ai, bi, a[None]) * o(ai, bi, b[None]) < 0) & \
            (o(a[None], b[None], ai) * o(a[None], b[None], bi) < 0)
        gap = (idx[None] - i) % n
        if np.any(x & (gap > 1) & (gap < n - 1)):
            return True
    return False


def hermite(rows, per=PER):
    """Samples of a cubic record's Hermite rows (pa pb da db), per a
    segment, closed polyline without its repeated end."""
    u = np.linspace(0, 1, per, endpoint=False)[:, None]
    h00, h10 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u
    h01, h11 = -2 * u**3 + 3 * u**2, u**3 - u**2
    return np.concatenate([h00 * r[0:2] + h01 * r[2:4] + h10 * r[4:6] +
                           h11 * r[6:8] for r in rows])


def bezier(ctl):
    u = np.linspace(0, 1, PER, endpoint=False)[:, None]
    n = len(ctl) - 1
    return sum(math.comb(n, i) * u**i * (1 - u)**(n - i) * ctl[i]
               for i in range(n + 1))


def hausdorff(c, dense):
    return max(cKDTree(dense).query(c)[0].max(),
               cKDTree(c).query(dense)[0].max())


def raster(pts, s):
    """The polygon pts filled (even-odd) on pixels s wide, with a margin
    of 4 pixels: rows top first, and the origin of pixel (0, bottom)."""
    lo = pts.min(axis=0) - 4 * s
    w, h = (np.ceil((pts.max(axis=0) + 4 * s - lo) / s)).astype(int)
    img = np.zeros((h, w), dtype=np.uint8)
    a, b = pts, np.roll(pts, -1, axis=0)
    xc = lo[0] + (np.arange(w) + 0.5) * s
    for r in range(h):
        y = lo[1] + (h - r - 0.5) * s
        hit = (a[:, 1] <= y) != (b[:, 1] <= y)
        x = a[hit, 0] + (y - a[hit, 1]) * (b[hit, 0] - a[hit, 0]) / \
            (b[hit, 1] - a[hit, 1])
        img[r] = (np.searchsorted(np.sort(x), xc) % 2).astype(np.uint8)
    return img, lo


def svg_paths(d):
    """The subpaths of potrace's path data (M m l c z, relative after the
    first M) as lists of segments of control points, in its units."""
    tok = re.findall(r"[MmLlCcZz]|-?[0-9.]+", d)
    subs, cur, start, segs, cmd, i = [], np.zeros(2), None, [], None, 0
    while i < len(tok):
        t = tok[i]
        if t in "MmLlCcZz":
            cmd = t
            i += 1
            if t in "Zz":
                if segs:
                    subs.append(segs)
                segs, cur = [], start.copy()
            continue
        k = 6 if cmd in "Cc" else 2
        v = np.array([float(x) for x in tok[i:i + k]]).reshape(-1, 2)
        i += k
        if cmd in "mlc":
            v = v + cur
        if cmd in "Mm":
            start, cur = v[0], v[0]
            cmd = "l" if cmd == "m" else "L"
            continue
        segs.append(np.vstack([cur, v]))
        cur = v[-1]
    if segs:
        subs.append(segs)
    return subs


def potrace(pts, sigma, work):
    """potrace's trace of the points rasterised: (samples, segments)."""
    img, lo = raster(pts, sigma)
    h, w = img.shape
    pbm = os.path.join(work, "gn.pbm")
    with open(pbm, "wb") as f:
        f.write(b"P4\n%d %d\n" % (w, h))
        f.write(np.packbits(img, axis=1).tobytes())
    svg = subprocess.run(["potrace", "-b", "svg", "-u", "100", "-o", "-",
                          pbm], capture_output=True, text=True).stdout
    subs = []
    for d in re.findall(r'\bd="([^"]*)"', svg):
        subs += svg_paths(d)
    best = max(subs, key=len)
    c = np.concatenate([bezier(g) if len(g) == 4 else
                        np.linspace(g[0], g[1], PER, endpoint=False)
                        for g in best])
    return (lo + c / 100 * sigma, len(best),
            lo + kinks(best) / 100 * sigma)


def kinks(segs):
    """The joints of a closed path (segments of control points) where
    its tangent turns by more than KINK: potrace's corners (it joins
    its curves with one tangent, to within the rounding of its
    output)."""
    def way(v):
        return v / (np.hypot(*v) or 1)
    out = []
    for a, b in zip([segs[-1]] + segs[:-1], segs):
        u = way(a[-1] - a[-2] if np.any(a[-1] != a[-2]) else a[-1] - a[0])
        v = way(b[1] - b[0] if np.any(b[1] != b[0]) else b[-1] - b[0])
        if math.acos(max(-1.0, min(1.0, u @ v))) > KINK:
            out.append(b[0])
    return np.array(out).reshape(-1, 2)


def true_corners(head, t):
    """The truth's corners from the knots' corners=: (point, turn)."""
    m = re.search(r"corners=([0-9,]+)", head or "")
    out = []
    for k in (int(x) for x in m.group(1).split(",")) if m else []:
        i = (k - 1) * SEG
        a, b = t[i] - t[i - 1], t[(i + 1) % len(t)] - t[i]
        out.append((t[i], abs(math.atan2(a[0] * b[1] - a[1] * b[0],
                                         a @ b))))
    return out


def perimeter(t):
    """The length of the closed polyline t."""
    return float(np.sum(np.hypot(*np.diff(np.r_[t, t[:1]], axis=0).T)))


def turn_within(t, p, reach):
    """How far the outline t (a closed polyline) turns, in radians,
    between the points reach along it either side of its point nearest
    p."""
    n = len(t)
    i = int(np.argmin(np.hypot(*(t - p).T)))
    step = np.hypot(*np.diff(np.r_[t, t[:1]], axis=0).T)
    a = b = i
    back = ahead = 0.0
    while back < reach and (i - a) < n // 2:
        a -= 1
        back += step[a % n]
    while ahead < reach and (b - i) < n // 2:
        ahead += step[b % n]
        b += 1
    u, v = t[(a + 1) % n] - t[a % n], t[b % n] - t[(b - 1) % n]
    return abs(math.atan2(u[0] * v[1] - u[1] * v[0], u @ v))


def joints(head, rows):
    """The points of a fit's corner= joints."""
    m = re.search(r"corners=([0-9,]+)", head)
    return np.array([rows[int(x) - 1][0:2] for x in m.group(1).split(",")]
                    if m else np.zeros((0, 2)))


def corners_of(head, rows, tol, truth, t, step=0):
    """corners_at for the fit's corner= joints."""
    return corners_at(joints(head, rows), tol, truth, t, step)


def unmatched(a, b, tol):
    """How many of the points a have none of b within tol."""
    return sum(len(b) == 0 or np.hypot(*(b - p).T).min() > tol for p in a)


def reversal(pts, sigma, head, rows, tally):
    """Fit the points pts read backwards and add to tally (contours
    whose corners differ, corners read forwards, corners either way
    with none within TOL in the other reading, contours whose count of
    corners differs) what that changes."""
    back = splinefit([], pts[::-1], sigma)
    if back.returncode != 0:
        return
    a, b = joints(head, rows), joints(*records(back.stdout)[0])
    u = unmatched(a, b, 4 * sigma) + unmatched(b, a, 4 * sigma)
    tally[0] += u > 0
    tally[1] += len(a)
    tally[2] += u
    tally[3] += len(a) != len(b)


def corners_at(at, tol, truth, t, step=0):
    """(kept, wanted, false, near_true, tight, unresolved) of the corners
    at (points) against the true corners (point, turn) of the outline t:
    the false ones within 4 tol of a true corner, those where the
    outline turns by CORNER within tol either side, and of all the false
    ones those where it turns by CORNER within two spacings step of the
    points (or tol, if longer) either side: a bend the points, that far
    apart, cannot tell from a corner."""
    near = [len(at) and np.hypot(*(at - p).T).min() <= 2 * tol
            for p, _ in truth]
    kept = sum(n for n, (_, a) in zip(near, truth) if a >= CORNER)
    want = sum(a >= CORNER for _, a in truth)
    off = [min([np.hypot(*(p - q)) for q, _ in truth] or [math.inf])
           for p in at]
    false = sum(d > 2 * tol for d in off)
    near_true = sum(2 * tol < d <= 4 * tol for d in off)
    tight = sum(turn_within(t, p, tol) >= CORNER for p, d in zip(at, off)
                if d > 4 * tol)
    unresolved = sum(turn_within(t, p, max(tol, 2 * step)) >= CORNER
                     for p, d in zip(at, off) if d > 2 * tol)
    return kept, want, false, near_true, tight, unresolved


def tally(sums, counts):
    for i, x in enumerate(counts):
        sums[i] += x


def report_corners(name, c):
    kept, want, false, near_true, tight, unresolved = c
    print("  %s corners: %d of %d true corners of %d degrees or more "
          "kept, %d false (%d of them within 4 TOL of a true corner, %d "
          "where the outline turns %d degrees or more within TOL either "
          "side, %d on gentler bends; of all %d, %d where it turns that "
          "much within two spacings of the points, or TOL, either side)" %
          (name, kept, want, round(math.degrees(CORNER)), false, near_true,
           tight, round(math.degrees(CORNER)), false - near_true - tight,
           false, unresolved))


def pct(v, q):
    v = sorted(v)
    return v[int(q * (len(v) - 1))] if v else float("nan")


def report(name, fails, loops, dist, nseg):
    print("  %-9s failures %d, self-crossing curves %d; Hausdorff distance "
          "to the true outline in sigmas: median %.2f, 90%% %.2f, worst "
          "%.2f; segments: median %d, 90%% %d" %
          (name, fails, loops, pct(dist, 0.5), pct(dist, 0.9),
           max(dist) if dist else float("nan"), pct(nseg, 0.5),
           pct(nseg, 0.9)))


def noisy(k, t, rng, npts=400):
    """Contour k of the truth t sampled as the corpus is (at npts
    points): (points, sigma, the dense truth)."""
    tt = np.r_[t, t[:1]]
    d = np.r_[0, np.cumsum(np.hypot(*np.diff(tt, axis=0).T))]
    sigma = [0.001, 0.0025, 0.005][k % 3] * np.ptp(t, axis=0).max()
    u = np.linspace(0, d[-1], npts, endpoint=False)
    pts = np.array([[x + rng.gauss(0, sigma), y + rng.gauss(0, sigma)]
                    for x, y in zip(np.interp(u, d, tt[:, 0]),
                                    np.interp(u, d, tt[:, 1]))])
    pts = np.round(pts, 4)
    dense = np.concatenate([np.linspace(tt[i], tt[i + 1], 20,
                                        endpoint=False)
                            for i in range(len(t))])
    return pts, sigma, dense


def joint_turn(rows, j):
    """The angle a closed cubic record's tangent turns by where its
    segment j starts (radians)."""
    u, v = rows[j - 1][6:8], rows[j][4:6]
    return abs(math.atan2(u[0] * v[1] - u[1] * v[0], u @ v))


def least_radius(rows, per=256):
    """The least radius of curvature of a cubic record's Hermite rows,
    sampled per times a segment, its ends included (a cusp, where the
    curve stops and turns back, has none: 0)."""
    u = np.linspace(0, 1, per + 1)[:, None]
    least = math.inf
    for r in rows:
        p0, p1, d0, d1 = r[0:2], r[2:4], r[4:6], r[6:8]
        # first and second derivatives of the Hermite form in u
        v = (6 * u**2 - 6 * u) * p0 + (-6 * u**2 + 6 * u) * p1 + \
            (3 * u**2 - 4 * u + 1) * d0 + (3 * u**2 - 2 * u) * d1
        a = (12 * u - 6) * p0 + (-12 * u + 6) * p1 + \
            (6 * u - 4) * d0 + (6 * u - 2) * d1
        speed = np.hypot(v[:, 0], v[:, 1])
        cross = np.abs(v[:, 0] * a[:, 1] - v[:, 1] * a[:, 0])
        with np.errstate(divide="ignore", invalid="ignore"):
            rad = np.where(speed == 0, 0.0,
                           np.where(cross > 0, speed ** 3 / cross, math.inf))
        least = min(least, float(np.nanmin(rad)))
    return least


def fine(rows, sigma):
    """Samples of a cubic record a quarter sigma apart at most: with
    PER a segment, the truth's distance to a long segment would be its
    distance to the samples, up to half their spacing."""
    # each span is no longer than its chord and a third of each tangent
    span = max(np.hypot(*(r[2:4] - r[0:2])) + np.hypot(*r[4:6]) / 3 +
               np.hypot(*r[6:8]) / 3 for r in rows)
    return hermite(rows, max(PER, int(np.ceil(span / (0.25 * sigma)))))


def splinefit(opt, pts, sigma):
    """splinefit -e 4 sigma (and opt) of the points, as run."""
    return subprocess.run(["bin/splinefit"] + opt + ["-e", "%g" % (4 * sigma)],
                          input="".join("%.4f %.4f\n" % tuple(p)
                                        for p in pts),
                          capture_output=True, text=True)


def check(which, truth, opt, heads=None, seed=23, npts=400):
    """The --check lines for contours which, fitted with opt; with the
    knot records' heads (their corners), the true corners kept and
    wanted and the false ones too; the noise drawn from seed, npts
    points a contour."""
    rng = random.Random(seed)
    for k, t in enumerate(truth):
        pts, sigma, dense = noisy(k, t, rng, npts)
        if k not in which:
            continue
        fit = splinefit(["-v"] + opt, pts, sigma)
        if fit.returncode != 0:
            print(k, "fails:", fit.stderr.strip())
            continue
        head, rows = records(fit.stdout)[0]
        astray = re.search(r"(\d+) spans? astray", fit.stderr)
        corners = re.search(r"corners=([0-9,]+)", head)
        joints = [int(x) - 1 for x in corners.group(1).split(",")] \
            if corners else []
        print(k, int(crosses(hermite(rows))),
              "%.2f" % (hausdorff(fine(rows, sigma), dense) / sigma),
              astray.group(1) if astray else 0, len(joints),
              "%.1f" % min(math.degrees(joint_turn(rows, j)) for j in joints)
              if joints else "-",
              *(corners_of(head, rows, 4 * sigma, true_corners(heads[k], t),
                           t)[:3] if heads else ()),
              "%.4g" % (least_radius(rows) / (4 * sigma)))


def main():
    if sys.argv[1] == "--check":
        opt, heads, seed, npts = sys.argv[4:], None, 23, 400
        while opt[:1] in (["--knots"], ["--seed"], ["--points"]):
            if opt[0] == "--knots":
                heads = [h for h, _ in records(open(opt[1]).read())]
            elif opt[0] == "--seed":
                seed = int(opt[1])
            else:
                npts = int(opt[1])
            opt = opt[2:]
        check([int(x) for x in sys.argv[2].split(",")],
              [r for _, r in records(open(sys.argv[3]).read())], opt, heads,
              seed, npts)
        return
    truth = [r for _, r in records(open(sys.argv[1]).read())[:100]]
    work = sys.argv[2]
    heads = [h for h, _ in records(open(sys.argv[3]).read())] \
        if len(sys.argv) > 3 else [""] * len(truth)
    have_potrace = shutil.which("potrace") is not None
    rng = random.Random(23)
    res = {"loft": [0, 0, [], []], "loft -C": [0, 0, [], []],
           "potrace": [0, 0, [], []]}
    found = {"loft": [0] * 6, "potrace": [0] * 6}
    back = [0] * 4
    for k, t in enumerate(truth):
        pts, sigma, dense = noisy(k, t, rng)
        tc = true_corners(heads[k], t)
        step = perimeter(t) / len(pts)
        for name, opt in (("loft", []), ("loft -C", ["-C"])):
            fit = splinefit(opt, pts, sigma)
            r = res[name]
            if fit.returncode != 0:
                r[0] += 1
                continue
            head, rows = records(fit.stdout)[0]
            c = hermite(rows)
            r[1] += crosses(c)
            r[2].append(hausdorff(fine(rows, sigma), dense) / sigma)
            r[3].append(len(rows))
            if not opt:
                tally(found["loft"],
                      corners_of(head, rows, 4 * sigma, tc, t, step))
                reversal(pts, sigma, head, rows, back)
        if have_potrace:
            r = res["potrace"]
            c, ns, at = potrace(pts, sigma, work)
            r[1] += crosses(c)
            r[2].append(hausdorff(c, dense) / sigma)
            r[3].append(ns)
            tally(found["potrace"], corners_at(at, 4 * sigma, tc, t, step))
    print("splinefit -e 4 sigma on %d noisy glyph contours (400 points, "
          "sigma 0.1-0.5%% of the size, no corners given)%s" %
          (len(truth), "" if have_potrace else
           "; potrace skipped (no potrace)"))
    report("loft", *res["loft"])
    report("loft -C", *res["loft -C"])
    if have_potrace:
        report("potrace", *res["potrace"])
    report_corners("loft's", found["loft"])
    print("  loft's corners with the points read backwards: other corners "
          "on %d contours (of the %d corners read forwards and those read "
          "backwards, %d have none within TOL in the other reading; the "
          "count differs on %d)" % (back[0], back[1], back[2], back[3]))
    if have_potrace:
        report_corners("potrace's", found["potrace"])


if __name__ == "__main__":
    main()
