#!/usr/bin/env python3
"""Per-category geometry references for tests/reader_reference.rs, computed with ezdxf.

For one or more files per awkward category (spline, ellipse, mirrored nested
insert, extrusion -Z, binary, code page, no header): the total drawn length,
the extents, the signed area of every closed entity (CIRCLE, full ARC or
ELLIPSE, closed LWPOLYLINE/POLYLINE, closed SPLINE), and the names of the
layers holding geometry, in drawing units, of the cuttable geometry (as in
ezdxf_reference.py: LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE, SPLINE,
ELLIPSE; INSERTs exploded recursively by ezdxf; visible, thawed layers).

Independent of kerfcam: lines, arcs and polyline bulges are computed exactly
(lengths r·θ, areas by the shoelace formula plus circular segments, extents
from end points and the quadrant points an arc passes); SPLINE and ELLIPSE
from ezdxf's own curve evaluation (BSpline with knots and weights,
ConstructionEllipse), flattened to FLAT (relative to the file's extents),
fine enough that its error (length and extents short by at most FLAT·size,
area by FLAT·size·length) is far below the test's bounds.

Categories without a corpus file get a small fixture written here by ezdxf
(tests/reference/fixtures/, committed). Run by hand (pip install ezdxf),
review the diff, commit:

    python3 tests/reference/ezdxf_categories.py ../shared/corpus > tests/reference/categories.json
"""
import json
import math
import pathlib
import sys

import ezdxf
from ezdxf.math import Vec3

# What counts as cuttable, how a file is opened and its units read: the same
# as for the corpus-wide reference (this script's folder is on sys.path).
from ezdxf_reference import GEOMETRY, cuttable, declared_insunits, open_doc

HERE = pathlib.Path(__file__).resolve().parent
FIXTURES = HERE / "fixtures"

# category -> files (corpus paths, or fixtures/...).
CATEGORIES = {
    "spline": ["dxf2gcode-plasma/J test.dxf", "cadquery/spline.dxf", "dxf2gcode-plasma/Wiele.DXF"],
    "ellipse": ["ezdxf/forms.dxf", "dxf2gcode-plasma/Teile.dxf", "dxf2gcode-plasma/Ellipsenbögen_Block_gedreht.dxf"],
    "mirrored nested insert": [
        "ezdxf/insert_bricscad_level_1.dxf",
        "dxf2gcode-plasma/problem_with_arc_and_problem_with_G41-G42_auto_switch.dxf",
        "fixtures/mirrored_nested_insert.dxf",
    ],
    "extrusion -Z": ["dxf2gcode-plasma/Stir_1.dxf", "fixtures/extrusion_minus_z.dxf"],
    "binary": ["ezdxf/bin_dxf_r12.dxf", "ixmilia-dxf/diamond-bin.dxf", "acadsharp/sample_AC1009_binary.dxf"],
    "code page": ["deepnestsharp/TopsNestVert.dxf", "fixtures/cp1251_layers.dxf"],
    "no header": ["ezdxf/empty_handles.dxf", "dxf2gcode-plasma/1997_simplified_doppelte_linien.dxf"],
}

# Flattening distance of splines and ellipses, relative to the file's size.
FLAT = 1e-8


def make_fixtures():
    """Writes the fixtures that are missing (ezdxf stamps dates and handles into
    a file, so existing ones are kept: delete one to write it again)."""
    FIXTURES.mkdir(exist_ok=True)
    if all((FIXTURES / n).exists() for n in ("cp1251_layers.dxf", "extrusion_minus_z.dxf", "mirrored_nested_insert.dxf")):
        return

    # Layer names in Windows-1251 (an R2000 file: text in the code page, not UTF-8).
    doc = ezdxf.new("R2000")
    doc.encoding = "cp1251"  # written as $DWGCODEPAGE ANSI_1251
    doc.header["$INSUNITS"] = 4
    for name in ("Контур", "Отверстия"):
        doc.layers.add(name)
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0), (120, 0, 0.4), (120, 80, 0), (0, 80, 0)], format="xyb", close=True,
                       dxfattribs={"layer": "Контур"})
    msp.add_circle((30, 40), 12.5, dxfattribs={"layer": "Отверстия"})
    msp.add_arc((80, 40), 15, 30, 250, dxfattribs={"layer": "Отверстия"})
    doc.saveas(FIXTURES / "cp1251_layers.dxf")

    # Arcs, a circle and a bulged polyline drawn with extrusion (0,0,-1): the OCS is
    # mirrored in X, so every arc turns the other way in world coordinates.
    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    neg = {"extrusion": (0, 0, -1)}
    msp.add_arc((50, 20), 10, 0, 120, dxfattribs=neg)
    msp.add_arc((-40, 35), 7.5, 200, 330, dxfattribs=neg)
    msp.add_circle((-10, 60), 5, dxfattribs=neg)
    msp.add_lwpolyline([(0, 0, 0.5), (30, 0, 0), (30, 20, -0.3), (0, 20, 0)], format="xyb", close=True,
                       dxfattribs=neg)
    msp.add_line((0, 0), (-60, 80))
    doc.saveas(FIXTURES / "extrusion_minus_z.dxf")

    # A block inserted mirrored and rotated inside a block that is itself inserted
    # mirrored the other way, rotated and arrayed.
    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = 4
    inner = doc.blocks.new("INNER", base_point=(5, 5))
    inner.add_lwpolyline([(0, 0, 0), (20, 0, 1), (20, 10, 0), (0, 10, 0)], format="xyb", close=True)
    inner.add_arc((10, 25), 6, 10, 160)
    inner.add_circle((30, 5), 3)
    outer = doc.blocks.new("OUTER", base_point=(0, 0))
    outer.add_blockref("INNER", (40, 0), dxfattribs={"xscale": -1, "yscale": 1, "rotation": 30})
    outer.add_blockref("INNER", (0, 40), dxfattribs={"xscale": 1.5, "yscale": 1.5, "rotation": -45})
    outer.add_line((0, 0), (50, 50))
    msp = doc.modelspace()
    msp.add_blockref("OUTER", (100, 100), dxfattribs={"xscale": 2, "yscale": -2, "rotation": 15})
    ref = msp.add_blockref("OUTER", (300, 0), dxfattribs={"xscale": -1, "yscale": -1, "rotation": 90})
    ref.dxf.column_count = 2
    ref.dxf.row_count = 2
    ref.dxf.column_spacing = 120
    ref.dxf.row_spacing = 110
    doc.saveas(FIXTURES / "mirrored_nested_insert.dxf")


class Acc:
    """Length, extents and closed-loop areas of one file."""

    def __init__(self):
        self.length = 0.0
        self.box = None
        self.areas = []

    def add_point(self, x, y):
        if self.box is None:
            self.box = [x, y, x, y]
        else:
            b = self.box
            self.box = [min(b[0], x), min(b[1], y), max(b[2], x), max(b[3], y)]


def arc_points(cx, cy, r, a0, sweep):
    """End points and the quadrant points an arc from angle a0 (radians) through sweep passes."""
    pts = [(cx + r * math.cos(a0), cy + r * math.sin(a0)), (cx + r * math.cos(a0 + sweep), cy + r * math.sin(a0 + sweep))]
    lo, hi = (a0, a0 + sweep) if sweep >= 0 else (a0 + sweep, a0)
    k = math.ceil(lo / (math.pi / 2))
    while k * math.pi / 2 <= hi:
        t = k * math.pi / 2
        pts.append((cx + r * math.cos(t), cy + r * math.sin(t)))
        k += 1
    return pts


def bulge_segment(p, q, b):
    """Length, signed area term (shoelace part plus circular segment) and extreme points of one polyline segment."""
    (x0, y0), (x1, y1) = p, q
    shoelace = (x0 * y1 - x1 * y0) / 2
    c = math.hypot(x1 - x0, y1 - y0)
    if b == 0 or c == 0:
        return c, shoelace, [p, q]
    theta = 4 * math.atan(b)
    r = c / (2 * abs(math.sin(theta / 2)))
    # Centre on the chord's normal, left of p->q for b > 0 (as DXF bulges turn).
    h = c * (1 - b * b) / (4 * b)
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    nx, ny = -(y1 - y0) / c, (x1 - x0) / c
    cx, cy = mx + nx * h, my + ny * h
    a0 = math.atan2(y0 - cy, x0 - cx)
    segment = r * r / 2 * (theta - math.sin(theta))
    return r * abs(theta), shoelace + segment, arc_points(cx, cy, r, a0, theta)


def add_polyline(acc, ocs_pts, closed, to_world, mirror):
    """A polyline given as OCS (x, y, bulge) vertices; to_world maps an OCS point to world (x, y)."""
    n = len(ocs_pts)
    count = n if closed else n - 1
    area = 0.0
    for i in range(count):
        x0, y0, b = ocs_pts[i]
        x1, y1, _ = ocs_pts[(i + 1) % n]
        length, term, pts = bulge_segment((x0, y0), (x1, y1), b)
        acc.length += length
        area += term
        for pt in pts:
            acc.add_point(*to_world(pt))
    if closed and n >= 2:
        acc.areas.append(-area if mirror else area)


def add_flat(acc, pts, closed):
    """A curve given by a fine flattening."""
    pts = [(p.x, p.y) for p in pts]
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        acc.length += math.hypot(x1 - x0, y1 - y0)
    for pt in pts:
        acc.add_point(*pt)
    if closed:
        ring = pts + [pts[0]]
        acc.areas.append(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:])) / 2)


def entity(acc, e, flat):
    kind = e.dxftype()
    if kind == "LINE":
        a, b = e.dxf.start, e.dxf.end
        acc.length += math.hypot(b.x - a.x, b.y - a.y)
        acc.add_point(a.x, a.y)
        acc.add_point(b.x, b.y)
    elif kind in ("ARC", "CIRCLE"):
        ocs = e.ocs()
        mirror = e.dxf.extrusion.z < 0
        c, r = e.dxf.center, e.dxf.radius
        if kind == "CIRCLE":
            a0, sweep = 0.0, 2 * math.pi
        else:
            s, t = e.dxf.start_angle, e.dxf.end_angle
            d = (t - s) % 360.0
            a0, sweep = math.radians(s), math.radians(d if d != 0 else 360.0)
        acc.length += r * sweep
        for x, y in arc_points(c.x, c.y, r, a0, sweep):
            w = ocs.to_wcs(Vec3(x, y, c.z))
            acc.add_point(w.x, w.y)
        if abs(sweep - 2 * math.pi) < 1e-12:
            acc.areas.append((-1 if mirror else 1) * math.pi * r * r)
    elif kind == "LWPOLYLINE":
        ocs = e.ocs()
        pts = [(x, y, b) for x, y, b in e.get_points("xyb")]
        add_polyline(acc, pts, e.closed, lambda p: tuple(ocs.to_wcs(Vec3(p[0], p[1], 0)))[:2], e.dxf.extrusion.z < 0)
    elif kind == "POLYLINE":
        flags = e.dxf.flags
        is_3d = bool(flags & 8)
        pts = []
        for v in e.vertices:
            if v.dxf.flags & 16:
                continue
            p = v.dxf.location
            pts.append((p.x, p.y, 0.0 if is_3d else v.dxf.get("bulge", 0.0)))
        if is_3d:
            add_polyline(acc, pts, e.is_closed, lambda p: p, False)
        else:
            ocs = e.ocs()
            add_polyline(acc, pts, e.is_closed, lambda p: tuple(ocs.to_wcs(Vec3(p[0], p[1], 0)))[:2],
                         e.dxf.extrusion.z < 0)
    elif kind == "SPLINE":
        if len(e.control_points) == 0:
            raise ValueError("fit-point-only SPLINE: kerfcam's fit differs by design; choose another file")
        bs = e.construction_tool()
        pts = list(bs.flattening(flat, segments=16))
        closed = bool(e.closed) or pts[0].isclose(pts[-1], abs_tol=flat)
        add_flat(acc, pts, closed)
    elif kind == "ELLIPSE":
        ce = e.construction_tool()
        span = (ce.end_param - ce.start_param) % (2 * math.pi)
        full = span == 0 or abs(span - 2 * math.pi) < 1e-9
        add_flat(acc, list(ce.flattening(flat, segments=16)), full)


def exploded(entities):
    """Entities with INSERTs exploded recursively (ezdxf's transformations).
    Only INSERTs: disassemble.recursive_decompose also explodes DIMENSIONs
    into lines and arcs, which are annotation, not cuttable geometry."""
    for e in entities:
        if e.dxftype() == "INSERT":
            # multi_insert: one INSERT per copy of a column/row array.
            for one in e.multi_insert():
                yield from exploded(one.virtual_entities())
        else:
            yield e


def reference(filename):
    doc = open_doc(filename)
    geo = cuttable(doc, exploded(doc.modelspace()))
    # A first pass for the size, which sets the flattening distance.
    rough = Acc()
    for e in geo:
        entity(rough, e, 1e-3)
    size = max(rough.box[2] - rough.box[0], rough.box[3] - rough.box[1]) if rough.box else 1.0
    flat = FLAT * max(size, 1e-9)
    acc = Acc()
    layers = set()
    for e in geo:
        entity(acc, e, flat)
        layers.add(e.dxf.get("layer", "0"))
    return {
        "insunits": declared_insunits(doc, filename),
        "length": acc.length,
        "bbox": acc.box,
        "areas": sorted(acc.areas),
        "layers": sorted(layers),
        "flat": flat,
    }


def main():
    corpus = pathlib.Path(sys.argv[1])
    make_fixtures()
    out = {}
    for category, files in CATEGORIES.items():
        for name in files:
            path = HERE / name if name.startswith("fixtures/") else corpus / name
            r = reference(str(path))
            r["category"] = category
            out[name] = r
    json.dump(out, sys.stdout, indent=1, sort_keys=True, ensure_ascii=False)
    print()


if __name__ == "__main__":
    main()
