//! Parts closer than the kerf (issue 14): common-line cutting needs parts
//! nested with a spacing of exactly the kerf, so that the compensated paths
//! of two neighbours coincide. Closer parts (touching, as in paper 003's
//! fabric grid, or a nest exported with no gap) cannot both keep their size:
//! each part's path runs inside its neighbour by the kerf minus the gap.
//! The order cuts what was asked and says which parts lose material and how
//! much: a common edge once on the drawn line (half the kerf from each part,
//! [`super::touching`]); parts that only touch at a corner or are closer
//! than the kerf, each on its own kerf path (the kerf less the gap from each).

use crate::cell_lists::CellLists;
use crate::contour::{ContourKind, Contours};
use crate::fx::FxMap;
use crate::geom::{dist_to_segment, floor, BBox, Point, Segment};
use crate::text;
use crate::warning::{dec, Warning};

/// Two part numbers, the smaller first.
type Pair = (usize, usize);
/// Closest gap between two parts, where, and how many samples touch.
type Approach = (f64, Point, usize);

/// Pairs of parts named one by one; further pairs are counted.
const MAX_NAMED: usize = 20;
/// Most grid cells one segment is filed under; longer ones are checked always.
const MAX_CELLS: i64 = 4096;
/// Most cells of the grid per segment, plus a few.
const CELLS_PER_SEGMENT: i64 = 4;

/// The parts' segments filed by the cells of a flat grid their boxes meet
/// ([`CellLists`]), cells at least `least` wide (a sample's 3 x 3 cells
/// then hold every segment within `least` of it) and about a segment's
/// share of the sheet: a map of vectors by 6 mm cell was most of the
/// eulerian order's time on a 137k-contour sheet (issue 17).
struct SegmentGrid {
    cell: f64,
    /// The grid's first cell, cells across and up.
    x0: i64,
    y0: i64,
    nx: i64,
    ny: i64,
    lists: CellLists,
    /// Segments over more than [`MAX_CELLS`] cells (or not finite):
    /// checked always.
    always: Vec<u32>,
}

impl SegmentGrid {
    fn new(boxes: &[BBox], least: f64) -> SegmentGrid {
        let mut ext = BBox::EMPTY;
        for b in boxes {
            ext.union(b);
        }
        let finite = !ext.is_empty() && ext.min.is_finite() && ext.max.is_finite();
        let (w, h) = match finite {
            true => (ext.max.x - ext.min.x, ext.max.y - ext.min.y),
            false => (0.0, 0.0),
        };
        let most = CELLS_PER_SEGMENT.saturating_mul(boxes.len() as i64) + 4096;
        let mut cell = least.max((w * h / boxes.len().max(1) as f64).sqrt());
        while (w / cell + 2.0) * (h / cell + 2.0) > most as f64 && cell < f64::MAX / 4.0 {
            cell *= 2.0;
        }
        let mut g = SegmentGrid {
            cell,
            x0: 0,
            y0: 0,
            nx: 0,
            ny: 0,
            lists: CellLists::default(),
            always: Vec::new(),
        };
        if finite {
            (g.x0, g.y0) = g.cell(ext.min);
            let (x1, y1) = g.cell(ext.max);
            (g.nx, g.ny) = (x1 - g.x0 + 1, y1 - g.y0 + 1);
        }
        let ranges: Vec<Option<(i64, i64, i64, i64)>> = boxes
            .iter()
            .map(|b| {
                let (lo, hi) = (g.cell(b.min), g.cell(b.max));
                let inside = finite && b.min.is_finite() && b.max.is_finite();
                (inside && (hi.0 - lo.0 + 1).saturating_mul(hi.1 - lo.1 + 1) <= MAX_CELLS)
                    .then_some((lo.0 - g.x0, lo.1 - g.y0, hi.0 - g.x0, hi.1 - g.y0))
            })
            .collect();
        g.always = (ranges.iter().enumerate())
            .filter(|(_, r)| r.is_none())
            .map(|(i, _)| i as u32)
            .collect();
        let nx = g.nx;
        g.lists = CellLists::build((g.nx * g.ny) as usize, |f| {
            for (i, r) in ranges.iter().enumerate() {
                let Some((x0, y0, x1, y1)) = *r else { continue };
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        f.push((y * nx + x) as usize, i as u32);
                    }
                }
            }
        });
        g
    }

    /// The cell of a point (not clamped).
    fn cell(&self, p: Point) -> (i64, i64) {
        let f = |v: f64| floor(v / self.cell).clamp(-1e15, 1e15) as i64;
        (f(p.x), f(p.y))
    }

    /// The segments filed under cell `(x, y)`; none off the grid.
    fn at(&self, x: i64, y: i64) -> &[u32] {
        let (i, j) = (x.saturating_sub(self.x0), y.saturating_sub(self.y0));
        if i < 0 || j < 0 || i >= self.nx || j >= self.ny {
            return &[];
        }
        self.lists.get((j * self.nx + i) as usize)
    }
}

/// Warnings for every pair of parts whose drawn contours come closer than
/// `kerf` (less the tolerance `tol`).
pub fn warnings(contours: &Contours, kerf: f64, tol: f64) -> Vec<Warning> {
    if kerf.is_nan() || kerf <= tol {
        // No kerf: touching parts share their drawn line and lose nothing.
        return Vec::new();
    }
    let segs: Vec<(Segment, usize)> = contours
        .contours
        .iter()
        .filter(|c| c.kind != ContourKind::Open)
        .filter_map(|c| c.part.map(|p| (c, p)))
        .flat_map(|(c, p)| c.segments.iter().map(move |s| (*s, p)))
        .filter(|(s, _)| s.is_finite())
        .collect();
    let boxes: Vec<BBox> = segs.iter().map(|(s, _)| s.bbox()).collect();
    let grid = SegmentGrid::new(&boxes, kerf.max(1.0) * 4.0);
    // Closest approach of each pair of parts: (part, part) → (gap, where,
    // samples touching): one touching sample is a corner, more an edge.
    let mut close: FxMap<Pair, Approach> = FxMap::default();
    let step = (kerf / 2.0).max(tol);
    let mut near = Vec::new();
    let mut touched = Vec::new();
    for c in contours
        .contours
        .iter()
        .filter(|c| c.kind == ContourKind::Outer)
    {
        let Some(part) = c.part else { continue };
        for s in c.segments.iter().filter(|s| s.is_finite()) {
            // The other parts' segments a sample of `s` can come within the
            // kerf of, gathered once for the segment: those filed under the
            // cells around its box (a sample's 3 x 3 cells lie among them)
            // whose box comes within the kerf of its box. On a nest spaced
            // wider than the kerf nearly every segment has none and is not
            // sampled (the 4 MB nest's check was half the order's 1.7 s).
            // Each sample then weighs the same segments as its own cells
            // would give, but for ones farther than the kerf, which add
            // nothing.
            let b = s.bbox();
            let (lo, hi) = (grid.cell(b.min), grid.cell(b.max));
            let cells = (hi.0 - lo.0 + 3).saturating_mul(hi.1 - lo.1 + 3);
            near.clear();
            near.extend(
                grid.always
                    .iter()
                    .copied()
                    .filter(|&i| segs[i as usize].1 != part),
            );
            if cells <= MAX_CELLS {
                for y in lo.1.saturating_sub(1)..=hi.1.saturating_add(1) {
                    for x in lo.0.saturating_sub(1)..=hi.0.saturating_add(1) {
                        near.extend(grid.at(x, y).iter().copied().filter(|&i| {
                            segs[i as usize].1 != part && boxes[i as usize].overlaps(&b, kerf)
                        }));
                    }
                }
                near.sort_unstable();
                near.dedup();
                if near.is_empty() {
                    continue;
                }
            }
            let n = ((s.length() / step).ceil() as usize).clamp(1, 100_000);
            for k in 0..=n {
                let p = s.point_at(k as f64 / n as f64);
                if cells > MAX_CELLS {
                    // A segment across too many cells: each sample's own.
                    let (x, y) = grid.cell(p);
                    near.clear();
                    near.extend_from_slice(&grid.always);
                    for dy in -1..=1_i64 {
                        for dx in -1..=1_i64 {
                            near.extend_from_slice(
                                grid.at(x.saturating_add(dx), y.saturating_add(dy)),
                            );
                        }
                    }
                }
                touched.clear();
                // Farther from a segment's box than the kerf is farther from
                // the segment: such samples skip the exact distance (most of
                // the check's time on graded patterns, whose sizes lie inside
                // one another). The margin covers the box's rounding, so the
                // distances weighed are the ones weighed without the skip.
                let slack = 1e-6 + 1e-12 * (p.x.abs() + p.y.abs());
                let reach = kerf - tol + slack;
                for &i in &near {
                    let (t, other) = segs[i as usize];
                    if other == part || boxes[i as usize].gap_sq(p) > reach * reach {
                        continue;
                    }
                    let d = dist_to_segment(p, &t);
                    if d < kerf - tol {
                        let e = close.entry((part.min(other), part.max(other))).or_insert((
                            f64::INFINITY,
                            p,
                            0,
                        ));
                        if d < e.0 {
                            (e.0, e.1) = (d, p);
                        }
                        if d <= tol && !touched.contains(&other) {
                            touched.push(other);
                            e.2 += 1;
                        }
                    }
                }
            }
        }
    }
    // Faces of lines drawn once that share edges are cut on those lines,
    // which `parts-share-edges` says (issue 39 §6): where two of them
    // meet, at an edge or a corner, each loses half the kerf.
    let mut faces: Vec<usize> = (contours.shared.contours.iter())
        .filter_map(|&c| contours.contours.get(c)?.part)
        .collect();
    faces.sort_unstable();
    let face = |p: &usize| faces.binary_search(p).is_ok();
    let mut pairs: Vec<(Pair, Approach)> = close
        .into_iter()
        .filter(|((a, b), _)| !(face(a) && face(b)))
        .collect();
    crate::sort::sort_by_key(&mut pairs, |p| p.0);
    let mut out = Vec::new();
    for &((a, b), (gap, at, touching)) in pairs.iter().take(MAX_NAMED) {
        // Hundredths of a mm: what a shop measures.
        let r2 = |v: f64| (v * 100.0).round() / 100.0;
        let (loss, w, g) = (r2(kerf - gap), r2(kerf), r2(gap));
        // A corner sample is met from both edges' ends: up to 4 at one point.
        let text = if touching > 4 {
            // Cut once on the common edge (touching.rs): half the kerf each.
            let loss = r2(kerf / 2.0);
            text!("parts {a} and {b} share an edge: each loses {loss} mm there; space them by the kerf ({w} mm) for common-line cutting";
                  "as peças {a} e {b} têm uma aresta comum: cada uma perde {} mm ali; espace-as pela sangria ({} mm) para o corte em linha comum", dec(loss), dec(w))
        } else if gap <= tol {
            text!("parts {a} and {b} touch at a corner: each loses {loss} mm there; space them by the kerf ({w} mm)";
                  "as peças {a} e {b} se tocam num canto: cada uma perde {} mm ali; espace-as pela sangria ({} mm)", dec(loss), dec(w))
        } else {
            text!("parts {a} and {b} are {g} mm apart, closer than the kerf ({w} mm): each loses {loss} mm there; space them by the kerf for common-line cutting";
                  "as peças {a} e {b} estão a {} mm uma da outra, menos que a sangria ({} mm): cada uma perde {} mm ali; espace-as pela sangria para o corte em linha comum", dec(g), dec(w), dec(loss))
        };
        out.push(Warning::at("parts-closer-than-kerf", text, at));
    }
    if pairs.len() > MAX_NAMED {
        let more = pairs.len() - MAX_NAMED;
        out.push(Warning::new(
            "parts-closer-than-kerf",
            text!("{more} more pair(s) of parts closer than the kerf";
                  "mais {more} par(es) de peças mais próximas que a sangria"),
        ));
    }
    out
}
