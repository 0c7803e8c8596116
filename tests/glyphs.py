#!/usr/bin/python3
"""glyphs.py: glyph contours of typefaces Debian ships, read with
fontTools at test time (the fonts are never copied into the tree), as
loft knot records: each contour's on-curve points as knots, with
corners= (where the outline's tangent turns by more than 10 degrees)
and straight= (a line segment that a curve meets smoothly at either
end), and beside it the designer's outline sampled densely.

    glyphs.py KNOTS TRUTH [N] [FONT ...]

KNOTS gets the knot records, TRUTH one record of the designer's outline
per contour (200 points a segment, the same order); N contours at most
(default 200), of 5 to 60 on-curve points.  Exit 0 with nothing written
and one line on stderr where no font or no fontTools is found."""
import math
import sys

FONTS = ["/usr/share/fonts/truetype/freefont/FreeSerif.ttf",
         "/usr/share/fonts/opentype/linux-libertine/LinLibertine_R.otf",
         "/usr/share/fonts/opentype/ebgaramond/EBGaramond12-Regular.otf"]
LETTERS = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789&"
KINK = math.radians(10)     # a turn sharper than this is a corner
TINY = 0.01                 # font units: a segment shorter is none


def contours(font):
    """The contours of each glyph of LETTERS: lists of segments, each a
    list of Bezier control points (2 for a line, 3 quadratic, 4 cubic)."""
    from fontTools.pens.recordingPen import DecomposingRecordingPen
    from fontTools.pens.basePen import decomposeQuadraticSegment
    gs = font.getGlyphSet()
    cmap = font.getBestCmap()
    for ch in LETTERS:
        name = cmap.get(ord(ch))
        if name is None:
            continue
        pen = DecomposingRecordingPen(gs)
        gs[name].draw(pen)
        cur, start, segs = None, None, []
        for op, args in pen.value:
            if op == "moveTo":
                cur = start = args[0]
                segs = []
            elif op == "lineTo":
                segs.append([cur, args[0]])
                cur = args[0]
            elif op == "curveTo":
                segs.append([cur] + list(args))
                cur = args[-1]
            elif op == "qCurveTo":
                if args[-1] is None:    # an all-off-curve contour
                    continue
                for c, e in decomposeQuadraticSegment(args):
                    segs.append([cur, c, e])
                    cur = e
            elif op in ("closePath", "endPath"):
                if cur != start:
                    segs.append([cur, start])
                # a segment of no length (a lineTo to where the pen is,
                # or a CFF contour closed a rounding away from its start)
                # would make two knots one
                segs = [s for s in segs if any(math.dist(q, s[0]) > TINY
                                               for q in s[1:])]
                if len(segs) >= 3:
                    yield ch, segs
                segs = []


def tangent(seg, end):
    """The unit direction of a segment at its start (0) or end (1)."""
    pts = seg if end == 0 else seg[::-1]
    for q in pts[1:]:
        dx, dy = q[0] - pts[0][0], q[1] - pts[0][1]
        if dx or dy:
            d = math.hypot(dx, dy)
            return (dx / d, dy / d) if end == 0 else (-dx / d, -dy / d)
    return None


def turn(a, b):
    if a is None or b is None:
        return math.pi
    return abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))


def point(seg, u):
    n = len(seg) - 1
    x = y = 0.0
    for i, q in enumerate(seg):
        c = math.comb(n, i) * u ** i * (1 - u) ** (n - i)
        x += c * q[0]
        y += c * q[1]
    return x, y


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: glyphs.py KNOTS TRUTH [N] [FONT ...]")
    limit = int(sys.argv[3]) if len(sys.argv) > 3 else 200
    fonts = sys.argv[4:] or FONTS
    try:
        from fontTools.ttLib import TTFont
    except ImportError:
        print("glyphs: no fontTools (python3-fonttools)", file=sys.stderr)
        return 0
    fonts = [f for f in fonts if __import__("os").path.exists(f)]
    if not fonts:
        print("glyphs: no font found (fonts-freefont-ttf, "
              "fonts-linuxlibertine, fonts-ebgaramond)", file=sys.stderr)
        return 0
    out, truth, n = open(sys.argv[1], "w"), open(sys.argv[2], "w"), 0
    for f in fonts:
        font = TTFont(f)
        for ch, segs in contours(font):
            m = len(segs)
            if n >= limit or not 5 <= m <= 60:
                continue
            corners, straight = [], []
            for i in range(m):
                if turn(tangent(segs[i - 1], 1), tangent(segs[i], 0)) > KINK:
                    corners.append(i + 1)
            for i in range(m):
                if len(segs[i]) != 2:
                    continue
                nb = [(segs[i - 1], i), (segs[(i + 1) % m], (i + 1) % m)]
                if any(len(s) > 2 and (j + 1) not in corners for s, j in nb):
                    straight.append(i + 1)
            head = "points font=%s glyph=%s" % (f.split("/")[-1], ch)
            if corners:
                head += " corners=" + ",".join(map(str, corners))
            if straight:
                head += " straight=" + ",".join(map(str, straight))
            out.write(head + "\n")
            for s in segs:
                out.write("%g %g\n" % tuple(s[0]))
            out.write("\n")
            truth.write("points\n")
            for s in segs:
                for k in range(200):
                    truth.write("%.6f %.6f\n" % point(s, k / 200))
            truth.write("\n")
            n += 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
