"""fromcad_ezdxf.py VERSION OUT.dxf OUT.want: write a DXF with ezdxf (R12
or R2018) and, beside it, the loft records fromcad must read from it,
made from the numbers given to ezdxf here (and, for the spline, ezdxf's
own Bezier decomposition), never from fromcad's output."""
import sys

import ezdxf
from ezdxf.math import BSpline

ver, out, want = sys.argv[1], sys.argv[2], sys.argv[3]
doc = ezdxf.new(ver)
msp = doc.modelspace()
scale = 1.0
if ver != "R12":
    doc.header["$INSUNITS"] = 1      # inches: fromcad writes millimetres
    scale = 25.4
rec = []


def knots(header, pts):
    rec.append(header)
    for p in pts:
        rec.append(" ".join(repr(c * scale) for c in p))
    rec.append("")


outline = [(0.0, 0.0), (120.5, -10.25), (250.0, 3.0), (130.0, 60.125),
           (10.0, 40.0)]
if ver == "R12":
    msp.add_polyline2d(outline, close=True, dxfattribs={"layer": "1"})
else:
    msp.add_lwpolyline(outline, close=True, dxfattribs={"layer": "1"})
# turn points on layer 2 at vertices 2 and 4, a curve point on layer 3
msp.add_point(outline[1], dxfattribs={"layer": "2"})
msp.add_point(outline[3], dxfattribs={"layer": "2"})
msp.add_point(outline[2], dxfattribs={"layer": "3"})
knots("points closed=1 layer=1 corners=2,4", outline)
rec.append("points layer=3")
rec.append(" ".join(repr(c * scale) for c in outline[2]))
rec.append("")
msp.add_line((1.5, 2.0), (3.0, -4.5), dxfattribs={"layer": "lines"})
knots("points closed=0 layer=lines", [(1.5, 2.0), (3.0, -4.5)])

if ver != "R12":
    ctl = [(0.0, 0.0, 0.0), (10.0, 20.0, 0.0), (30.0, 25.0, 0.0),
           (45.0, 5.0, 0.0), (60.0, 10.0, 0.0), (70.0, 0.0, 0.0)]
    kv = [0.0, 0.0, 0.0, 0.0, 0.3, 1.1, 2.0, 2.0, 2.0, 2.0]
    s = msp.add_spline(dxfattribs={"layer": "0"})
    s.dxf.degree = 3
    s.control_points = ctl
    s.knots = kv
    rec.append("cubic closed=0 layer=0")
    for b in BSpline(ctl, order=4, knots=kv).bezier_decomposition():
        b = [(v.x * scale, v.y * scale) for v in b]
        row = [b[0], b[3], (3 * (b[1][0] - b[0][0]), 3 * (b[1][1] - b[0][1])),
               (3 * (b[3][0] - b[2][0]), 3 * (b[3][1] - b[2][1]))]
        rec.append(" ".join(repr(c) for p in row for c in p))
    rec.append("")
    fit = [(0.0, 0.0), (5.0, 5.0), (10.0, 0.0), (15.0, -2.5)]
    f = msp.add_spline(fit_points=fit, dxfattribs={"layer": "fit"})
    f.dxf.start_tangent = (1, 0, 0)
    f.dxf.end_tangent = (0, -1, 0)
    knots("points closed=0 layer=fit start=1,0 end=0,-1", fit)

doc.saveas(out)
with open(want, "w") as fp:
    fp.write("\n".join(rec) + "\n")
