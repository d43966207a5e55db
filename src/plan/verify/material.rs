//! Part material as a point test: the drawn closed contours filed by
//! horizontal bands for the even-odd rule.

use crate::contour::point_in_loop;
use crate::geom::{BBox, Point, Segment};

/// Every closed contour's segments filed by horizontal bands, for the
/// even-odd test of part material: a point is in a part when a ray to its
/// right crosses the drawn closed contours an odd number of times (the sum
/// of each contour's parity), and only the segments of its band can cross.
pub(super) struct Material<'a> {
    y0: f64,
    height: f64,
    bands: Vec<Vec<(f64, &'a Segment)>>,
}

impl<'a> Material<'a> {
    pub(super) fn new(contours: &'a crate::contour::Contours, height: f64) -> Material<'a> {
        let closed = || contours.contours.iter().filter(|c| c.is_closed());
        let mut ext = BBox::EMPTY;
        for c in closed() {
            ext.union(&c.bbox);
        }
        if ext.is_empty() {
            return Material {
                y0: 0.0,
                height: 1.0,
                bands: Vec::new(),
            };
        }
        let height = height.max((ext.max.y - ext.min.y) / 100_000.0).max(1e-6);
        let n = (((ext.max.y - ext.min.y) / height).ceil() as usize + 1).max(1);
        let mut bands: Vec<Vec<(f64, &Segment)>> = vec![Vec::new(); n];
        for c in closed() {
            for s in &c.segments {
                let b = s.bbox();
                let lo = (((b.min.y - ext.min.y) / height).floor().max(0.0) as usize).min(n - 1);
                let hi = (((b.max.y - ext.min.y) / height).floor().max(0.0) as usize).min(n - 1);
                for band in &mut bands[lo..=hi] {
                    band.push((b.max.x, s));
                }
            }
        }
        Material {
            y0: ext.min.y,
            height,
            bands,
        }
    }
    /// True when `p` lies in a part's material.
    pub(super) fn contains(&self, p: Point) -> bool {
        // Nudged off chords and vertices, as `Scrap::in_material`.
        let p = Point::new(p.x + 0.754_877_666e-7, p.y + 0.569_840_291e-7);
        let k = (p.y - self.y0) / self.height;
        if !(k >= 0.0 && (k as usize) < self.bands.len()) {
            return false;
        }
        self.bands[k as usize]
            .iter()
            .filter(|(max_x, s)| *max_x >= p.x && point_in_loop(p, std::slice::from_ref(*s)))
            .count()
            % 2
            == 1
    }
}
