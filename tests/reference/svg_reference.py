#!/usr/bin/env python3
"""Independent reference values for tests/it/svg.rs, computed with svgelements.

For each SVG of ../shared/corpus-svg: the page size (width/height, or the
viewBox as px) and the bounding box of the shapes drawn (paths, rects,
circles, ellipses, lines, polylines, polygons; <use> expanded; text, images
and hidden elements left out), in millimetres at 96 px per inch, y down as
SVG has it (the test compares sizes, not positions). Curves' boxes are
svgelements' exact ones. Run by hand (pip install svgelements), review the
diff, commit:

    python3 tests/reference/svg_reference.py ../shared/corpus-svg > tests/reference/corpus-svg.json
"""
import json
import math
import pathlib
import sys

from svgelements import SVG, Shape, Use, Group

MM_PER_PX = 25.4 / 96.0


def reference(path):
    svg = SVG.parse(str(path), ppi=96.0, reify=True)
    box = None
    count = 0
    for e in svg.elements():
        if not isinstance(e, Shape) or isinstance(e, (Use, Group)):
            continue
        if e.values.get("visibility") in ("hidden", "collapse"):
            continue
        b = e.bbox(transformed=True, with_stroke=False)
        if b is None or not all(math.isfinite(v) for v in b):
            continue
        count += 1
        box = b if box is None else (min(box[0], b[0]), min(box[1], b[1]), max(box[2], b[2]), max(box[3], b[3]))
    out = {"shapes": count}
    w, h = svg.width, svg.height
    if w and h:
        out["page_mm"] = [round(w * MM_PER_PX, 4), round(h * MM_PER_PX, 4)]
    if box is not None:
        out["size_mm"] = [round((box[2] - box[0]) * MM_PER_PX, 4), round((box[3] - box[1]) * MM_PER_PX, 4)]
    return out


def main(root):
    root = pathlib.Path(root)
    result = {}
    for p in sorted(root.rglob("*.svg")):
        name = str(p.relative_to(root))
        try:
            result[name] = reference(p)
        except Exception as e:  # a file svgelements cannot read: said, not guessed
            result[name] = {"error": type(e).__name__}
    json.dump(result, sys.stdout, indent=1, sort_keys=True)
    print()


if __name__ == "__main__":
    main(sys.argv[1])
