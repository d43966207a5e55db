//! Edges bucketed by height, for the point-in-polygon parity of the exact
//! test on many-vertex shapes (issue 44: CAD outlines of hundreds of
//! vertices, where every point asked every edge near the other shape and
//! the touching test of two keyboard plates was most of a first nest).

use crate::geom::Point;

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
        let n = (edges.len() / Self::PER).clamp(1, 4096);
        let step = ((y1 - y0) / n as f64).max(f64::MIN_POSITIVE);
        let span = |e: &(Point, Point)| {
            let (lo, hi) = (e.0.y.min(e.1.y), e.0.y.max(e.1.y));
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
        let mut s = 7u64;
        let mut r = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64 * 10.0
        };
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
}
