//! Where a label's box goes inside one part, in the part's own drawing
//! coordinates (so every copy of a part shares one search): the box
//! upright or across, as high as fits between `max` and `min`, at the
//! candidate centre that leaves it most room.
//!
//! The part is flattened into polygons (chords within `chord`, which is
//! added to the margin: a chord lies inside its arc, so the true outline
//! is at most `chord` nearer). Candidate centres are a grid over the
//! part's box, kept where they lie in the material, taken in order of
//! their distance to the outline (the pole of inaccessibility first:
//! Garcia-Castellanos & Lombardo 2007 search the same quantity on a grid).
//! A box fits at a centre when the centre lies in the material and no
//! edge of the outline or of a hole comes nearer the box than the margin.
//! A box that fits at some height fits at every smaller one (the smaller
//! box lies inside the larger at the same centre), so the height is
//! found by bisection.

use crate::geom::{dist_to_segment, Point, Segment};

/// Most candidate centres on one part.
const MAX_CANDIDATES: usize = 4096;
/// Bisection steps on the height (the last step is (max − min) / 2^12).
const BISECTIONS: usize = 12;

/// A part flattened into edges, with its candidate centres.
#[derive(Clone, Debug)]
pub struct Region {
    /// Every edge of the outline and of the holes.
    edges: Vec<(Point, Point)>,
    /// Centres in the material and their distance to the nearest edge,
    /// farthest first.
    candidates: Vec<(Point, f64)>,
}

/// A label's box in the part's coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// Its centre.
    pub centre: Point,
    /// True when it reads along the part's y axis (turned 90°).
    pub across: bool,
    /// The text's height, mm.
    pub height: f64,
}

/// Crossing-number test of `p` against closed polygon `poly`.
fn inside(poly: &[Point], p: Point) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            c = !c;
        }
    }
    c
}

impl Region {
    /// `outer` and `holes` flattened within `chord`, with candidate centres.
    pub fn new(outer: &[Segment], holes: &[Vec<Segment>], chord: f64) -> Region {
        let mut polys = Vec::with_capacity(holes.len() + 1);
        for l in std::iter::once(outer).chain(holes.iter().map(|h| &h[..])) {
            let mut p = Vec::new();
            crate::geom::path_points(l, chord, &mut p);
            polys.push(p);
        }
        let mut edges = Vec::new();
        let (mut lo, mut hi) = (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for p in &polys {
            for i in 0..p.len() {
                edges.push((p[i], p[(i + 1) % p.len()]));
            }
        }
        for q in &polys[0] {
            lo = Point::new(lo.x.min(q.x), lo.y.min(q.y));
            hi = Point::new(hi.x.max(q.x), hi.y.max(q.y));
        }
        let mut candidates = Vec::new();
        let (w, h) = (hi.x - lo.x, hi.y - lo.y);
        if polys[0].len() >= 3 && w.is_finite() && h.is_finite() && w > 0.0 && h > 0.0 {
            // At least 12 rows across the narrow side, 40 along the long.
            let mut step = (w.max(h) / 40.0).min(w.min(h) / 12.0);
            let count = |step: f64| ((w / step).ceil() + 1.0) * ((h / step).ceil() + 1.0);
            if count(step) > MAX_CANDIDATES as f64 {
                step *= (count(step) / MAX_CANDIDATES as f64).sqrt();
            }
            let (nx, ny) = ((w / step).ceil() as usize, (h / step).ceil() as usize);
            let (sx, sy) = (w / nx.max(1) as f64, h / ny.max(1) as f64);
            for i in 0..=nx {
                for j in 0..=ny {
                    let p = Point::new(lo.x + i as f64 * sx, lo.y + j as f64 * sy);
                    if inside(&polys[0], p) && !polys[1..].iter().any(|h| inside(h, p)) {
                        let d = edges
                            .iter()
                            .map(|&(a, b)| dist_to_segment(p, &Segment::line(a, b)))
                            .fold(f64::INFINITY, f64::min);
                        candidates.push((p, d));
                    }
                }
            }
        }
        candidates.sort_by(|a, b| b.1.total_cmp(&a.1));
        Region { edges, candidates }
    }

    /// The nearest an edge comes to the axis-aligned box at `c` with half
    /// sizes `hw`, `hh` (0 when one touches or crosses it), or some
    /// distance under `enough` as soon as one edge comes nearer than it.
    fn box_clearance(&self, c: Point, hw: f64, hh: f64, enough: f64) -> f64 {
        let mut least = f64::INFINITY;
        for &(a, b) in &self.edges {
            least = least.min(edge_box(a.sub(c), b.sub(c), hw, hh));
            if least < enough {
                break;
            }
        }
        least
    }

    /// The best centre for a box `hw` × `hh` (half sizes) clear of every
    /// edge by `margin`: the most clearance among the first `look` that
    /// fit (1: the first found). None when none fits.
    fn place(&self, hw: f64, hh: f64, margin: f64, look: usize) -> Option<(Point, f64)> {
        // A box holds the disc of its smaller half size about its centre.
        let need = margin + hw.min(hh);
        let mut best: Option<(Point, f64)> = None;
        let mut found = 0;
        for &(p, d) in self.candidates.iter().take_while(|c| c.1 >= need) {
            if best.is_some_and(|(_, b)| d - hw.min(hh) <= b) {
                // Its box is no farther from the edges than its centre less
                // its smaller half size: it cannot beat the best.
                break;
            }
            let clear = self.box_clearance(p, hw, hh, margin);
            if clear >= margin {
                if best.is_none_or(|(_, b)| clear > b) {
                    best = Some((p, clear));
                }
                found += 1;
                if found >= look {
                    break;
                }
            }
        }
        best
    }

    /// The box `ratio` × height (ratio = width over height) upright or
    /// across, as high as fits in `min..=max` with `margin` to every edge.
    /// None when it fits nowhere at `min`.
    pub fn fit(&self, ratio: f64, min: f64, max: f64, margin: f64) -> Option<Fit> {
        let at = |h: f64, look: usize| -> Option<Fit> {
            let (hw, hh) = (ratio * h / 2.0, h / 2.0);
            let up = self.place(hw, hh, margin, look);
            let across = self.place(hh, hw, margin, look);
            match (up, across) {
                (Some(u), Some(a)) if a.1 > u.1 => Some((a.0, true)),
                (Some(u), _) => Some((u.0, false)),
                (None, Some(a)) => Some((a.0, true)),
                (None, None) => None,
            }
            .map(|(centre, across)| Fit {
                centre,
                across,
                height: h,
            })
        };
        if !(min > 0.0 && max >= min && ratio.is_finite()) {
            return None;
        }
        let mut best = at(min, 1)?;
        if let Some(f) = at(max, 1) {
            best = f;
        } else {
            let (mut lo, mut hi) = (min, max);
            for _ in 0..BISECTIONS {
                let mid = 0.5 * (lo + hi);
                match at(mid, 1) {
                    Some(f) => {
                        best = f;
                        lo = mid;
                    }
                    None => hi = mid,
                }
            }
        }
        // At the height found, the centre that leaves the box most room.
        Some(at(best.height, usize::MAX).unwrap_or(best))
    }
}

/// Distance from edge `a`–`b` to the box |x| ≤ `hw`, |y| ≤ `hh`.
fn edge_box(a: Point, b: Point, hw: f64, hh: f64) -> f64 {
    if clips(a, b, hw, hh) {
        return 0.0;
    }
    let to_box = |p: Point| {
        let dx = (p.x.abs() - hw).max(0.0);
        let dy = (p.y.abs() - hh).max(0.0);
        dx.hypot(dy)
    };
    let corners = [(hw, hh), (-hw, hh), (-hw, -hh), (hw, -hh)];
    let c = corners
        .iter()
        .map(|&(x, y)| dist_to_segment(Point::new(x, y), &Segment::line(a, b)))
        .fold(f64::INFINITY, f64::min);
    c.min(to_box(a)).min(to_box(b))
}

/// True when some of the edge lies in the box (Liang–Barsky clipping).
fn clips(a: Point, b: Point, hw: f64, hh: f64) -> bool {
    let d = b.sub(a);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x + hw),
        (d.x, hw - a.x),
        (-d.y, a.y + hh),
        (d.y, hh - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(w: f64, h: f64) -> Vec<Segment> {
        let p = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| Point::new(x, y));
        (0..4)
            .map(|i| Segment::line(p[i], p[(i + 1) % 4]))
            .collect()
    }

    #[test]
    fn a_box_fits_as_high_as_the_part_allows_and_turns_across_a_tall_part() {
        // 100 × 30: a 4:1 label, margin 2, is at most 26 high by the height
        // and 96/4 = 24 by the width; the grid finds nearly that.
        let r = Region::new(&rect(100.0, 30.0), &[], 0.05);
        let f = r.fit(4.0, 3.0, 40.0, 2.0).unwrap();
        assert!(!f.across);
        assert!(f.height <= 24.0 + 1e-9 && f.height > 20.0, "{f:?}");
        // The same part standing up: the label reads across it.
        let tall = Region::new(&rect(30.0, 100.0), &[], 0.05);
        let f = tall.fit(4.0, 3.0, 40.0, 2.0).unwrap();
        assert!(f.across, "{f:?}");
        // Too small for the smallest label: none.
        let tiny = Region::new(&rect(8.0, 5.0), &[], 0.05);
        assert_eq!(tiny.fit(4.0, 3.0, 10.0, 2.0), None);
    }

    #[test]
    fn edges_near_the_box_are_measured_whether_they_cross_it_or_not() {
        let p = Point::new;
        assert_eq!(edge_box(p(-5.0, 0.0), p(5.0, 0.0), 1.0, 1.0), 0.0);
        assert!((edge_box(p(-5.0, 3.0), p(5.0, 3.0), 1.0, 1.0) - 2.0).abs() < 1e-12);
        assert!((edge_box(p(3.0, 3.0), p(3.0, 9.0), 1.0, 1.0) - 8f64.sqrt()).abs() < 1e-12);
        // A diagonal edge past a corner.
        let d = edge_box(p(0.0, 4.0), p(4.0, 0.0), 1.0, 1.0);
        assert!((d - 2.0 / 2f64.sqrt()).abs() < 1e-12, "{d}");
    }
}
