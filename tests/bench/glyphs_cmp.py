#!/usr/bin/python3
"""glyphs_cmp.py: issue 23's table of glyph contours interpolated.  For
each sampled curve record of CURVES beside the designer's outline of the
same record of TRUTH (both as written by tests/glyphs.py and sample -n):
the Hausdorff distance, by nearest sample points (scipy's cKDTree), in
font units (thousandths of an em for these fonts); the contours that
cross themselves; and the inflexions the designer's outline lacks.

    glyphs_cmp.py TRUTH NAME CURVES [NAME CURVES ...]

The peers get rows of their own, made from the knots beside TRUTH (its
name with .truth made .knots): Spiro (libspiro, `[` `]` points beside the
straight spans, corner points at corners) and Hobby (his algorithm as
compare.c has it, cut at corners and straight spans) through
tests/bench/glyphpeers.c, built here; potrace, Debian's, tracing the
outline rasterised at one font unit a pixel.  A peer that is missing is
skipped with one line.  The last line says whether the first row (loft's
default) meets the issue's targets."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
# A run of turns of one sign smaller than this in all (radians) is no
# bend: it is the rounding of the samples (6 decimals of a font unit on a
# step of half a unit turn by 1e-6).  Above it the count is measure(1)'s
# (splinefit -v's) on 39 of the first 40 contours, the one short a bend
# between two samples.
BEND = 1e-4
PER = 50        # samples a Bezier segment of potrace's, as sample -n 50
# A turn sharper than this in one step of the samples is a corner, not
# curvature: glyphs.py's corners turn by more (10 degrees), a curve's
# steps by a few degrees at most
KINK = np.radians(10)


def records(path):
    """The point records of path, a blank line ending each; a record
    holding a number that is not finite (a peer's failure) is None."""
    recs, cur = [], []
    for line in open(path):
        w = line.split()
        if not w:
            if cur:
                a = np.array(cur)
                recs.append(a if np.isfinite(a).all() else None)
            cur = []
        elif len(w) >= 2 and w[0][0] in "-.0123456789ni":
            cur.append([float(w[0]), float(w[1])])
    if cur:
        a = np.array(cur)
        recs.append(a if np.isfinite(a).all() else None)
    return recs


def hausdorff(t, c):
    if c is None or len(c) == 0:
        return np.inf
    return max(cKDTree(t).query(c)[0].max(), cKDTree(c).query(t)[0].max())


def changes(turn, cyclic):
    """Sign changes between the runs of turns of one sign of turn[],
    runs turning less than BEND in all left out."""
    turn = turn[turn != 0]
    if len(turn) == 0:
        return 0
    sign = np.sign(turn)
    cut = np.flatnonzero(sign[1:] != sign[:-1]) + 1
    runs = np.add.reduceat(turn, np.concatenate(([0], cut)))
    runs = np.sign(runs[np.abs(runs) >= BEND])
    if len(runs) < 2:
        return 0
    n = int((runs[1:] != runs[:-1]).sum())
    return n + int(cyclic and runs[0] != runs[-1])


def inflexions(p):
    """The inflexions of the closed polyline p: the changes of sign of
    its turning, its corners (a turn above KINK in one step, where a
    smooth curve sampled at 50 points a segment turns a few degrees) left
    out, as measure(1) counts the sign changes of a curve's curvature."""
    if p is None:
        return 0
    keep = np.any(np.diff(p, axis=0, append=p[:1]) != 0, axis=1)
    p = p[keep]
    if len(p) < 4:
        return 0
    d = np.roll(p, -1, axis=0) - p
    e = np.roll(d, -1, axis=0)
    turn = np.arctan2(d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0],
                      (d * e).sum(axis=1))
    return changes(turn[np.abs(turn) <= KINK], True)


def crossings(peers, path):
    """Per record of path, whether it crosses itself (glyphpeers)."""
    out = subprocess.run([peers, "cross", path], capture_output=True,
                         text=True, check=True).stdout.split()
    return [w == "1" for w in out]


def build(work):
    """glyphpeers built into work; its path and whether it has Spiro."""
    exe, lib = os.path.join(work, "glyphpeers"), os.path.join(TOP, "bin",
                                                              "libloft.a")
    cc = os.environ.get("CC", "cc").split()
    src = os.path.join(HERE, "glyphpeers.c")
    for spiro in (["-DHAVE_SPIRO"], []):
        args = cc + ["-std=c99", "-O2"] + spiro + ["-o", exe, src, lib] + \
            (["-lspiro"] if spiro else []) + ["-lm"]
        if subprocess.run(args, capture_output=True).returncode == 0:
            return exe, bool(spiro)
    return None, False


def rasterise(p):
    """The closed polygon p filled (even-odd) at one unit a pixel, as a
    PBM's bytes, and the font coordinates of the bitmap's lower left."""
    ox, oy = np.floor(p.min(axis=0)) - 2
    w, h = (np.ceil(p.max(axis=0)) - (ox, oy) + 2).astype(int)
    a, b = p - (ox, oy), np.roll(p, -1, axis=0) - (ox, oy)
    lo, hi = np.minimum(a[:, 1], b[:, 1]), np.maximum(a[:, 1], b[:, 1])
    j0, j1 = np.ceil(lo - 0.5).astype(int), np.ceil(hi - 0.5).astype(int)
    cnt = np.maximum(j1 - j0, 0)
    e = np.repeat(np.arange(len(a)), cnt)
    rows = np.repeat(j0, cnt) + np.arange(cnt.sum()) - \
        np.repeat(np.cumsum(cnt) - cnt, cnt)
    t = (rows + 0.5 - a[e, 1]) / (b[e, 1] - a[e, 1])
    xs = a[e, 0] + t * (b[e, 0] - a[e, 0])
    o = np.lexsort((xs, rows))
    rows, cols = rows[o], np.ceil(xs[o] - 0.5).astype(int)
    grid = np.zeros((h, w + 1), dtype=np.int32)
    np.add.at(grid, (rows[0::2], cols[0::2]), 1)
    np.add.at(grid, (rows[1::2], cols[1::2]), -1)
    bits = (np.cumsum(grid, axis=1)[::-1, :w] > 0).astype(np.uint8)
    return b"P4\n%d %d\n" % (w, h) + np.packbits(bits, axis=1).tobytes(), \
        (ox, oy)


def svg_paths(svg):
    """The closed subpaths of potrace's SVG as lists of Bezier segments
    (potrace writes M m l c z, numbers in tenths of a pixel, y up)."""
    scale = float(re.search(r"scale\(([-0-9.e]+)", svg).group(1))
    subs = []
    for d in re.findall(r' d="([^"]*)"', svg):
        cur = start = np.zeros(2)
        cmd, segs = None, []
        toks = re.findall(r"[MmLlCcZz]|-?[0-9.]+(?:e-?[0-9]+)?", d)
        i = 0
        while i < len(toks):
            if toks[i] in "MmLlCcZz":
                cmd = toks[i]
                i += 1
                if cmd in "Zz":
                    if segs:
                        subs.append(segs)
                    segs, cur = [], start
                    continue
            k = 6 if cmd in "Cc" else 2
            v = np.array(toks[i:i + k], dtype=float).reshape(-1, 2)
            i += k
            if cmd.islower():
                v = v + cur
            if cmd in "Mm":
                if segs:
                    subs.append(segs)
                segs, cur, start = [], v[0], v[0]
                cmd = "l" if cmd == "m" else "L"
                continue
            segs.append(np.vstack([cur, v]))
            cur = v[-1]
        if segs:
            subs.append(segs)
    return [[s * scale for s in sub] for sub in subs]


def bezier_points(segs):
    u = np.arange(PER)[:, None] / PER
    pts = []
    for s in segs:
        if len(s) == 2:
            pts.append(s[0] + u * (s[1] - s[0]))
        else:
            pts.append((1 - u) ** 3 * s[0] + 3 * u * (1 - u) ** 2 * s[1] +
                       3 * u * u * (1 - u) * s[2] + u ** 3 * s[3])
    return np.vstack(pts)


def potrace(truth, out):
    """Each outline of truth rasterised and traced by potrace, sampled,
    into out; False where there is no potrace."""
    exe = shutil.which("potrace")
    if exe is None:
        return False
    with open(out, "w") as f, tempfile.TemporaryDirectory() as tmp:
        pbm = os.path.join(tmp, "g.pbm")
        for t in truth:
            img, (ox, oy) = rasterise(t)
            open(pbm, "wb").write(img)
            svg = subprocess.run([exe, "-b", "svg", "-u", "100", "-o", "-",
                                  pbm], capture_output=True, text=True).stdout
            subs = [bezier_points(s) for s in svg_paths(svg)]
            f.write("points\n")
            if not subs:
                f.write("nan nan\n\n")
                continue
            area = [abs((p[:, 0] * np.roll(p[:, 1], -1) - p[:, 1] *
                         np.roll(p[:, 0], -1)).sum()) for p in subs]
            for x, y in subs[int(np.argmax(area))] + (ox, oy):
                f.write("%.6f %.6f\n" % (x, y))
            f.write("\n")
    return True


def row(name, d, cross, new, extra):
    d = np.sort(d)
    n = len(d)
    print("%-22s %8d %8.2f %8.2f %8.2f %8d %8s %8d %8d" % (
        name, n, d[n // 2], d[int(0.9 * (n - 1))], d[-1], sum(cross),
        "-" if new is None else "%d" % new, extra,
        int(np.isinf(d).sum())))


def main():
    truth = records(sys.argv[1])
    work = os.path.dirname(os.path.abspath(sys.argv[1]))
    knots = re.sub(r"\.truth$", "", sys.argv[1]) + ".knots"
    rows = list(zip(sys.argv[2::2], sys.argv[3::2]))
    notes = []
    peers, spiro = build(work)
    if peers is None:
        notes.append("Spiro, Hobby: skipped: tests/bench/glyphpeers.c not "
                     "built (no cc or no bin/libloft.a)")
    elif not os.path.exists(knots):
        notes.append("Spiro, Hobby: skipped: no %s beside the truth" % knots)
        peers = None
    else:
        for peer, name, ok in (("spiro", "Spiro", spiro),
                               ("hobby", "Hobby", True)):
            if not ok:
                notes.append("Spiro: skipped: libspiro not found "
                             "(libspiro-dev)")
                continue
            path = os.path.join(work, "g-%s.pts" % peer)
            with open(path, "w") as f:
                subprocess.run([peers, peer, knots], stdout=f, check=True)
            rows.append((name, path))
    path = os.path.join(work, "g-potrace.pts")
    if potrace(truth, path):
        rows.append(("potrace", path))
    else:
        notes.append("potrace: skipped: no potrace on PATH")
    tinfl = [inflexions(t) for t in truth]
    res = {}
    for name, path in rows:
        curves = records(path)[:len(truth)]
        cross = crossings(peers, path) if peers else [False] * len(curves)
        res[name] = (np.array([hausdorff(t, c) for t, c in zip(truth,
                                                             curves)]),
                     cross[:len(curves)],
                     sum(max(0, inflexions(c) - i) for c, i in
                         zip(curves, tinfl)))
    print("%-22s %8s %8s %8s %8s %8s %8s %8s %8s" % (
        "method", "contours", "median", "90%", "worst", "crossed",
        "newcross", "xinflex", "fails"))
    loft = [n for n, _ in rows if n not in ("Spiro", "Hobby", "potrace")]
    both = "Spiro" in res and "Hobby" in res
    for name, _ in rows:
        d, cross, extra = res[name]
        new = None
        if name in loft and both:
            new = sum(c and not s and not h for c, s, h in
                      zip(cross, res["Spiro"][1], res["Hobby"][1]))
        row(name, d, cross, new, extra)
    for n in notes:
        print(n)
    print("(distance: to the designer's outline, font units; crossed: "
          "contours that cross themselves;\n newcross: of those, crossed "
          "by neither Spiro nor Hobby; xinflex: inflexions the outline\n "
          "lacks, summed over the contours; fails: no curve)")
    if not both or not loft:
        print("targets (issue 23): not judged: Spiro or Hobby missing")
        return
    d, cross, extra = res[loft[0]]
    peer = [np.sort(res[p][0]) for p in ("Spiro", "Hobby")]
    n = len(d)
    med = min(p[len(p) // 2] for p in peer)
    p90 = min(p[int(0.9 * (len(p) - 1))] for p in peer)
    dm, d9 = np.sort(d)[n // 2], np.sort(d)[int(0.9 * (n - 1))]
    new = sum(c and not s and not h for c, s, h in
              zip(cross, res["Spiro"][1], res["Hobby"][1]))
    ok = ["pass" if v else "FAIL" for v in (dm <= med, d9 <= p90, new == 0,
                                           extra < res["Spiro"][2])]
    print("targets (issue 23) for %s: median %.2f <= %.2f %s; 90%% %.2f <= "
          "%.2f %s; newcross %d = 0 %s; xinflex %d < Spiro's %d %s" % (
              loft[0], dm, med, ok[0], d9, p90, ok[1], new, ok[2], extra,
              res["Spiro"][2], ok[3]))


if __name__ == "__main__":
    main()
