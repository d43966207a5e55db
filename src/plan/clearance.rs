//! Where the torch may go with the torch on and not touch a part: a grid
//! index of the drawn closed contours, queried by lead-ins and chain links.
//!
//! Paper 001 §2.1 (L413): pierce outside the part contour, because a slag
//! blob forms at the pierce point; the thesis leaves collisions with
//! neighbouring parts to the user's eye (L1129). We check them: a lead or a
//! link must not cross any drawn closed contour, and a pierce point must keep
//! a clearance from every one.

use std::collections::HashMap;

pub use super::crossing::{crossings, line_to_segment};
use crate::cell_lists::CellLists;
use crate::contour::Contours;
use crate::geom::{dist_to_segment, BBox, Point, Segment};

/// Segments spanning more cells than this go to a list checked every time.
const MAX_CELLS_PER_SEGMENT: i64 = 1024;

/// Most cells a flat grid may have per indexed segment (plus a constant):
/// beyond, a drawing spread over a huge extent keeps its cells in a map.
const FLAT_CELLS_PER_SEGMENT: i64 = 8;

/// Drawn closed contours in a uniform grid.
pub struct Obstacles {
    segments: Vec<Segment>,
    cell: f64,
    grid: Cells,
    big: Vec<u32>,
    tol: f64,
    /// Each stored segment's contour, when asked ([`Obstacles::with_owners`]).
    owners: Vec<u32>,
}

/// The segments of each cell. Flat (one array for all cells, a start per
/// cell) when the drawing's cells are few enough: hashing each cell of
/// every segment was most of the index's time on a 137k-contour sheet, and
/// each query's cells are a few array reads. A map otherwise. Either way a
/// segment is in exactly the cells its bounding box meets, so queries see
/// the same segments.
enum Cells {
    Flat {
        /// Cell coordinates of the grid's first cell.
        x0: i64,
        y0: i64,
        nx: i64,
        ny: i64,
        /// Cell `(y - y0) * nx + (x - x0)`'s segments.
        lists: CellLists,
    },
    Map(HashMap<(i64, i64), Vec<u32>>),
}

impl Obstacles {
    /// Indexes every closed contour's segments; `tol` is the one tolerance.
    pub fn new(contours: &Contours, tol: f64) -> Obstacles {
        Obstacles::build(contours, tol, false)
    }

    /// [`Obstacles::new`] that also knows each segment's contour
    /// ([`Obstacles::owner`]).
    pub fn with_owners(contours: &Contours, tol: f64) -> Obstacles {
        Obstacles::build(contours, tol, true)
    }

    /// The contour (index) of segment `i`; with [`Obstacles::with_owners`] only.
    pub(crate) fn owner(&self, i: u32) -> usize {
        self.owners[i as usize] as usize
    }

    fn build(contours: &Contours, tol: f64, owned: bool) -> Obstacles {
        // Sized first: collected from a flat map the vector grew by
        // doubling, and on a 137k-contour sheet its copies and fresh pages
        // (zeroed by the kernel on first touch) were a third of the index.
        let closed = || contours.contours.iter().filter(|c| c.is_closed());
        let finite = || {
            closed()
                .flat_map(|c| c.segments.iter())
                .filter(|s| s.is_finite())
        };
        // Each segment's box once (it was made twice, and an arc's box
        // with four sines, four cosines and two arc tangents was a third
        // of the index's time on a 137k-contour sheet): see `index_box`.
        let mut boxes: Vec<BBox> = Vec::with_capacity(closed().map(|c| c.segments.len()).sum());
        boxes.extend(finite().map(index_box));
        let count = boxes.len();
        let mut ext = BBox::EMPTY;
        for b in &boxes {
            ext.union(b);
        }
        // About one segment per cell, but never finer than 1 mm.
        let area = if ext.is_empty() {
            1.0
        } else {
            ((ext.max.x - ext.min.x) * (ext.max.y - ext.min.y)).max(1.0)
        };
        let cell = (area / count.max(1) as f64).sqrt().max(1.0);
        let mut o = Obstacles {
            segments: Vec::new(),
            cell,
            grid: Cells::Map(HashMap::new()),
            big: Vec::new(),
            tol,
            owners: Vec::new(),
        };
        // Each segment's cells, or None for a big one (or one beyond
        // i32 cell numbers: a drawing thousands of km wide), kept as i32
        // (16 bytes a segment; as Option<(i64, ..)> they were 16 MB of
        // fresh pages on a 137k-contour sheet, each zeroed by the kernel on
        // first touch). A big segment is checked by every query instead.
        const BIG: [i32; 4] = [1, 0, 0, 0];
        let mut big = Vec::new();
        let (mut lo_x, mut lo_y, mut hi_x, mut hi_y) = (i64::MAX, i64::MAX, i64::MIN, i64::MIN);
        let mut kept: Vec<[i32; 4]> = Vec::with_capacity(count);
        for (i, b) in boxes.iter().enumerate() {
            let (x0, y0, x1, y1) = o.cells(b);
            let fits = [x0, y0, x1, y1].iter().all(|&v| i32::try_from(v).is_ok());
            if fits && (x1 - x0 + 1).saturating_mul(y1 - y0 + 1) <= MAX_CELLS_PER_SEGMENT {
                (lo_x, lo_y) = (lo_x.min(x0), lo_y.min(y0));
                (hi_x, hi_y) = (hi_x.max(x1), hi_y.max(y1));
                kept.push([x0, y0, x1, y1].map(|v| v as i32));
            } else {
                big.push(i as u32);
                kept.push(BIG);
            }
        }
        drop(boxes);
        let ranges = || {
            kept.iter().map(|r| {
                (*r != BIG).then(|| {
                    let [x0, y0, x1, y1] = r.map(i64::from);
                    (x0, y0, x1, y1)
                })
            })
        };
        let (nx, ny) = (
            hi_x.saturating_sub(lo_x).saturating_add(1),
            hi_y.saturating_sub(lo_y).saturating_add(1),
        );
        let flat = lo_x <= hi_x
            && nx.saturating_mul(ny) <= FLAT_CELLS_PER_SEGMENT.saturating_mul(count as i64) + 4096;
        // Where each segment is copied to, last (empty: as found).
        let mut slot: Vec<u32> = Vec::new();
        if flat {
            let index = |x: i64, y: i64| ((y - lo_y) * nx + (x - lo_x)) as usize;
            // Stored by the cell of their box's lower left corner (big
            // ones last), a query's segments lie side by side: in drawing
            // order a lead-in's were a cache miss each (half of `lead_in`
            // on a 137k-contour sheet, perf). Queries meet the same
            // segments, and least distances and "all clear" are order-free.
            let cells = (nx * ny) as usize;
            let mut at = vec![0u32; cells + 2];
            let home = |r: &[i32; 4]| {
                if *r == BIG {
                    cells
                } else {
                    index(i64::from(r[0]), i64::from(r[1]))
                }
            };
            for r in &kept {
                at[home(r) + 1] += 1;
            }
            for c in 1..at.len() {
                at[c] += at[c - 1];
            }
            slot.reserve_exact(count);
            for r in &kept {
                let h = home(r);
                slot.push(at[h]);
                at[h] += 1;
            }
            let lists = CellLists::build((nx * ny) as usize, |f| {
                for (i, r) in ranges().enumerate() {
                    let Some((x0, y0, x1, y1)) = r else { continue };
                    for y in y0..=y1 {
                        for x in x0..=x1 {
                            f.push(index(x, y), slot[i]);
                        }
                    }
                }
            });
            o.grid = Cells::Flat {
                x0: lo_x,
                y0: lo_y,
                nx,
                ny,
                lists,
            };
        } else {
            let mut map: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
            for (i, r) in ranges().enumerate() {
                let Some((x0, y0, x1, y1)) = r else { continue };
                for x in x0..=x1 {
                    for y in y0..=y1 {
                        map.entry((x, y)).or_default().push(i as u32);
                    }
                }
            }
            o.grid = Cells::Map(map);
        }
        // Each finite segment's contour, in the order `finite` gives them.
        let owner_of = || {
            contours
                .contours
                .iter()
                .enumerate()
                .filter(|(_, c)| c.is_closed())
                .flat_map(|(k, c)| {
                    c.segments
                        .iter()
                        .filter(|s| s.is_finite())
                        .map(move |_| k as u32)
                })
        };
        if owned {
            if slot.is_empty() {
                o.owners = owner_of().collect();
            } else {
                o.owners = vec![0; count];
                for (k, &to) in owner_of().zip(&slot) {
                    o.owners[to as usize] = k;
                }
            }
        }
        if slot.is_empty() {
            o.segments.reserve_exact(count);
            o.segments.extend(finite().copied());
        } else {
            for b in &mut big {
                *b = slot[*b as usize];
            }
            o.segments = vec![Segment::line(Point::default(), Point::default()); count];
            for (s, &to) in finite().zip(&slot) {
                o.segments[to as usize] = *s;
            }
        }
        o.big = big;
        o
    }

    fn cells(&self, b: &BBox) -> (i64, i64, i64, i64) {
        let f = |v: f64| (v / self.cell).floor().clamp(-1e12, 1e12) as i64;
        (f(b.min.x), f(b.min.y), f(b.max.x), f(b.max.y))
    }

    /// Calls `f` with every segment whose cells meet `b` (some more than
    /// once: every use is a minimum or an "all", which repeats do not
    /// change), until `f` returns false; false if it did.
    fn each_near(&self, b: &BBox, mut f: impl FnMut(&Segment) -> bool) -> bool {
        self.each_index_near(b, |i| f(&self.segments[i as usize]))
    }

    /// [`Self::each_near`] by the segments' numbers ([`Self::segment`]).
    pub(crate) fn each_index_near(&self, b: &BBox, mut f: impl FnMut(u32) -> bool) -> bool {
        let (x0, y0, x1, y1) = self.cells(b);
        if (x1 - x0 + 1).saturating_mul(y1 - y0 + 1) > MAX_CELLS_PER_SEGMENT * 16 {
            // A query as big as the drawing: every segment.
            return (0..self.segments.len() as u32).all(f);
        }
        for &i in &self.big {
            if !f(i) {
                return false;
            }
        }
        match &self.grid {
            Cells::Flat {
                x0: gx,
                y0: gy,
                nx,
                ny,
                lists,
            } => {
                // Cells outside the grid hold nothing.
                let (xa, xb) = (x0.max(*gx), x1.min(gx + nx - 1));
                let (ya, yb) = (y0.max(*gy), y1.min(gy + ny - 1));
                for y in ya..=yb {
                    for x in xa..=xb {
                        let c = ((y - gy) * nx + (x - gx)) as usize;
                        for &i in lists.get(c) {
                            if !f(i) {
                                return false;
                            }
                        }
                    }
                }
            }
            Cells::Map(map) => {
                for x in x0..=x1 {
                    for y in y0..=y1 {
                        for &i in map.get(&(x, y)).into_iter().flatten() {
                            if !f(i) {
                                return false;
                            }
                        }
                    }
                }
            }
        }
        true
    }

    /// Segment number `i` of [`Self::each_index_near`].
    pub(crate) fn segment(&self, i: u32) -> &Segment {
        &self.segments[i as usize]
    }

    /// How many segments are indexed (their numbers are `0..len`).
    pub(crate) fn len(&self) -> usize {
        self.segments.len()
    }

    /// True when the straight move `p → q` crosses or touches no drawn
    /// contour, except within the tolerance of the points in `allowed`
    /// (where a lead meets its own contour).
    pub fn line_is_clear(&self, p: Point, q: Point, allowed: &[Point]) -> bool {
        let mut b = BBox::EMPTY;
        b.add(p);
        b.add(q);
        let lead = Segment::line(p, q);
        self.each_near(&b, |s| {
            crossings(&lead, s)
                .iter()
                .all(|x| allowed.iter().any(|a| a.dist(x) <= 2.0 * self.tol))
        })
    }

    /// True when a whole path (lines and arcs) is clear, as [`Self::line_is_clear`].
    pub fn path_is_clear(&self, path: &[Segment], allowed: &[Point]) -> bool {
        path.iter().all(|s| match s.arc_center() {
            None => self.line_is_clear(s.a, s.b, allowed),
            // Arcs as 16 chords: leads are short, and the pierce clearance
            // keeps them well away from parts anyway.
            Some(_) => (0..16).all(|k| {
                let a = s.point_at(k as f64 / 16.0);
                let b = s.point_at((k + 1) as f64 / 16.0);
                self.line_is_clear(a, b, allowed)
            }),
        })
    }

    /// Distance from `p` to the nearest drawn contour, looked for up to `reach`.
    pub fn distance(&self, p: Point, reach: f64) -> f64 {
        let mut b = BBox::EMPTY;
        b.add(Point::new(p.x - reach, p.y - reach));
        b.add(Point::new(p.x + reach, p.y + reach));
        let mut least = f64::INFINITY;
        // A margin far above rounding, far below any tolerance.
        let slack = 1e-9 * (1.0 + reach + p.x.abs() + p.y.abs());
        self.each_near(&b, |s| {
            // A segment surely farther than the least found so far leaves
            // it as it is: a line whose box is, an arc whose disc about its
            // chord's midpoint is (as in `clear_of`). Skipped before the
            // exact distance: the lead checks of a dense sheet ask this at
            // every lead tried (perf: a graded garment pattern).
            let beyond = least + slack;
            if s.is_line() {
                let mut sb = BBox::at(s.a);
                sb.add(s.b);
                if sb.gap_sq(p) > beyond * beyond {
                    return true;
                }
            } else {
                let len = |v: Point| (v.x * v.x + v.y * v.y).sqrt();
                let mid = s.a.add(s.b).scale(0.5);
                let half = 0.5 * len(s.b.sub(s.a)) * s.bulge.abs().max(1.0);
                if len(p.sub(mid)) - half > beyond {
                    return true;
                }
            }
            least = least.min(dist_to_segment(p, s));
            true
        });
        least
    }
    /// True when no drawn contour comes nearer `p` than `clearance`: the
    /// answer of `distance(p, reach) >= clearance` for any `reach` ≥
    /// `clearance`, without the least distance itself. It looks only in the
    /// box the clearance spans (anything nearer lies in it), stops at the
    /// first segment too near, and skips an arc whose bounding disc lies
    /// beyond the clearance without placing its centre (a pierce check is
    /// made for every lead tried; on a 137k-contour sheet the exact
    /// distance to each arc nearby was a third of the cuts' time, perf).
    pub fn clear_of(&self, p: Point, clearance: f64) -> bool {
        let mut b = BBox::EMPTY;
        b.add(Point::new(p.x - clearance, p.y - clearance));
        b.add(Point::new(p.x + clearance, p.y + clearance));
        // A margin far above rounding, far below any tolerance.
        let beyond = clearance + 1e-9 * (1.0 + clearance + p.x.abs() + p.y.abs());
        self.each_near(&b, |s| {
            if !s.is_line() {
                // Every point of an arc lies within half its chord times
                // max(1, |bulge|) of the chord's midpoint (a minor arc
                // inside the circle on its chord, a major one within its
                // sagitta), so it is at least that much less far.
                let len = |v: Point| (v.x * v.x + v.y * v.y).sqrt();
                let mid = s.a.add(s.b).scale(0.5);
                let reach = 0.5 * len(s.b.sub(s.a)) * s.bulge.abs().max(1.0);
                if len(p.sub(mid)) - reach > beyond {
                    return true;
                }
            }
            // `distance` takes the least and ignores a NaN: so does this.
            let d = dist_to_segment(p, s);
            d >= clearance || d.is_nan()
        })
    }

    /// Least distance from the straight move `p → q` to any drawn closed
    /// contour, looked for up to `reach` mm from the move (∞ beyond).
    pub fn line_distance(&self, p: Point, q: Point, reach: f64) -> f64 {
        let mut b = BBox::EMPTY;
        b.add(Point::new(p.x.min(q.x) - reach, p.y.min(q.y) - reach));
        b.add(Point::new(p.x.max(q.x) + reach, p.y.max(q.y) + reach));
        let l = Segment::line(p, q);
        let mut least = f64::INFINITY;
        self.each_near(&b, |s| {
            least = least.min(line_to_segment(&l, s));
            true
        });
        least
    }
}

/// A box holding every point of `s`, where the index files it: a line's
/// own box; an arc's ends and those of its circle's four axis extremes
/// (centre ± radius) that lie on the arc's side of its chord (the chord's
/// line cuts the circle into the arc and the rest, and the arc bulges to
/// the right of `a → b` when counter-clockwise), widened by a margin far
/// above rounding. No sine, cosine or arc tangent, and never smaller than
/// [`Segment::bbox`]: a query still meets every segment it met, and each
/// answer (a least distance, or "all clear") is the same whichever extra
/// segments it also looks at.
pub(crate) fn index_box(s: &Segment) -> BBox {
    let (a, b) = (s.a, s.b);
    let mut bb = BBox {
        min: Point::new(a.x.min(b.x), a.y.min(b.y)),
        max: Point::new(a.x.max(b.x), a.y.max(b.y)),
    };
    let mut r = 0.0;
    if let Some((c, radius)) = s.arc_center() {
        r = radius;
        let chord = b.sub(a);
        for p in [
            Point::new(c.x + r, c.y),
            Point::new(c.x - r, c.y),
            Point::new(c.x, c.y + r),
            Point::new(c.x, c.y - r),
        ] {
            // > 0 on the arc's side (right of the chord for bulge > 0).
            let side = -chord.cross(p.sub(a)) * s.bulge;
            if side >= -1e-9 * (chord.dot(chord) + r * r) * s.bulge.abs() {
                bb.add(p);
            }
        }
    }
    let m = 1e-9 * (1.0 + r + a.x.abs().max(a.y.abs()) + b.x.abs().max(b.y.abs()));
    bb.min = Point::new(bb.min.x - m, bb.min.y - m);
    bb.max = Point::new(bb.max.x + m, bb.max.y + m);
    bb
}

#[cfg(test)]
#[path = "clearance_tests.rs"]
mod tests;
