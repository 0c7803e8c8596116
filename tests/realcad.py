"""realcad.py: fromcad against independent readers.

  realcad.py gen DIR          write DIR/blocks.dxf (blocks, arrays,
                              nesting, extrusions, ellipses, a layer off)
                              and DIR/d6673.dxf (a pattern file in the
                              style of ASTM D6673) with ezdxf, and
                              DIR/features.svg (use, symbol, viewports,
                              rounded rects, hidden elements)
  realcad.py dxf LIST         for each line "DOC<tab>LOFT" of LIST,
                              compare the records LOFT (fromcad's output
                              for DOC) with ezdxf's own geometry of DOC
  realcad.py svg LIST         the same with svgelements for SVGs

The references are ezdxf's and svgelements' own evaluation (their
transforms of blocks and <use>, their ellipses and arcs, their Bezier
decomposition of splines), never numbers taken from fromcad.  Where
svgelements is known to part from SVG, the document it reads is mended
first (svg_as_drawn) or its shape left out, each with the reason: path
data in error (dropped whole; SVG draws it up to the error), numbers
such as "12." (SVG 1.1 reads 12), flowRoot (a draft's text, drawn by no
browser; svgelements draws its region), an ellipse with no radii (not
drawn; svgelements draws radius 1).  Prints
one line "N records, M points compared, largest deviation D (of the
tolerance)" of them all, and "FAIL DOC: why" for each document with a
record that differs (then exits 1)."""
import copy
import io
import math
import re
import sys

# Relative rounding: two readers' coordinates of one point agree to
# this fraction of the drawing's size (doubles carry 1e-16; the
# transforms of nested blocks cost a few roundings each).
ROUND = 1e-9
SVG_ROUND = 1e-7
# A subpath back at its start to this fraction of its coordinates
# (relative commands add up roundings) is closed with no closing side
# (svgread.c PATH_SAME, fromcad.1)
PATH_SAME = 1e-12
# fromcad's default arc tolerance (loftprog.h LOFT_CADIN_ARC_REL)
ARC_REL = 1e-4


class Unreadable(Exception):
    """The reference reader cannot read the document: no comparison."""


def records(path):
    """fromcad's output as [(header words, rows of floats)]."""
    out, cur = [], None
    for line in open(path):
        w = line.split()
        if not w:
            cur = None
            continue
        if cur is None:
            cur = (w, [])
            out.append(cur)
        else:
            cur[1].append([float(x) for x in w])
    return out


def attr(head, key):
    for w in head[1:]:
        if w.startswith(key + "="):
            return w[len(key) + 1:]
    return None


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def pt3(p):
    p = list(p)
    return p + [0.0] * (3 - len(p))


class Check:
    def __init__(self, size):
        self.size = size        # the drawing's extent, for ROUND
        self.points = 0
        self.dev = 0.0          # largest deviation over its allowance

    def near(self, what, got, want, tol=None):
        tol = tol if tol is not None else ROUND * self.size
        d = dist(pt3(got), pt3(want))
        self.points += 1
        self.dev = max(self.dev, d / tol if tol > 0 else 0)
        if d > tol:
            sys.exit("%s: %r, want %r (%.3g off)" % (what, got, want, d))


# ---- DXF ---------------------------------------------------------------

def gen(d):
    gen_svg(d)
    try:
        import ezdxf
    except ImportError:
        return          # the DXF cases are skipped
    doc = ezdxf.new("R2018")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    inner = doc.blocks.new("INNER", base_point=(1, 1))
    inner.add_line((1, 1), (3, 2))
    inner.add_circle((2, 2), 0.5)
    inner.add_ellipse((0, 0), major_axis=(2, 1), ratio=0.4,
                      start_param=0.3, end_param=2.5)
    outer = doc.blocks.new("OUTER", base_point=(0, 0, 0))
    outer.add_lwpolyline([(0, 0, 0), (4, 0, 0.5), (4, 3, 0), (0, 3, 0)],
                         format="xyb", close=True)
    outer.add_blockref("INNER", (5, 5), dxfattribs={
        "xscale": 2, "yscale": 0.5, "rotation": 30})
    outer.add_arc((1, 1), 2, 10, 200)
    outer.add_spline([(0, 0), (1, 3), (3, 3), (4, 0), (6, 1)])
    msp.add_blockref("OUTER", (10, 20), dxfattribs={"rotation": 45,
                                                    "xscale": 1.5,
                                                    "yscale": 1.5})
    msp.add_blockref("INNER", (0, 0, 3), dxfattribs={
        "extrusion": (0.3, -0.2, 0.9), "rotation": 10})
    m = msp.add_blockref("INNER", (-50, 0), dxfattribs={"rotation": 15})
    m.grid(size=(3, 4), spacing=(7, 11))
    msp.add_ellipse((3, 4, 0), major_axis=(10, 2, 0), ratio=0.3)
    msp.add_ellipse((1, 1, 1), major_axis=(0, 5, 1), ratio=0.7,
                    start_param=1, end_param=5,
                    dxfattribs={"extrusion": (1, 0, 0)})
    # rational splines: a circle's arc and a whole ellipse, exact NURBS
    from ezdxf.math import (rational_bspline_from_arc,
                            rational_bspline_from_ellipse,
                            ConstructionEllipse)
    for bs in (rational_bspline_from_arc(center=(5, 5), radius=3,
                                         start_angle=30, end_angle=300),
               rational_bspline_from_ellipse(ConstructionEllipse(
                   center=(1, 2, 3), major_axis=(4, 1, 0), ratio=0.5,
                   extrusion=(0, 0.6, 0.8)))):
        msp.add_rational_spline(bs.control_points, bs.weights(),
                                degree=bs.degree, knots=bs.knots())
    outer.add_rational_spline(*(lambda b: (b.control_points, b.weights(),
                                           b.degree, b.knots()))(
        rational_bspline_from_arc(center=(0, 0), radius=1, start_angle=0,
                                  end_angle=90)))
    doc.layers.add("OLD").off()
    doc.layers.add("ICE").freeze()
    msp.add_line((0, 0), (9, 9), dxfattribs={"layer": "OLD"})
    msp.add_line((0, 0), (9, -9), dxfattribs={"layer": "ICE"})
    msp.add_text("label", dxfattribs={"layer": "15"})
    # a HATCH (fromcad -F): a polyline path with a bulge, and an edge
    # path of lines and arcs turning both ways
    h = msp.add_hatch(dxfattribs={"elevation": (0, 0, 2)})
    h.paths.add_polyline_path([(0, 0, 0), (10, 0, 0.4), (10, 5, 0),
                               (0, 5, 0)], is_closed=True)
    e = h.paths.add_edge_path()
    e.add_line((20, 0), (30, 0))
    e.add_arc((30, 5), 5, -90, 90, ccw=True)
    e.add_line((30, 10), (25, 10))
    e.add_arc((22.5, 10), 2.5, 0, 180, ccw=False)
    e.add_line((20, 10), (20, 0))
    doc.saveas(d + "/blocks.dxf")

    # ASTM D6673 style: one block per size, the boundary on layer 1, its
    # turn points on layer 2, the size as TEXT on layer 15, each inserted;
    # both sizes inserted at the same place (stacked, as graded nests are)
    doc = ezdxf.new("R12")
    for size, k in (("S7", 1.0), ("S8", 1.06)):
        b = doc.blocks.new(size)
        pts = [(0, 0), (100 * k, 0), (110 * k, 40 * k), (60 * k, 70 * k),
               (0, 50 * k)]
        b.add_polyline2d(pts, close=True, dxfattribs={"layer": "1"})
        for p in (pts[1], pts[3]):
            b.add_point(p, dxfattribs={"layer": "2"})
        b.add_text(size, dxfattribs={"layer": "15"})
        doc.modelspace().add_blockref(size, (0, 0))
    doc.saveas(d + "/d6673.dxf")
    gen_hatch(d)


def gen_hatch(d):
    """HATCHes whose edge paths hold ellipse and spline edges: ellipse
    arcs both ways and whole, splines of degree 2 and 3 with and without
    fit data and tangents, a rational one (an exact arc), a spline as a
    path's last edge, one HATCH in an OCS; as R2013 and as R2000 (which
    writes no fit-point count when there are no fit points)."""
    import ezdxf
    from ezdxf.math import rational_bspline_from_arc
    for ver in ("R2013", "R2000"):
        doc = ezdxf.new(ver)
        doc.header["$INSUNITS"] = 4
        msp = doc.modelspace()
        h = msp.add_hatch()
        e = h.paths.add_edge_path()             # an ellipse arc, a line
        g = e.add_ellipse((0, 0), (4, 1), 0.5, 20, 200)
        e.add_line(g.end_point, g.start_point)
        e = h.paths.add_edge_path()             # clockwise, then lines
        g = e.add_ellipse((10, 0), (0, 3), 0.3, 30, 100, ccw=False)
        e.add_line(g.start_point, (10, 0))
        e.add_line((10, 0), g.end_point)
        e = h.paths.add_edge_path()             # a whole ellipse
        e.add_ellipse((20, 0), (-2, 2), 0.7)
        h = msp.add_hatch(dxfattribs={"extrusion": (0, 0.6, 0.8),
                                      "elevation": (0, 0, 2)})
        e = h.paths.add_edge_path()             # a cubic, fit data too,
        ctl = [(0, 0), (2, 3), (5, 3), (7, -1), (9, 0)]
        e.add_spline(fit_points=[(0, 0), (4, 2.5), (9, 0)],
                     control_points=ctl,
                     knot_values=[0, 0, 0, 0, 0.4, 1, 1, 1, 1],
                     start_tangent=(1, 1), end_tangent=(1, 0))
        e.add_line((0, 0), (9, 0))              # the line written backwards
        e = h.paths.add_edge_path()             # a line, then a quadratic
        e.add_line((0, 10), (10, 10))           # spline last, no fit data
        e.add_spline(control_points=[(10, 10), (12, 14), (6, 16), (3, 12),
                                     (0, 10)], degree=2,
                     knot_values=[0, 0, 0, 1, 2, 3, 3, 3])
        e = h.paths.add_edge_path()             # a rational quarter
        bs = rational_bspline_from_arc(center=(20, 10), radius=3,
                                       start_angle=0, end_angle=90)
        e.add_line((20, 10), (23, 10))
        e.add_spline(control_points=bs.control_points,
                     weights=bs.weights(), degree=bs.degree,
                     knot_values=bs.knots())
        e.add_line((20, 13), (20, 10))
        doc.saveas("%s/hatch%s.dxf" % (d, ver[1:]))


def gen_svg(d):
    # SVG: use (of a path, of a symbol, under transforms), a nested svg
    # viewport, hidden elements, rounded rects (one a circle), arcs,
    # ellipses under rotation, scale and skew, polygon and polyline
    with open(d + "/features.svg", "w") as f:
        f.write("""<svg xmlns="http://www.w3.org/2000/svg"
 xmlns:xlink="http://www.w3.org/1999/xlink" width="96" height="96"
 viewBox="0 0 96 96">
<defs><path id="p" d="M0 0L10 0"/>
<symbol id="s"><path d="M0 0L0 10"/><circle cx="2" cy="3" r="1"/></symbol>
</defs>
<use xlink:href="#p" x="5" y="1"/>
<g transform="translate(100,0)"><use href="#s" transform="scale(2)"/></g>
<path d="M1 1L2 2" style="fill:none; display : none"/>
<g visibility="hidden"><path d="M3 3L4 4"/>
<path visibility="visible" d="M5 5L6 6"/></g>
<svg x="10" y="10" width="20" height="10" viewBox="0 0 2 2">
<path d="M0 0L2 2"/></svg>
<rect x="1" y="2" width="10" height="6" rx="2" transform="rotate(20)"/>
<rect x="390.57" y="505.8" width="36" height="36" rx="18"/>
<path d="M0 0 A 5 3 30 1 1 10 5 Q 12 12 3 4 C 1 1 2 2 0 0z"/>
<ellipse cx="3" cy="4" rx="5" ry="2" transform="skewX(10)"/>
<ellipse cx="3" cy="4" rx="5" ry="2" transform="rotate(30) scale(2,1)"/>
<polygon points="0,0 4,0 4,3"/><polyline points="1 1 2 5 7 1"/>
<text x="0" y="0">a label</text>
</svg>
""")
    # where svgelements parts from SVG (svg_as_drawn, svg_subpaths), as
    # breeze's icons have it: path data in error, drawn up to the error
    # (network-mobile-*-locked), numbers ending in their point
    # (folder-open), a flowRoot (calindori), an ellipse with no radii
    # (yast), a rect rounded by 1.6e-7 (gcompris-qt), a subpath back at
    # its start to a rounding (application-pgp-signature)
    with open(d + "/inerror.svg", "w") as f:
        f.write("""<svg xmlns="http://www.w3.org/2000/svg" width="96" height="96"
 viewBox="0 0 96 96">
<path d="M 17,5 3,19 h 11 v -3 l 1,-1 h "/><path d="M 13,9 3,19 h 11 l"/>
<path d="M 3 3 L 3 19 L 12. 5 L 10. 3 z M 9 8 L 18 8 L 18 18 z"/>
<flowRoot><flowRegion><rect x="1" y="1" width="5" height="5"/>
</flowRegion><flowPara>a</flowPara></flowRoot>
<ellipse cx="16" cy="16"/>
<rect rx="1.6473932e-07" y="60.39374" x="45.8447" height="4.84" width="3.87"/>
<path d="m 9471.8,4996 c 10,20 30,20 40,0 l 0.1,0 0.2,0 -40.3,0 z"
 transform="scale(0.001)"/>
</svg>
""")


def edge_ends(g):
    """The two ends of a HATCH edge (OCS), in either order."""
    if g.EDGE_TYPE == "LineEdge":
        return g.start, g.end
    if g.EDGE_TYPE == "SplineEdge":
        bs = g.construction_tool()
        k = bs.knots()
        return bs.point(k[bs.degree]), bs.point(k[-bs.degree - 1])
    if g.EDGE_TYPE == "EllipseEdge":
        return g.start_point, g.end_point
    return tuple((g.center[0] + g.radius * math.cos(math.radians(a)),
                  g.center[1] + g.radius * math.sin(math.radians(a)))
                 for a in (g.start_angle, g.end_angle))


def hatch_loops(p):
    """A boundary path's loops, each a list of its edges ([None] for a
    polyline path): a new loop where an edge touches neither end of the
    chain so far and that chain is closed, as ezdxf's path.from_hatch
    chains them (a gap in an open chain is bridged)."""
    if not hasattr(p, "edges"):
        return [None]

    def close(a, b):
        return math.hypot(a[0] - b[0], a[1] - b[1]) <= 1e-9
    loops, s, e = [], None, None
    for g in p.edges:
        a, b = edge_ends(g)
        if s is None:
            loops.append([g])
            s, e = a, b
            continue
        if close(e, a):
            e = b
        elif close(e, b):
            e = a
        elif close(s, b):
            s = a
        elif close(s, a):
            s, e = e, b
        elif close(s, e):
            loops.append([g])
            s, e = a, b
            continue
        else:
            e = b
        loops[-1].append(g)
    return loops


def dxf_expected(doc, fills=False):
    """ezdxf's entities of the model space, blocks exploded by ezdxf;
    with fills, a HATCH's boundary paths too, one entry a loop (as
    ("PATH", hatch, path, its edges, the loop's index in ezdxf's
    path.from_hatch))."""
    def off(e):
        name = e.dxf.get("layer", "0")
        if not doc.layers.has_entry(name):
            return False
        lay = doc.layers.get(name)
        return lay.is_off() or lay.is_frozen()

    def walk(ents, depth):
        for e in ents:
            if depth == 0 and off(e):
                continue
            t = e.dxftype()
            if t == "INSERT":
                if e.mcount > 1:
                    for v in e.multi_insert():
                        yield from walk(v.virtual_entities(), depth + 1)
                else:
                    yield from walk(e.virtual_entities(), depth + 1)
            elif t == "HATCH" and fills:
                from ezdxf import path as ep
                j = 0
                for p in e.paths:
                    for edges in hatch_loops(p):
                        yield ("PATH", e, p, edges, j)
                        j += 1
                if j != len(list(ep.from_hatch(e))):
                    sys.exit("HATCH %s: %d loops, ezdxf makes %d" % (
                        e.dxf.handle, j, len(list(ep.from_hatch(e)))))
            elif t in ("ARC", "CIRCLE") and not e.dxf.radius > 0:
                continue        # draws nothing: passed over
            elif t in ("LINE", "POINT", "ARC", "CIRCLE", "ELLIPSE",
                       "LWPOLYLINE", "POLYLINE", "SPLINE"):
                yield e
    return list(walk(doc.modelspace(), 0))


def ellipse_dev(ce, p):
    """How far p lies off the ellipse, as the radial error in the
    ellipse's own unit-circle coordinates times the major radius."""
    c, mj, mn = ce.center, ce.major_axis, ce.minor_axis
    q = [p[k] - c[k] for k in range(3)]
    x = sum(q[k] * mj[k] for k in range(3)) / mj.magnitude ** 2
    y = sum(q[k] * mn[k] for k in range(3)) / mn.magnitude ** 2
    z = q[0] * ce.extrusion[0] + q[1] * ce.extrusion[1] + q[2] * ce.extrusion[2]
    return math.hypot(abs(math.hypot(x, y) - 1) * mj.magnitude, z)


def bez(row, dim, t):
    a, b = row[:dim], row[dim:2 * dim]
    ta, tb = row[2 * dim:3 * dim], row[3 * dim:]
    b1 = [a[k] + ta[k] / 3 for k in range(dim)]
    b2 = [b[k] - tb[k] / 3 for k in range(dim)]
    s = 1 - t
    return [s ** 3 * a[k] + 3 * s * s * t * b1[k] + 3 * s * t * t * b2[k]
            + t ** 3 * b[k] for k in range(dim)]


def cmp_ellipse(ck, what, e, rec, mm):
    ce = e.construction_tool()
    ce = type(ce)(center=ce.center * mm, major_axis=ce.major_axis * mm,
                  extrusion=ce.extrusion, ratio=ce.ratio,
                  start_param=ce.start_param, end_param=ce.end_param)
    tol = ARC_REL * ce.major_axis.magnitude * (1 + 1e-6) + ROUND * ck.size
    rows = rec[1]
    if rec[0][0] == "points":   # an ARC or CIRCLE stretched by a block
        for p in rows:
            d = ellipse_dev(ce, pt3(p))
            ck.points += 1
            ck.dev = max(ck.dev, d / (ROUND * ck.size))
            if d > ROUND * ck.size:
                sys.exit("%s: a knot %.3g off the ellipse" % (what, d))
        return
    if rec[0][0] != "cubic":
        sys.exit("%s: a %s record, want cubic" % (what, rec[0][0]))
    dim = len(rows[0]) // 4
    ck.near(what + " start", rows[0][:dim], ce.start_point)
    ck.near(what + " end", rows[-1][dim:2 * dim], ce.end_point)
    for r in rows:
        for t in (0, 0.25, 0.5, 0.75):
            p = pt3(bez(r, dim, t))
            d = ellipse_dev(ce, p)
            ck.points += 1
            ck.dev = max(ck.dev, d / tol)
            if d > tol:
                sys.exit("%s: a point %.3g off the ellipse (tolerance %.3g)"
                         % (what, d, tol))


def cmp_arc(ck, what, e, rec, mm):
    from ezdxf.math import OCS
    ocs = OCS(e.dxf.extrusion)
    c, r = e.dxf.center, e.dxf.radius
    tol = ROUND * ck.size
    for p in rec[1]:
        q = ocs.from_wcs([x / mm for x in pt3(p)])
        d = abs(math.hypot(q[0] - c[0], q[1] - c[1]) - r) * mm
        d = max(d, abs(q[2] - c[2]) * mm)
        ck.points += 1
        ck.dev = max(ck.dev, d / tol)
        if d > tol:
            sys.exit("%s: a knot %.3g off the circle" % (what, d))
    if e.dxftype() == "ARC":
        ck.near(what + " start", rec[1][0], e.start_point * mm)
        ck.near(what + " end", rec[1][-1], e.end_point * mm)


def cmp_vertices(ck, what, verts, rec, mm):
    """Every vertex, in order, is a knot of the record."""
    knots = [pt3(p) for p in rec[1]]
    i = 0
    for v in verts:
        v = [x * mm for x in pt3(v)]
        while i < len(knots) and dist(knots[i], v) > ROUND * ck.size:
            i += 1
        if i == len(knots):
            sys.exit("%s: vertex %r is no knot of the record" % (what, v))
        ck.points += 1


def seg_dist(p, a, b):
    ab = [b[k] - a[k] for k in range(3)]
    ap = [p[k] - a[k] for k in range(3)]
    L = sum(x * x for x in ab)
    t = 0 if L == 0 else max(0, min(1, sum(ap[k] * ab[k] for k in range(3)) / L))
    return dist(p, [a[k] + t * ab[k] for k in range(3)])


def cmp_rational(ck, what, e, rec, mm):
    """fromcad's cubic pieces against ezdxf's own rational evaluation,
    sampled densely enough (4000 chords) that the chords' own error is
    1000 times below the tolerance of 10^-4 of half the extent."""
    bs = e.construction_tool()
    pts = [[x * mm for x in pt3(q)] for q in bs.approximate(4000)]
    ext = max(dist(p, q) for p in pts[::50] for q in pts[::50])
    tol = ARC_REL * ext / 2 + ROUND * ck.size
    rows = rec[1]
    dim = len(rows[0]) // 4
    ck.near(what + " start", rows[0][:dim], pts[0])
    ck.near(what + " end", rows[-1][dim:2 * dim], pts[-1])
    j = 0
    for r in rows:
        for t in (0.25, 0.5, 0.75):
            p = pt3(bez(r, dim, t))
            best = min(range(len(pts)), key=lambda i: dist(p, pts[i]))
            dd = min(seg_dist(p, pts[i], pts[i + 1])
                     for i in range(max(0, best - 2), min(len(pts) - 1,
                                                          best + 2)))
            ck.points += 1
            ck.dev = max(ck.dev, dd / tol)
            if dd > tol:
                sys.exit("%s: a point %.3g off the rational curve "
                         "(tolerance %.3g)" % (what, dd, tol))


def cmp_spline(ck, what, e, rec, mm):
    w = list(e.weights)
    if w and max(w) - min(w) > 1e-12 * max(w):
        return cmp_rational(ck, what, e, rec, mm)
    if rec[0][0] == "points" and e.dxf.n_control_points == 0:
        return cmp_vertices(ck, what, e.fit_points, rec, mm)
    bs = e.construction_tool()
    pieces = list(bs.bezier_decomposition())
    if rec[0][0] == "cubic":
        rows = rec[1]
        dim = len(rows[0]) // 4
        if len(rows) != len(pieces):
            sys.exit("%s: %d pieces, want %d" % (what, len(rows),
                                                  len(pieces)))
        for r, b in zip(rows, pieces):
            p = len(b) - 1
            b = [[x * mm for x in pt3(q)] for q in b]
            ck.near(what + " piece start", r[:dim], b[0])
            ck.near(what + " piece end", r[dim:2 * dim], b[p])
            ck.near(what + " start tangent", r[2 * dim:3 * dim],
                    [p * (b[1][k] - b[0][k]) for k in range(3)])
    else:
        sys.exit("%s: a %s record" % (what, rec[0][0]))


def cmp_path(ck, what, h, p, rec, mm, edges, k):
    """A HATCH path: its vertices, or its edges' starts, knots in order;
    an arc edge's knots on its circle."""
    ocs = h.ocs()
    z = h.dxf.elevation[2]
    if hasattr(p, "vertices"):
        cmp_vertices(ck, what, [ocs.to_wcs((v[0], v[1], z))
                                for v in p.vertices], rec, mm)
        return
    starts = []
    for g in edges:
        if g.EDGE_TYPE == "LineEdge":
            starts.append(g.start)
        elif g.EDGE_TYPE == "EllipseEdge":
            starts.append(g.start_point if g.ccw else g.end_point)
        elif g.EDGE_TYPE == "SplineEdge":
            bs = g.construction_tool()
            starts.append(bs.point(bs.knots()[bs.degree]))
        else:
            # ezdxf keeps a clockwise arc's angles counter-clockwise
            # (mirrored and swapped on reading): it starts at the end
            a = g.start_angle if g.ccw else g.end_angle
            starts.append((g.center[0] + g.radius * math.cos(math.radians(a)),
                           g.center[1] + g.radius * math.sin(math.radians(a))))
    cmp_vertices(ck, what, [ocs.to_wcs((v[0], v[1], z)) for v in starts],
                 rec, mm)
    if any(g.EDGE_TYPE in ("EllipseEdge", "SplineEdge") for g in edges):
        cmp_curved_path(ck, what, h, edges, rec, mm)
        return
    # every knot on ezdxf's own boundary, whose arcs are cubic Beziers
    # (2.7e-4 of the radius off a quarter circle, so 3e-4 of the path's
    # size is allowed): an arc drawn the other way round fails here
    from ezdxf import path as ep
    line = [[x * mm for x in pt3(q)] for q in
            list(ep.from_hatch(h))[k].flattening(1e-7)]
    few = line[::max(1, len(line) // 64)]
    size = max(dist(a, b) for a in few for b in few)
    for q in rec[1]:
        dd = min(seg_dist(pt3(q), line[i], line[i + 1])
                 for i in range(len(line) - 1))
        ck.points += 1
        if dd > 3e-4 * size:
            sys.exit("%s: knot %r is %.3g off the boundary" % (what, q, dd))


# fromcad -t for the HATCHes of ellipse and spline edges (kind dxf-Ft)
HATCH_T = 1e-3


def edge_samples(g, n):
    """n points along a HATCH edge by ezdxf's own evaluation (OCS)."""
    import numpy as np
    t = g.EDGE_TYPE
    if t == "LineEdge":
        return [g.start, g.end]
    if t == "SplineEdge":
        bs = g.construction_tool()
        k = bs.knots()
        return list(bs.points(np.linspace(k[bs.degree], k[-bs.degree - 1], n)))
    if t == "EllipseEdge":
        ce = g.construction_tool()
        a, b = ce.start_param, ce.end_param
        b = b + 2 * math.pi if b <= a + 1e-12 else b
        return list(ce.vertices(np.linspace(a, b, n)))
    a, b = math.radians(g.start_angle), math.radians(g.end_angle)
    b = b + 2 * math.pi if b <= a else b
    return [(g.center[0] + g.radius * math.cos(u),
             g.center[1] + g.radius * math.sin(u))
            for u in np.linspace(a, b, n)]


def pts_to_segs(P, A, B):
    """The distance of each point of P to the nearest segment A[i] B[i]."""
    import numpy as np
    best = np.full(len(P), np.inf)
    AB = B - A
    L = np.maximum((AB * AB).sum(1), 1e-300)
    for i in range(0, len(P), 2000):
        Q = P[i:i + 2000, None, :] - A[None, :, :]
        t = np.clip((Q * AB[None]).sum(2) / L[None], 0, 1)
        D = Q - t[:, :, None] * AB[None]
        best[i:i + 2000] = np.sqrt((D * D).sum(2)).min(1)
    return best


def cmp_curved_path(ck, what, h, edges, rec, mm):
    """A path with ellipse or spline edges, read with -t HATCH_T: its
    edges sampled by ezdxf (20000 points each: the samples' own chords
    stand under 2e-7 off) lie within HATCH_T of fromcad's closed polygon
    (its chords keep the tolerance), and every knot lies on ezdxf's
    curve: within 2e-6 (the sampling), or HATCH_T / 2 on a path with a
    rational spline (its cubics take half the tolerance)."""
    import numpy as np
    ocs, z = h.ocs(), h.dxf.elevation[2]
    curve = []
    for g in edges:
        curve += [ocs.to_wcs((v[0], v[1], z)) for v in edge_samples(g, 20000)]
    C = np.array([[x * mm for x in pt3(q)] for q in curve])
    K = np.array([pt3(q) for q in rec[1]])
    if len(K) < 3:
        sys.exit("%s: %d knots" % (what, len(K)))
    Kn = np.roll(K, -1, axis=0)
    d1 = pts_to_segs(C, K, Kn)
    rat = any(g.EDGE_TYPE == "SplineEdge" and len(g.weights)
              for g in edges)
    on = HATCH_T / 2 if rat else 2e-6
    d2 = pts_to_segs(K, C[:-1], C[1:])
    ck.points += len(C) + len(K)
    ck.dev = max(ck.dev, d1.max() / HATCH_T, d2.max() / on)
    ck.hatch = max(getattr(ck, "hatch", 0), d1.max())
    if d1.max() > HATCH_T:
        sys.exit("%s: the boundary stands %.3g off the knots' polygon, "
                 "over -t %g" % (what, d1.max(), HATCH_T))
    if d2.max() > on:
        sys.exit("%s: a knot stands %.3g off the boundary" % (what,
                                                             d2.max()))


def cmp_dxf(path, loft, fills=False):
    import ezdxf
    from ezdxf import units
    try:
        doc = ezdxf.readfile(path)
    except (IOError, ezdxf.DXFError) as e:
        raise Unreadable(str(e))
    u = doc.header.get("$INSUNITS", 0)
    mm = units.conversion_factor(u, units.MM) if u else 1.0
    exp = dxf_expected(doc, fills)
    recs = records(loft)
    ext = 0.0
    for r in recs:
        for p in r[1]:
            ext = max([ext] + [abs(x) for x in p[:3]])
    ck = Check(max(ext, 1e-300))
    if len(exp) != len(recs):
        sys.exit("%d records, want %d (ezdxf: %s)" % (
            len(recs), len(exp), ", ".join(str(e) for e in exp[:8])))
    for i, (e, rec) in enumerate(zip(exp, recs)):
        if isinstance(e, tuple):
            cmp_path(ck, "record %d (HATCH path)" % (i + 1), e[1], e[2],
                     rec, mm, e[3], e[4])
            continue
        t = e.dxftype()
        what = "record %d (%s)" % (i + 1, t)
        if t == "LINE":
            ck.near(what, rec[1][0], e.dxf.start * mm)
            ck.near(what, rec[1][1], e.dxf.end * mm)
        elif t == "POINT":
            ck.near(what, rec[1][0], e.dxf.location * mm)
        elif t in ("ARC", "CIRCLE"):
            cmp_arc(ck, what, e, rec, mm)
        elif t == "ELLIPSE":
            cmp_ellipse(ck, what, e, rec, mm)
        elif t == "LWPOLYLINE":
            ocs = e.ocs()
            z = e.dxf.elevation
            cmp_vertices(ck, what, [ocs.to_wcs((p[0], p[1], z))
                                    for p in e.get_points("xy")], rec, mm)
        elif t == "POLYLINE":
            cmp_vertices(ck, what, list(e.points_in_wcs())
                         if hasattr(e, "points_in_wcs") else
                         [v.dxf.location for v in e.vertices], rec, mm)
        elif t == "SPLINE":
            cmp_spline(ck, what, e, rec, mm)
    return len(recs), ck


# ---- SVG ---------------------------------------------------------------

PATH_TOKEN = re.compile(r"[MmLlHhVvCcSsQqTtAaZz]|[-+]?(?:[0-9]+\.?[0-9]*|"
                        r"\.[0-9]+)(?:[eE][-+]?[0-9]+)?")


def d_as_drawn(d):
    """Path data d as fromcad reads it, for svgelements: a number ending
    in its point ("12.") completed, as SVG 1.1's grammar reads it
    (fromcad.1; svgelements, like SVG 2 and Chromium, stops there); and
    data in error cut after the last token before the error, for SVG
    draws such a path up to there (SVG 1.1 F.2, SVG 2 9.5.4) where
    svgelements drops the whole path."""
    import svgelements as se
    d = re.sub(r"([0-9])\.(?![0-9])", r"\1.0", d)
    ends = [m.end() for m in PATH_TOKEN.finditer(d)]
    for k in [len(d)] + ends[::-1]:
        try:
            se.Path(d[:k])
            return d[:k]
        except Exception:       # noqa: svgelements' parse error
            continue
    return ""


def svg_as_drawn(path):
    """The document of path as a file for svgelements: path data as
    d_as_drawn makes it, and no flowRoot (SVG 1.2's draft flowed text,
    drawn by no browser; fromcad passes it over whole, where svgelements
    draws the rect of its flowRegion)."""
    text = open(path, encoding="utf-8", errors="replace").read()
    text = re.sub(r"<flowRoot\b[^>]*?(?:/>|>.*?</flowRoot>)", "", text,
                  flags=re.S)
    text = re.sub(r'(\sd\s*=\s*)(["\'])(.*?)\2',
                  lambda m: m.group(1) + m.group(2) + d_as_drawn(m.group(3))
                  + m.group(2), text, flags=re.S)
    return io.BytesIO(text.encode("utf-8"))


def svg_subpaths(path):
    """svgelements' shapes, as lists of segments per subpath in user
    units: its own transforms, <use>, visibility.  An arc is kept with
    its shape's own (untransformed) arc and the transform, for svgelements
    moves an arc through a skewing transform only approximately; arcs of
    one ellipse in a row are one arc (fromcad cuts a circle into pieces
    of its own)."""
    import svgelements as se
    try:
        svg = se.SVG.parse(svg_as_drawn(path), reify=False, ppi=96.0)
    except Exception as e:      # noqa: the reference fails, not fromcad
        raise Unreadable(str(e))
    vb = svg.viewbox
    if vb is not None and (vb.x != 0 or vb.y != 0 or (
            svg.width and svg.height and abs(svg.width * vb.height -
                                             svg.height * vb.width) >
            1e-9 * svg.width * vb.height)):
        # fromcad keeps the viewBox's origin where it is (fromcad.1),
        # and so does not move a viewBox of another shape to the middle
        raise Unreadable("viewBox origin not 0 0, or centred")
    out = []
    for el in svg.elements():
        if not isinstance(el, se.Shape):
            continue
        if el.values.get("visibility") in ("hidden", "collapse"):
            continue
        if isinstance(el, (se.Ellipse, se.Circle)) and not any(
                k in el.values for k in ("r", "rx", "ry")):
            continue    # radii auto, 0 (SVG 2): not drawn; svgelements
            # draws a circle of radius 1 (breeze's applications-development)
        local = se.Path(el)
        m = local.transform
        for sub in local.as_subpaths():
            segs = []
            for g in sub:
                if isinstance(g, se.Move):
                    continue
                if g.start == g.end and (isinstance(g, se.Close) or (
                        isinstance(g, se.Arc) and abs(g.sweep) < 1e-9)):
                    continue    # fromcad draws nothing there either
                if isinstance(g, se.Close) and max(
                        abs(g.start.x - g.end.x), abs(g.start.y - g.end.y)) \
                        <= PATH_SAME * max(abs(g.start.x), abs(g.start.y),
                                           abs(g.end.x), abs(g.end.y)):
                    continue    # fromcad ends the subpath on its start
                if (g.start == g.end and isinstance(g, se.Line) and
                        isinstance(el, se.Rect)):
                    continue    # a rounded rect's side of length 0
                if (isinstance(g, se.Arc) and segs and
                        isinstance(segs[-1][1], se.Arc) and
                        segs[-1][1].center == g.center and
                        segs[-1][1].rx == g.rx and segs[-1][1].ry == g.ry
                        and segs[-1][1].get_rotation() == g.get_rotation()
                        and segs[-1][1].sweep * g.sweep > 0):
                    a = segs[-1][1]
                    g = se.Arc(start=a.start, end=g.end, center=g.center,
                               rx=g.rx, ry=g.ry,
                               rotation=g.get_rotation(),
                               sweep=a.sweep + g.sweep)
                    segs.pop()
                w = copy.copy(g)
                w *= m          # the segment in user space
                segs.append((w, g, m))
            if segs:
                out.append(segs)
    return out


def arc_dev(g, p):
    """How far the point p lies off the ellipse of arc g, as the radial
    error in its unit circle's coordinates times its larger radius."""
    r = g.get_rotation()
    x, y = p[0] - g.center.x, p[1] - g.center.y
    u = math.cos(r) * x + math.sin(r) * y
    v = -math.sin(r) * x + math.cos(r) * y
    return abs(math.hypot(u / g.rx, v / g.ry) - 1) * max(g.rx, g.ry)


def cmp_svg(path, loft):
    import svgelements as se
    mm = 25.4 / 96
    want = svg_subpaths(path)
    recs = records(loft)
    if len(want) != len(recs):
        sys.exit("%d records, want %d" % (len(recs), len(want)))
    ext = max([1e-300] + [abs(x) for r in recs for p in r[1] for x in p])
    # svgelements' transformed shapes agree with exact arithmetic to
    # about 1e-8 of a drawing (icons drawn at 1000 and moved back by
    # translate(0,-988)), so the rounding allowed here is coarser
    ext *= SVG_ROUND / ROUND
    ck = Check(ext)

    def u(q):                   # user space to fromcad's millimetres
        return [q.x * mm, -q.y * mm]

    def d(q):                   # a direction
        return [q.x * mm, -q.y * mm]

    for i, (segs, rec) in enumerate(zip(want, recs)):
        what = "record %d" % (i + 1)
        rows = rec[1]
        if rec[0][0] == "points":
            knots = [g[0].start for g in segs]
            if rec[0][1] == "closed=0":
                knots.append(segs[-1][0].end)
            if len(knots) != len(rows):
                sys.exit("%s: %d knots, want %d" % (what, len(rows),
                                                     len(knots)))
            for k, q in zip(rows, knots):
                ck.near(what, k, u(q))
            continue
        j = 0
        for g, lg, m in segs:
            if j >= len(rows):
                sys.exit("%s: fewer rows than segments" % what)
            r = rows[j]
            ck.near(what + " start", r[:2], u(g.start))
            if isinstance(g, se.Arc):
                # in the shape's own space, where fromcad's pieces are
                # within the tolerance over the transform's stretch
                inv = ~m
                tol = ARC_REL * max(lg.rx, lg.ry) * (1 + 1e-6)
                while True:
                    for t in (0.25, 0.5, 0.75):
                        q = bez(rows[j], 2, t)
                        q = inv.point_in_matrix_space(
                            se.Point(q[0] / mm, -q[1] / mm))
                        e = arc_dev(lg, (q.x, q.y))
                        ck.points += 1
                        ck.dev = max(ck.dev, e / tol)
                        if e > tol + ROUND * ext / mm:
                            sys.exit("%s: a point %.3g off the arc" %
                                     (what, e))
                    j += 1
                    if dist(rows[j - 1][2:4], u(g.end)) <= ROUND * ext:
                        # an arc below the rounding (a rect's rx of
                        # 1.6e-7, breeze's gcompris-qt) ends where it
                        # starts: its other pieces are there too
                        while (j < len(rows) and max(lg.rx, lg.ry) * mm <=
                               ROUND * ext and dist(rows[j][2:4], u(g.end))
                               <= ROUND * ext):
                            j += 1
                        break
                    if j == len(rows):
                        sys.exit("%s: no row ends where the arc does" %
                                 what)
                continue
            ck.near(what + " end", r[2:4], u(g.end))
            if isinstance(g, se.CubicBezier):
                ta = d(3 * (g.control1 - g.start))
                tb = d(3 * (g.end - g.control2))
            elif isinstance(g, se.QuadraticBezier):
                ta = d(2 * (g.control - g.start))
                tb = d(2 * (g.end - g.control))
            else:
                ta = tb = d(g.end - g.start)
            ck.near(what + " start tangent", r[4:6], ta)
            ck.near(what + " end tangent", r[6:8], tb)
            j += 1
        if j != len(rows):
            sys.exit("%s: %d rows, want %d" % (what, len(rows), j))
    return len(recs), ck


def batch(kind, listfile):
    """Each line of listfile "DOC LOFT": compared; a line per failure
    "FAIL DOC: why", then the totals.  Exit status 1 when any failed."""
    nf = nrec = npts = bad = unread = 0
    dev = 0.0
    for line in open(listfile):
        doc, loft = line.rstrip("\n").split("\t")
        try:
            if kind == "svg":
                n, ck = cmp_svg(doc, loft)
            else:
                n, ck = cmp_dxf(doc, loft, kind in ("dxf-F", "dxf-Ft"))
        except SystemExit as e:
            print("FAIL %s: %s" % (doc, e))
            bad += 1
            continue
        except Unreadable as e:
            unread += 1
            continue
        nf += 1
        nrec += n
        npts += ck.points
        dev = max(dev, ck.dev)
    print("%d files, %d records, %d points compared, largest deviation "
          "%.3g of its tolerance; %d files the reference cannot read"
          % (nf, nrec, npts, dev, unread))
    return bad


def main():
    if sys.argv[1] == "gen":
        gen(sys.argv[2])
        return
    sys.exit(1 if batch(sys.argv[1], sys.argv[2]) else 0)


main()
