//! The box of a many-vertex shape cut into square cells, each marked
//! outside, inside or near its boundary, with the vertices of each cell:
//! the index of the points-inside half of the exact test ([`super::inside`]).
//!
//! Past the crossing test, a neighbour's boundary is tested piece by piece:
//! every piece of it within the shape's box gets the vertices of the shape
//! near it (the cuts) and the parity and distance tests of its middle. On
//! keyboard plates and brackets (300–700 vertices) that was the largest
//! share of a nest (perf, issue 44: 38 %), almost every piece lying outside
//! the shape, and the lists of edges and vertices near the neighbour were
//! made anew for every pair. A piece in cells all outside (or all inside)
//! is answered by them, and the others find their cuts in the cells they
//! cross: the answer is the same, as a cell not near the boundary is more
//! than a quarter of a cell from it, where the parity test is exact and
//! no vertex can cut.
//!
//! The cells are made where the shape was made, on its first exact test
//! ([`Lazy`]: most turns of most parts and holes are never tested so),
//! and shared by its moved copies (as the height bands of
//! [`super::bands`]): a point asked is taken back by the shape's move,
//! and the rounding of the moves (a billionth of the coordinates at most,
//! as there) is far below the margin of an eighth of a cell the answers
//! keep.
//!
//! MEASURED 2026-12-01 (CPU %U new/main, medians of 5 alternating pairs,
//! 6 000 evaluations, nests cmp-identical): keyboard 0.68, brackets 0.96,
//! panels 0.94, flanges 1.00, flanges-solid 1.00, boxes 0.99 (pairs 0.78
//! to 1.11); free turns on the alps plate 1.02 (3 000 evaluations) and
//! 0.99 (100: the setup, 1.21 with the cells made at once). The
//! threshold [`CELLS_FROM`]: from 16 vertices, flanges (27–63) 1.21 and
//! free turns 1.17 / 1.10; from 64, 1.12 and 1.03 / 0.89 (one run of
//! pairs each); from 128 no better. A machine shared while measured:
//! ESICUP runs, which make no cells, gave pairs 0.81–1.58.

use std::sync::OnceLock;

use crate::geom::{fmax, fmin, Point};

/// Shapes of more vertices than this keep cells.
pub(super) const CELLS_FROM: usize = 64;

/// A shape's cells, made on the first exact test that asks them, from a
/// copy of its vertices where it was made: the placer makes a shape for
/// every turn of every part and hole, and many are never tested
/// exactly. Shared by the shape's moved copies (behind an `Arc`), so
/// they are made once, the same wherever the shape first stood.
#[derive(Debug)]
pub(super) struct Lazy {
    pts: Vec<Point>,
    made: OnceLock<Option<Cells>>,
}

impl Lazy {
    /// The cells of the polygon of vertices `pts`, to be made.
    pub fn of(pts: &[Point]) -> Lazy {
        Lazy {
            pts: pts.to_vec(),
            made: OnceLock::new(),
        }
    }
    /// The cells, made now if not yet ([`Cells::of`]).
    #[inline]
    pub fn get(&self) -> Option<&Cells> {
        self.made.get_or_init(|| Cells::of(&self.pts)).as_ref()
    }
    /// Made already?
    #[cfg(test)]
    pub fn made(&self) -> bool {
        self.made.get().is_some()
    }
}

/// A cell's mark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub(super) enum Mark {
    /// More than a quarter of a cell outside the boundary.
    Out = 1,
    /// More than a quarter of a cell inside it.
    In = 2,
    /// Within a quarter of a cell of it.
    Near = 4,
}

/// Cells over a polygon's box (and one more all round), in its
/// coordinates where it was made.
#[derive(Debug)]
pub(super) struct Cells {
    x0: f64,
    y0: f64,
    step: f64,
    /// 1 / step.
    inv: f64,
    nx: usize,
    ny: usize,
    /// Cell `j · nx + i` (column i, row j).
    marks: Vec<Mark>,
    /// How many rings of cells round each cell hold no near cell (0 for a
    /// near cell, at most 255): the cells of a short segment all lie
    /// within them, and are then all marked as its first one is.
    clear: Vec<u8>,
    /// The vertices (indices) in cell c: `index[start[c]..start[c + 1]]`.
    start: Vec<u32>,
    index: Vec<u32>,
    /// The greatest coordinate of the cells, for the rounding allowed.
    size: f64,
}

/// What the cells say of the points within a reach of a segment.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Seen(u8);

impl Seen {
    /// Every such point is outside (by more than the reach).
    pub fn all_out(self) -> bool {
        self.0 == Mark::Out as u8
    }
    /// Every such point is inside (by more than the reach).
    pub fn all_in(self) -> bool {
        self.0 == Mark::In as u8
    }
}

impl Cells {
    /// Cells along the longer side of the box.
    const ACROSS: f64 = 64.0;

    /// The cells of the polygon of vertices `pts` (edge i from vertex i
    /// to the next, the last to the first); None when its box is flat or
    /// not finite.
    pub fn of(pts: &[Point]) -> Option<Cells> {
        let n = pts.len();
        let (mut lo, mut hi) = (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for p in pts {
            lo = Point::new(fmin(lo.x, p.x), fmin(lo.y, p.y));
            hi = Point::new(fmax(hi.x, p.x), fmax(hi.y, p.y));
        }
        let (w, h) = (hi.x - lo.x, hi.y - lo.y);
        if !(w > 0.0 && h > 0.0 && w.is_finite() && h.is_finite()) || n > u32::MAX as usize {
            return None;
        }
        let step = fmax(w, h) / Self::ACROSS;
        // (One cell more all round: the cells beyond the box hold no
        // point of the polygon.)
        let (nx, ny) = (
            (w / step).ceil() as usize + 2,
            (h / step).ceil() as usize + 2,
        );
        let (x0, y0) = (lo.x - step, lo.y - step);
        let size = [x0, y0, x0 + nx as f64 * step, y0 + ny as f64 * step]
            .iter()
            .fold(1.0f64, |m, v| fmax(m, v.abs()));
        let mut cells = Cells {
            x0,
            y0,
            step,
            inv: 1.0 / step,
            nx,
            ny,
            marks: vec![Mark::Out; nx * ny],
            clear: Vec::new(),
            start: vec![0; nx * ny + 1],
            index: vec![0; n],
            size,
        };
        let edge = |i: usize| super::runs::edge(pts, i);
        let mut near = vec![false; nx * ny];
        for i in 0..n {
            let (a, b) = edge(i);
            cells.walk(a, b, step / 4.0, |c| near[c] = true);
        }
        // The others by the parity of their centres, a row at a time: a
        // centre more than a quarter of a cell from every edge, whose
        // crossings with its row are then on the right side of it.
        let mut xs: Vec<f64> = Vec::new();
        for j in 0..ny {
            let y = y0 + (j as f64 + 0.5) * step;
            xs.clear();
            xs.extend((0..n).filter_map(|i| {
                let (a, b) = edge(i);
                ((a.y > y) != (b.y > y)).then(|| a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y))
            }));
            xs.sort_by(f64::total_cmp);
            let mut left = 0;
            for i in 0..nx {
                let x = x0 + (i as f64 + 0.5) * step;
                while left < xs.len() && xs[left] <= x {
                    left += 1;
                }
                let c = j * nx + i;
                cells.marks[c] = if near[c] {
                    Mark::Near
                } else if (xs.len() - left) % 2 == 1 {
                    Mark::In
                } else {
                    Mark::Out
                };
            }
        }
        cells.clear = clear_rings(&near, nx, ny);
        // The vertices by cell (counted, then placed).
        let at: Vec<usize> = pts
            .iter()
            .map(|&p| cells.row(p.y) * nx + cells.col(p.x))
            .collect();
        for &c in &at {
            cells.start[c + 1] += 1;
        }
        for c in 0..nx * ny {
            cells.start[c + 1] += cells.start[c];
        }
        let mut fill = cells.start.clone();
        for (k, &c) in at.iter().enumerate() {
            cells.index[fill[c] as usize] = k as u32;
            fill[c] += 1;
        }
        Some(cells)
    }

    /// The reach of the points asked of a shape moved by `at`, `eps` mm
    /// and the rounding of the moves (a billionth of the coordinates,
    /// `far` the greatest of the points asked); None when it passes the
    /// margin the marks keep (an eighth of a cell): ask the edges then.
    pub fn reach(&self, eps: f64, at: Point, far: f64) -> Option<f64> {
        let r = eps + 1e-9 * (self.size + at.x.abs() + at.y.abs() + far);
        (r < self.step / 8.0).then_some(r)
    }

    /// True when a box of these corners passes the cells (its points
    /// there are outside).
    fn beyond(&self, lo: Point, hi: Point) -> bool {
        lo.x < self.x0
            || lo.y < self.y0
            || hi.x > self.x0 + self.nx as f64 * self.step
            || hi.y > self.y0 + self.ny as f64 * self.step
    }

    /// The marks of the cells holding a point within `r` of the segment
    /// `ab` (in the shape's coordinates where it was made); `near` gets
    /// each of those cells marked near.
    pub fn seen(&self, a: Point, b: Point, r: f64, mut near: impl FnMut(usize)) -> Seen {
        let lo = Point::new(fmin(a.x, b.x) - r, fmin(a.y, b.y) - r);
        let hi = Point::new(fmax(a.x, b.x) + r, fmax(a.y, b.y) + r);
        let mut seen = if self.beyond(lo, hi) {
            Mark::Out as u8
        } else {
            0
        };
        if let Some(m) = self.clear_box(a, b, r) {
            return Seen(seen | m as u8);
        }
        self.walk(a, b, r, |c| {
            let m = self.marks[c];
            seen |= m as u8;
            if m == Mark::Near {
                near(c);
            }
        });
        Seen(seen)
    }

    /// True when every point within `r` of the box `lo`–`hi` is outside
    /// (by more than `r`), as the clear rings of a cell say: a run of a
    /// neighbour's edges there is answered at once.
    pub fn box_out(&self, lo: Point, hi: Point, r: f64) -> bool {
        self.clear_box(lo, hi, r) == Some(Mark::Out)
    }

    /// The mark of every cell of the box of `a` and `b` ± `r` (those the
    /// walks of [`Self::seen`] take), when all lie in the clear rings of
    /// `a`'s cell: two neighbours not near lie on one side of the
    /// boundary, so all are marked as it is (and a cell inside has no
    /// neighbour beyond the cells).
    #[inline]
    fn clear_box(&self, a: Point, b: Point, r: f64) -> Option<Mark> {
        let k = self.reach_of(a, b, r);
        let (i, j) = (self.col(a.x), self.row(a.y));
        let span = (i - k.i0).max(k.i1 - i).max(j - k.j0).max(k.j1 - j);
        let c = j * self.nx + i;
        (span < self.clear[c] as usize).then(|| self.marks[c])
    }

    /// The marks of the cells holding a point within `r` of `p` (mostly
    /// one cell).
    pub fn seen_at(&self, p: Point, r: f64) -> Seen {
        let r = r + 1e-9 * self.size;
        let (lo, hi) = (Point::new(p.x - r, p.y - r), Point::new(p.x + r, p.y + r));
        let mut seen = if self.beyond(lo, hi) {
            Mark::Out as u8
        } else {
            0
        };
        for j in self.row(lo.y)..=self.row(hi.y) {
            for i in self.col(lo.x)..=self.col(hi.x) {
                seen |= self.marks[j * self.nx + i] as u8;
            }
        }
        Seen(seen)
    }

    /// The vertices (indices) in cell `c`.
    pub fn vertices(&self, c: usize) -> &[u32] {
        &self.index[self.start[c] as usize..self.start[c + 1] as usize]
    }

    #[inline]
    fn col(&self, x: f64) -> usize {
        index(x, self.x0, self.inv, self.nx)
    }
    #[inline]
    fn row(&self, y: f64) -> usize {
        index(y, self.y0, self.inv, self.ny)
    }

    /// Each cell holding a point within `r` of the segment `ab` (once), a
    /// column at a time: in each, the rows the segment spans over the
    /// column's width (± r), and r more. Where the segment is steeper
    /// than a cell across, the rows of its whole height (its height over
    /// a column computed is then rounded by as much as its slope times
    /// the coordinates' last bit). A billionth of the cells' coordinates
    /// more both ways covers the rounding of the cells' sides and of the
    /// heights.
    /// The box of the segment `ab` ± r, and the rounding allowed (a
    /// billionth of the cells' coordinates: the rounding of the cells'
    /// sides and of the heights), in cells.
    #[inline]
    fn reach_of(&self, a: Point, b: Point, r: f64) -> Reach {
        let r = r + 1e-9 * self.size;
        let (xa, xb) = (fmin(a.x, b.x), fmax(a.x, b.x));
        let (ya, yb) = (fmin(a.y, b.y), fmax(a.y, b.y));
        Reach {
            r,
            xa,
            xb,
            ya,
            yb,
            i0: self.col(xa - r),
            i1: self.col(xb + r),
            j0: self.row(ya - r),
            j1: self.row(yb + r),
        }
    }

    /// Each cell holding a point within `r` of the segment `ab` (once), a
    /// column at a time: in each, the rows the segment spans over the
    /// column's width (± r), and r more: cells of its box
    /// ([`Self::reach_of`]). Where the segment is steeper than a cell
    /// across, the rows of its whole height (its height over a column
    /// computed is then rounded by as much as its slope times the
    /// coordinates' last bit).
    #[inline]
    fn walk(&self, a: Point, b: Point, r: f64, mut f: impl FnMut(usize)) {
        let Reach {
            r,
            xa,
            xb,
            ya,
            yb,
            i0,
            i1,
            j0,
            j1,
        } = self.reach_of(a, b, r);
        if i0 == i1 || xb - xa < self.step {
            for i in i0..=i1 {
                for j in j0..=j1 {
                    f(j * self.nx + i);
                }
            }
            return;
        }
        let slope = (b.y - a.y) / (b.x - a.x);
        let y = |x: f64| a.y + (x - a.x) * slope;
        for i in i0..=i1 {
            let cx = self.x0 + i as f64 * self.step;
            let (u, v) = (fmax(cx - r, xa), fmin(cx + self.step + r, xb));
            let (p, q) = (y(u), y(v));
            let (lo, hi) = (fmax(fmin(p, q), ya), fmin(fmax(p, q), yb));
            for j in self.row(lo - r).max(j0)..=self.row(hi + r).min(j1) {
                f(j * self.nx + i);
            }
        }
    }
}

/// A segment's box ± a reach ([`Cells::reach_of`]).
struct Reach {
    r: f64,
    xa: f64,
    xb: f64,
    ya: f64,
    yb: f64,
    i0: usize,
    i1: usize,
    j0: usize,
    j1: usize,
}

/// How many rings of cells round each cell of an `nx` × `ny` grid hold
/// no `near` cell (its distance to the nearest, in cells either way: two
/// passes over the grid), at most 255; cells beyond the grid are not near.
fn clear_rings(near: &[bool], nx: usize, ny: usize) -> Vec<u8> {
    const FAR: u16 = 255;
    let mut d: Vec<u16> = near.iter().map(|&n| if n { 0 } else { FAR }).collect();
    let at = |i: usize, j: usize| j * nx + i;
    for j in 0..ny {
        for i in 0..nx {
            let mut m = d[at(i, j)];
            if i > 0 {
                m = m.min(d[at(i - 1, j)] + 1);
            }
            if j > 0 {
                m = m.min(d[at(i, j - 1)] + 1);
                if i > 0 {
                    m = m.min(d[at(i - 1, j - 1)] + 1);
                }
                if i + 1 < nx {
                    m = m.min(d[at(i + 1, j - 1)] + 1);
                }
            }
            d[at(i, j)] = m;
        }
    }
    for j in (0..ny).rev() {
        for i in (0..nx).rev() {
            let mut m = d[at(i, j)];
            if i + 1 < nx {
                m = m.min(d[at(i + 1, j)] + 1);
            }
            if j + 1 < ny {
                m = m.min(d[at(i, j + 1)] + 1);
                if i + 1 < nx {
                    m = m.min(d[at(i + 1, j + 1)] + 1);
                }
                if i > 0 {
                    m = m.min(d[at(i - 1, j + 1)] + 1);
                }
            }
            d[at(i, j)] = m;
        }
    }
    d.into_iter().map(|v| v.min(FAR) as u8).collect()
}

/// The cell (column or row) of `x`, cells of 1 / `inv` from `x0`, the
/// first or last one beyond them (a truncation of what is not negative:
/// its floor).
#[inline]
fn index(x: f64, x0: f64, inv: f64, n: usize) -> usize {
    (((x - x0) * inv).max(0.0) as usize).min(n - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::collide::inside::{holds_a_point_of, holds_a_point_of_lists, strictly_inside};
    use crate::nest::collide::runs::tests::star;
    use crate::nest::collide::Shape;
    use crate::nest::shape::Polygon;

    /// A finger-jointed board on a 1 mm grid (a box panel): `teeth`
    /// fingers of random widths and depth on top of a base; two of them
    /// moved by whole millimetres interlock, touching along many edges.
    fn comb(rng: &mut impl FnMut() -> f64, teeth: usize) -> Polygon {
        let depth = 1.0 + (rng() * 4.0).floor();
        let base = 2.0 + (rng() * 6.0).floor();
        let mut top = vec![];
        let mut x = 0.0;
        for k in 0..teeth {
            let w = 1.0 + (rng() * 4.0).floor();
            let y = if k % 2 == 0 { base + depth } else { base };
            top.push(Point::new(x, y));
            top.push(Point::new(x + w, y));
            x += w;
        }
        let mut pts = vec![Point::new(0.0, 0.0), Point::new(x, 0.0)];
        pts.extend(top.into_iter().rev());
        Polygon::new(pts)
    }

    /// A rounded rectangle (CAD arcs of `k` vertices a corner), a notch
    /// in its top side.
    fn rounded(rng: &mut impl FnMut() -> f64, k: usize) -> Polygon {
        let (w, h) = (20.0 + 60.0 * rng(), 10.0 + 40.0 * rng());
        let r = 2.0 + 5.0 * rng();
        let mut pts = vec![];
        for (c, a0) in [
            (Point::new(w - r, r), -90.0f64),
            (Point::new(w - r, h - r), 0.0),
            (Point::new(r, h - r), 90.0),
            (Point::new(r, r), 180.0),
        ] {
            for i in 0..=k {
                let a = (a0 + 90.0 * i as f64 / k as f64).to_radians();
                pts.push(Point::new(c.x + r * a.cos(), c.y + r * a.sin()));
            }
            if a0 == 0.0 {
                // The notch, between the upper corners.
                let (x0, x1) = (w * 0.4, w * 0.6);
                pts.extend([
                    Point::new(x1, h),
                    Point::new(x1, h * 0.6),
                    Point::new(x0, h * 0.6),
                    Point::new(x0, h),
                ]);
            }
        }
        Polygon::new(pts)
    }

    fn shape_of(rng: &mut impl FnMut() -> f64, many: bool) -> Polygon {
        let pick = rng();
        if !many && pick < 0.3 {
            // A rectangle on the grid.
            let (w, h) = ((1.0 + rng() * 12.0).floor(), (1.0 + rng() * 12.0).floor());
            return Polygon::new(vec![
                Point::new(0.0, 0.0),
                Point::new(w, 0.0),
                Point::new(w, h),
                Point::new(0.0, h),
            ]);
        }
        // (Many: more than CELLS_FROM vertices, those that keep cells.)
        let n = if many { CELLS_FROM + 1 } else { 5 };
        let (kind, size, r) = (rng(), rng(), 5.0 + 30.0 * rng());
        match (kind * 3.0) as usize {
            0 => star(rng, n + (size * 300.0) as usize, r, Point::default()),
            1 => comb(rng, n / 2 + (size * 60.0) as usize),
            _ => rounded(rng, n / 4 + (size * 40.0) as usize),
        }
    }

    /// The cells' answers (pieces in cells all outside or inside, the cuts
    /// from the cells crossed, the edges asked where they are) against
    /// the lists of the edges and vertices near, on pairs moved vertex
    /// onto vertex, by whole millimetres (interlocking fingers, plates
    /// side by side), exactly onto each other and anywhere near; each
    /// shape moved in steps from where it was made (the rounding of the
    /// separator's moves), at tolerances from none to past the cells'
    /// margin (where the lists answer).
    #[test]
    fn the_cells_answer_as_the_lists() {
        let mut rng = crate::test_rng::unit(4401);
        let (mut held, mut clear, mut by_cells) = (0, 0, 0);
        for case in 0..6000 {
            let a0 = shape_of(&mut rng, true);
            let many = rng() < 0.7;
            let b0 = shape_of(&mut rng, many);
            let u = Point::new(800.0 * rng() - 100.0, 400.0 * rng());
            let half = Point::new(u.x * 0.3, -u.y * 0.7);
            // (Cells made on first use, by a moved copy, where the shape
            // was made, and shared by the copies.)
            let made = Shape::new(a0.clone());
            let lazy = made.cells.clone().expect("many vertices");
            assert!(!lazy.made());
            let a = made.moved(half).moved(u.sub(half));
            let (na, nb) = (a.poly.pts.len(), b0.pts.len());
            let t = match case % 5 {
                0 => a.poly.pts[(rng() * na as f64) as usize]
                    .sub(b0.pts[(rng() * nb as f64) as usize]),
                1 => u.add(Point::new(
                    (rng() * 80.0 - 40.0).round(),
                    (rng() * 40.0 - 20.0).round(),
                )),
                // The same outline on it, or beside it along the grid.
                2 if rng() < 0.5 => u,
                _ => {
                    let c = a.bbox().centre().sub(b0.bbox.centre());
                    c.add(Point::new(60.0 * (rng() - 0.5), 60.0 * (rng() - 0.5)))
                }
            };
            let b0 = if case % 5 == 2 && t == u {
                a0.clone()
            } else {
                b0
            };
            let h = Point::new(t.x * 0.5, t.y * 0.25);
            let b = Shape::new(b0).moved(h).moved(t.sub(h));
            for eps in [0.0, 1e-9, 1e-6, 1e-3, 0.05, 0.5, 3.0] {
                for (o, f) in [(&a, &b), (&b, &a)] {
                    let got = holds_a_point_of(o, f, eps);
                    let want = holds_a_point_of_lists(o, f, eps);
                    assert_eq!(got, want, "case {case} eps {eps}");
                    if let Some(c) = o.cells() {
                        by_cells += c.reach(eps, o.core_at, 1e3).is_some() as usize;
                    }
                    held += got as usize;
                    clear += !got as usize;
                }
            }
            assert!(lazy.made() && made.cells().is_some());
            assert!(std::ptr::eq(made.cells().unwrap(), a.cells().unwrap()));
        }
        // Both answers came often, mostly from the cells.
        assert!(
            held > 5000 && clear > 20_000 && by_cells > 50_000,
            "{held} {clear} {by_cells}"
        );
    }

    /// A cell marked outside or inside is so by more than a quarter of a
    /// cell (every point of it), and every vertex is in its cell's list.
    #[test]
    fn the_marks_hold_for_every_point_of_a_cell() {
        let mut rng = crate::test_rng::unit(4402);
        let (mut ins, mut outs) = (0, 0);
        for _ in 0..60 {
            let p = shape_of(&mut rng, true);
            let cells = Cells::of(&p.pts).expect("a box");
            for (k, v) in p.pts.iter().enumerate() {
                let c = cells.row(v.y) * cells.nx + cells.col(v.x);
                assert!(cells.vertices(c).contains(&(k as u32)));
                assert_eq!(cells.marks[c], Mark::Near);
            }
            let quarter = cells.step / 4.0 * 0.999;
            for _ in 0..400 {
                let (i, j) = (
                    (rng() * cells.nx as f64) as usize,
                    (rng() * cells.ny as f64) as usize,
                );
                let q = Point::new(
                    cells.x0 + (i as f64 + rng()) * cells.step,
                    cells.y0 + (j as f64 + rng()) * cells.step,
                );
                match cells.marks[j * cells.nx + i] {
                    Mark::In => {
                        assert!(strictly_inside(&p, q, quarter), "{q:?}");
                        ins += 1;
                    }
                    Mark::Out => {
                        assert!(!strictly_inside(&p, q, 0.0), "{q:?}");
                        let near = (0..p.pts.len()).any(|e| {
                            let (a, b) = crate::nest::collide::runs::edge(&p.pts, e);
                            crate::nest::collide::seg_dist2(q, a, b) <= quarter * quarter
                        });
                        assert!(!near, "{q:?}");
                        outs += 1;
                    }
                    Mark::Near => {}
                }
            }
        }
        assert!(ins > 1000 && outs > 1000, "{ins} {outs}");
    }
}
