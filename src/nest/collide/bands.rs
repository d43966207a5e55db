//! Edges bucketed by height, for the point-in-polygon parity of the exact
//! test on many-vertex shapes (issue 44: CAD outlines of hundreds of
//! vertices, where every point asked every edge near the other shape and
//! the touching test of two keyboard plates was most of a first nest).
//!
//! A many-vertex shape keeps the buckets of all its edges ([`Outline`]),
//! made once where the shape was made and moved with it: the buckets of
//! the edges near the other shape, made anew for every pair tested, were
//! a third of a separation of keyboard plates (perf, issue 44). The
//! parity counts the edges a horizontal line crosses left of the point,
//! in any order, so any bucket holding every edge the line may cross
//! gives the same answer.

use crate::geom::{fmax, fmin, Point};

/// The buckets of every edge of a polygon, in its coordinates where it
/// was made: a bucket holds every edge within an eighth of a bucket of
/// it, so a height asked where the polygon has moved since, rounded by
/// far less than that, still finds every edge it may cross.
#[derive(Debug)]
pub(super) struct Outline {
    bands: Bands,
    /// The heights covered, and the margin each bucket has.
    y0: f64,
    y1: f64,
    margin: f64,
}

impl Outline {
    /// Vertices from which a polygon gets them: the exact test buckets
    /// the edges near a point only past 64 of them ([`super::inside`]).
    pub const FROM: usize = 65;

    /// The buckets of the polygon of vertices `pts` (edge i from vertex i
    /// to the next, the last to the first); None under [`Self::FROM`]
    /// vertices or without height.
    pub fn of(pts: &[Point]) -> Option<Outline> {
        let n = pts.len();
        if n < Self::FROM {
            return None;
        }
        let (y0, y1) = pts
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (fmin(lo, p.y), fmax(hi, p.y))
            });
        if y1.partial_cmp(&y0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let edges: Vec<(Point, Point)> = (0..n).map(|i| super::runs::edge(pts, i)).collect();
        let margin = (y1 - y0) / (n / Bands::PER).clamp(1, 4096) as f64 / 8.0;
        Some(Outline {
            bands: Bands::with_margin(&edges, y0, y1, margin),
            y0,
            y1,
            margin,
        })
    }

    /// The edges (indices) a horizontal line at `y` may cross, the
    /// polygon moved by `at` since; None when `y` is outside its heights
    /// or so far from the origin that rounding could pass the margin
    /// (a billionth of the coordinates: ask every edge then).
    pub fn at(&self, y: f64, at: Point) -> Option<&[u32]> {
        let slack = 1e-9 * (y.abs() + at.y.abs() + self.y0.abs() + self.y1.abs());
        if slack.partial_cmp(&self.margin) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        self.bands.at(y - at.y)
    }
}

#[derive(Debug)]
/// The edges a horizontal line at `y` may meet are those of `y`'s bucket
/// (every edge whose closed y range meets the bucket is in it).
pub(super) struct Bands {
    y0: f64,
    step: f64,
    /// Bucket k's edges: `index[start[k]..start[k + 1]]`.
    start: Vec<u32>,
    index: Vec<u32>,
}

impl Bands {
    /// Edges per bucket aimed at.
    const PER: usize = 4;

    /// The buckets of `edges` over heights `y0..=y1`.
    pub fn new(edges: &[(Point, Point)], y0: f64, y1: f64) -> Bands {
        Bands::with_margin(edges, y0, y1, 0.0)
    }

    /// [`Bands::new`], every edge also in the buckets within `margin` of
    /// its heights.
    fn with_margin(edges: &[(Point, Point)], y0: f64, y1: f64, margin: f64) -> Bands {
        let n = (edges.len() / Self::PER).clamp(1, 4096);
        let step = ((y1 - y0) / n as f64).max(f64::MIN_POSITIVE);
        let span = |e: &(Point, Point)| {
            let (lo, hi) = (fmin(e.0.y, e.1.y) - margin, fmax(e.0.y, e.1.y) + margin);
            let k = |y: f64| (((y - y0) / step).floor().max(0.0) as usize).min(n - 1);
            k(lo)..=k(hi)
        };
        let mut start = vec![0u32; n + 1];
        for e in edges {
            for k in span(e) {
                start[k + 1] += 1;
            }
        }
        for k in 0..n {
            start[k + 1] += start[k];
        }
        let mut fill = start.clone();
        let mut index = vec![0u32; start[n] as usize];
        for (i, e) in edges.iter().enumerate() {
            for k in span(e) {
                index[fill[k] as usize] = i as u32;
                fill[k] += 1;
            }
        }
        Bands {
            y0,
            step,
            start,
            index,
        }
    }

    /// The edges (indices) a horizontal line at `y` may meet; None when
    /// `y` is outside the heights covered (ask every edge then).
    pub fn at(&self, y: f64) -> Option<&[u32]> {
        let n = self.start.len() - 1;
        let f = (y - self.y0) / self.step;
        if !(f >= 0.0 && f < n as f64) {
            return None;
        }
        let k = (f.floor() as usize).min(n - 1);
        Some(&self.index[self.start[k] as usize..self.start[k + 1] as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_height_s_bucket_holds_every_edge_spanning_it() {
        let mut unit = crate::test_rng::unit(7);
        let mut r = || unit() * 10.0;
        let e: Vec<(Point, Point)> = (0..300)
            .map(|_| {
                let p = Point::new(r(), r());
                (p, Point::new(p.x + r() / 5.0 - 1.0, p.y + r() / 5.0 - 1.0))
            })
            .collect();
        let (y0, y1) = (-1.0, 11.0);
        let bands = Bands::new(&e, y0, y1);
        for k in 0..1200 {
            let y = y0 + (y1 - y0) * k as f64 / 1200.0;
            let got = bands.at(y).expect("inside");
            for (i, (p, q)) in e.iter().enumerate() {
                if p.y.min(q.y) <= y && y <= p.y.max(q.y) {
                    assert!(got.contains(&(i as u32)), "y {y} edge {i}");
                }
            }
        }
        assert!(bands.at(y0 - 1.0).is_none() && bands.at(y1 + 1.0).is_none());
    }

    /// A polygon's own buckets, the polygon moved as the separator moves
    /// copies (several steps, rounding each time): every edge a line
    /// at a height crosses, found by walking every edge of the moved
    /// polygon, is in the bucket asked there.
    #[test]
    fn an_outline_s_bucket_holds_every_edge_a_line_crosses_where_it_moved() {
        let mut r = crate::test_rng::unit(11);
        assert!(Outline::of(&[Point::default(); Outline::FROM - 1]).is_none());
        let mut asked = 0;
        for case in 0..40 {
            // A toothed ring of 65–400 vertices about (3, −2).
            let n = Outline::FROM + (r() * 335.0) as usize;
            let pts: Vec<Point> = (0..n)
                .map(|i| {
                    let a = i as f64 / n as f64 * std::f64::consts::TAU;
                    let k = if i % 6 < 3 { 1.0 } else { 0.8 + 0.1 * r() };
                    Point::new(3.0 + 40.0 * k * a.cos(), -2.0 + 25.0 * k * a.sin())
                })
                .collect();
            let outline = Outline::of(&pts).expect("many vertices");
            let (mut moved, mut at) = (pts.clone(), Point::default());
            for _ in 0..1 + case % 5 {
                let t = Point::new(3000.0 * (r() - 0.3), 1500.0 * (r() - 0.3));
                moved.iter_mut().for_each(|p| *p = p.add(t));
                at = at.add(t);
            }
            for k in 0..400 {
                // Heights at random, on vertices, and just off them.
                let y = match k % 3 {
                    0 => moved[0].y - 30.0 + 60.0 * r(),
                    1 => moved[(r() * n as f64) as usize].y,
                    _ => moved[(r() * n as f64) as usize].y + 1e-12 * (r() - 0.5),
                };
                let Some(got) = outline.at(y, at) else {
                    continue;
                };
                asked += 1;
                for i in 0..n {
                    let (a, b) = super::super::runs::edge(&moved, i);
                    if (a.y > y) != (b.y > y) {
                        assert!(got.contains(&(i as u32)), "case {case} y {y} edge {i}");
                    }
                }
            }
        }
        assert!(asked > 10_000, "{asked}");
    }
}
