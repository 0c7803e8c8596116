"""pdf_extent.py: what a PDF draws, for tests/tocad.sh's LibreCAD check.

    python3 tests/pdf_extent.py FILE.pdf

prints "PATHS WIDTH HEIGHT": the number of paths the page contents
paint (stroke or fill) and the width and height in millimetres of the
box around their points, taken through the current transformation
matrix (cm, q, Q).  Paths ended with n (clipping only) are not counted.
Only the Python standard library: content streams inflated with zlib,
tokens by regular expression; enough for the PDFs Qt writes (LibreCAD's
dxf2pdf), not a general PDF reader.  Curve control points count as
points, so a Bezier path's box may be a little large, never small.
"""
import re
import sys
import zlib

NUMBER = re.compile(rb"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)$")
TOKEN = re.compile(rb"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)|[A-Za-z*']+|[\[\]]")
PAINT = {b"S", b"s", b"f", b"F", b"f*", b"B", b"B*", b"b", b"b*"}
MM_PER_PT = 25.4 / 72


def contents(data):
    for m in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
        try:
            yield zlib.decompress(m.group(1))
        except zlib.error:
            yield m.group(1)


def times(a, b):
    """The matrix a then b, PDF's [a b c d e f] row-vector form."""
    return [a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3],
            a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3],
            a[4] * b[0] + a[5] * b[2] + b[4],
            a[4] * b[1] + a[5] * b[3] + b[5]]


def main():
    with open(sys.argv[1], "rb") as f:
        data = f.read()
    lo = [float("inf")] * 2
    hi = [float("-inf")] * 2
    painted = 0
    for text in contents(data):
        ctm, saved, args, path = [1, 0, 0, 1, 0, 0], [], [], []
        for tok in TOKEN.findall(text):
            if NUMBER.match(tok):
                args.append(float(tok))
                continue
            if tok == b"cm" and len(args) >= 6:
                ctm = times(args[-6:], ctm)
            elif tok == b"q":
                saved.append(ctm)
            elif tok == b"Q" and saved:
                ctm = saved.pop()
            elif tok in (b"m", b"l", b"c", b"v", b"y"):
                for i in range(0, len(args) - 1, 2):
                    x, y = args[i], args[i + 1]
                    path.append((ctm[0] * x + ctm[2] * y + ctm[4],
                                 ctm[1] * x + ctm[3] * y + ctm[5]))
            elif tok in PAINT:
                for p in path:
                    for k in (0, 1):
                        lo[k] = min(lo[k], p[k])
                        hi[k] = max(hi[k], p[k])
                painted += bool(path)
                path = []
            elif tok == b"n":
                path = []
            args = []
    if painted == 0:
        print("0 0 0")
        return
    print(painted, "%.6f %.6f" % ((hi[0] - lo[0]) * MM_PER_PT,
                                  (hi[1] - lo[1]) * MM_PER_PT))


main()
