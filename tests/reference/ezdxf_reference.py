#!/usr/bin/env python3
"""Independent reference values for tests/reader_reference.rs, computed with ezdxf.

For each corpus DXF: model-space entity counts by type (a scan of ezdxf's
model space: VERTEX/SEQEND/ATTRIB belong to their owner), $INSUNITS, and the
extents of the cuttable geometry (paths flattened to 0.001) (LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE,
SPLINE, ELLIPSE; INSERTs exploded recursively) on visible, thawed layers, in
drawing units. Run by hand (pip install ezdxf), review the diff, commit:

    python3 tests/reference/ezdxf_reference.py ../shared/corpus > tests/reference/corpus.json
"""
import json
import pathlib
import sys

import ezdxf
from ezdxf import disassemble, path, recover

GEOMETRY = {"LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE", "SPLINE", "ELLIPSE"}


def open_doc(filename):
    """The drawing, read strictly or, failing that, by ezdxf's recover mode."""
    try:
        return ezdxf.readfile(filename)
    except Exception:
        doc, _ = recover.readfile(filename)
        return doc


def cuttable(doc, entities):
    """The cuttable geometry among `entities`: the GEOMETRY types, model
    space only, on visible thawed layers, meshes left out."""
    hidden = {l.dxf.name for l in doc.layers if l.is_off() or l.is_frozen()}
    return [
        e
        for e in entities
        if e.dxftype() in GEOMETRY and e.dxf.get("layer", "0") not in hidden and not e.dxf.get("paperspace", 0)
        and not (e.dxftype() == "POLYLINE" and (e.is_polygon_mesh or e.is_poly_face_mesh))
    ]


def declared_insunits(doc, filename):
    """$INSUNITS as the file states it, or None: ezdxf fills in 6 for files
    without it, so it is taken only from the file itself."""
    with open(filename, "rb") as f:
        declared = b"$INSUNITS" in f.read()
    return doc.header.get("$INSUNITS", 0) if declared else None


def reference(filename):
    doc = open_doc(filename)
    msp = doc.modelspace()
    counts = {}
    for e in msp:
        counts[e.dxftype()] = counts.get(e.dxftype(), 0) + 1
    geo = cuttable(doc, disassemble.recursive_decompose(msp))
    # Extents of the flattened paths (ezdxf's bbox.extents disagrees with its own
    # make_path for 2-D polylines in tilted planes; the path is the geometry).
    box = None
    for e in geo:
        for v in path.make_path(e).flattening(0.001):
            if box is None:
                box = [v.x, v.y, v.x, v.y]
            else:
                box = [min(box[0], v.x), min(box[1], v.y), max(box[2], v.x), max(box[3], v.y)]
    return {"counts": counts, "insunits": declared_insunits(doc, filename), "bbox": box}


def main():
    root = pathlib.Path(sys.argv[1])
    out = {}
    for p in sorted(root.rglob("*")):
        if p.suffix.lower() == ".dxf":
            try:
                out[str(p.relative_to(root))] = reference(str(p))
            except Exception as e:  # a file ezdxf cannot read gives no reference
                out[str(p.relative_to(root))] = {"error": str(e)}
    json.dump(out, sys.stdout, indent=1, sort_keys=True, ensure_ascii=False)
    print()


if __name__ == "__main__":
    main()
