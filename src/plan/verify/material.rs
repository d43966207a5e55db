//! Part material as a point test: the even-odd rule over the drawn closed
//! contours whose box holds the point, found through a grid of boxes; a
//! contour of many segments (a flattened spline, a traced outline) tests
//! only the segments of its own horizontal band that the point's height
//! meets.
//!
//! A point is in a part when a ray to its right crosses the drawn closed
//! contours an odd number of times. A closed contour whose box does not
//! hold the point adds an even number (none, or the whole loop), so only
//! the contours around the point are tested. (The segments were filed by
//! horizontal bands across the whole sheet before: every test walked its
//! band to the sheet's edge, and a plan cut on the drawn lines asked it
//! millions of times — issue 17, sheet scale.)

use crate::cell_lists::CellLists;
use crate::contour::{point_in_loop, Contour};
use crate::geom::{BBox, Point};

/// Most grid cells one contour is filed under; bigger ones are always tested.
const MAX_CELLS: usize = 1024;
/// Contours of more segments than this are tested band by band.
const BANDED: usize = 32;

/// A big contour's segments by horizontal bands of its box: each band's
/// segments (index, lowest and highest y).
struct Bands {
    y0: f64,
    height: f64,
    bands: Vec<Vec<(u32, f64, f64)>>,
}

impl Bands {
    fn new(c: &Contour) -> Bands {
        let n = c.segments.len();
        let nb = ((n as f64).sqrt().ceil() as usize).max(1);
        let y0 = c.bbox.min.y;
        let height = ((c.bbox.max.y - y0) / nb as f64).max(1e-9);
        let mut bands = vec![Vec::new(); nb];
        for (i, s) in c.segments.iter().enumerate() {
            let b = s.bbox();
            let band = |y: f64| (((y - y0) / height).max(0.0) as usize).min(nb - 1);
            // Grown by far less than any tolerance: never misses a crossing.
            let m = 1e-9 * (1.0 + b.max.x.abs().max(b.max.y.abs()));
            let (lo, hi) = (b.min.y - m, b.max.y + m);
            if !(lo.is_finite() && hi.is_finite()) {
                continue;
            }
            for list in &mut bands[band(lo)..=band(hi)] {
                list.push((i as u32, lo, hi));
            }
        }
        Bands { y0, height, bands }
    }

    /// The parity of the crossings of `c`'s segments (these bands') by the
    /// ray from `p` to +x.
    fn parity(&self, c: &Contour, p: Point) -> bool {
        let k = (p.y - self.y0) / self.height;
        if !(k >= 0.0 && (k as usize) < self.bands.len()) {
            return false;
        }
        let mut inside = false;
        for &(i, lo, hi) in &self.bands[k as usize] {
            if p.y >= lo
                && p.y <= hi
                && point_in_loop(p, std::slice::from_ref(&c.segments[i as usize]))
            {
                inside = !inside;
            }
        }
        inside
    }
}

/// The closed contours filed by the grid cells their boxes meet.
pub(super) struct Material<'a> {
    loops: Vec<&'a Contour>,
    /// The bands of each loop of more than [`BANDED`] segments.
    banded: Vec<Option<Bands>>,
    min: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// Each cell's contours (indices into `loops`).
    lists: CellLists,
    /// Contours over more than [`MAX_CELLS`] cells: tested for every point.
    big: Vec<u32>,
}

impl<'a> Material<'a> {
    pub(super) fn new(contours: &'a crate::contour::Contours) -> Material<'a> {
        let loops: Vec<&Contour> = contours
            .contours
            .iter()
            .filter(|c| c.is_closed() && !c.bbox.is_empty())
            .collect();
        let mut ext = BBox::EMPTY;
        for c in &loops {
            ext.union(&c.bbox);
        }
        let finite = ext.min.is_finite() && ext.max.is_finite();
        let (w, h) = if finite && !ext.is_empty() {
            (ext.max.x - ext.min.x, ext.max.y - ext.min.y)
        } else {
            (0.0, 0.0)
        };
        // About one contour a cell, at most 2048 cells an axis.
        let cell = ((w * h) / loops.len().max(1) as f64)
            .sqrt()
            .max(w.max(h) / 2048.0)
            .max(1e-6);
        let (nx, ny) = ((w / cell) as usize + 1, (h / cell) as usize + 1);
        let banded = loops
            .iter()
            .map(|c| (c.segments.len() > BANDED).then(|| Bands::new(c)))
            .collect();
        let mut m = Material {
            loops,
            banded,
            min: if finite { ext.min } else { Point::default() },
            cell,
            nx,
            ny,
            lists: CellLists::default(),
            big: Vec::new(),
        };
        let ranges: Vec<Option<(usize, usize, usize, usize)>> = m
            .loops
            .iter()
            .map(|c| {
                let (x0, y0) = m.cell_of(c.bbox.min)?;
                let (x1, y1) = m.cell_of(c.bbox.max)?;
                ((x1 - x0 + 1) * (y1 - y0 + 1) <= MAX_CELLS).then_some((x0, y0, x1, y1))
            })
            .collect();
        for (i, r) in ranges.iter().enumerate() {
            if r.is_none() {
                m.big.push(i as u32);
            }
        }
        m.lists = CellLists::build(nx * ny, |f| {
            for (i, r) in ranges.iter().enumerate() {
                if let Some((x0, y0, x1, y1)) = r {
                    for y in *y0..=*y1 {
                        for x in *x0..=*x1 {
                            f.push(y * nx + x, i as u32);
                        }
                    }
                }
            }
        });
        m
    }

    /// The cell of `p`, clamped to the grid; None for a non-finite point.
    fn cell_of(&self, p: Point) -> Option<(usize, usize)> {
        if !p.is_finite() {
            return None;
        }
        let f = |v: f64, n: usize| ((v / self.cell).max(0.0) as usize).min(n - 1);
        Some((f(p.x - self.min.x, self.nx), f(p.y - self.min.y, self.ny)))
    }

    /// True when `p` lies in a part's material.
    pub(super) fn contains(&self, p: Point) -> bool {
        self.around(p).0
    }

    /// The part whose material holds `p` (that of the innermost closed
    /// contour round it), None off the parts.
    pub(super) fn part_at(&self, p: Point) -> Option<usize> {
        match self.around(p) {
            (true, Some(c)) => c.part,
            _ => None,
        }
    }

    /// Whether `p` lies in part material (the even-odd rule over the
    /// closed contours), and the smallest closed contour round it.
    fn around(&self, p: Point) -> (bool, Option<&'a Contour>) {
        // Nudged off chords and vertices, as `Scrap::in_material`.
        let p = Point::new(p.x + 0.754_877_666e-7, p.y + 0.569_840_291e-7);
        let Some((x, y)) = self.cell_of(p) else {
            return (false, None);
        };
        let c = y * self.nx + x;
        let here = self.lists.get(c);
        let mut inside = false;
        let mut inner: Option<&Contour> = None;
        for &i in here.iter().chain(&self.big) {
            let k = self.loops[i as usize];
            // A box grown by far less than any tolerance: a point on its
            // edge still tests the contour.
            if !k.bbox.overlaps(&BBox::at(p), 1e-9) {
                continue;
            }
            let odd = match &self.banded[i as usize] {
                Some(b) => b.parity(k, p),
                None => point_in_loop(p, &k.segments),
            };
            if odd {
                inside = !inside;
                if inner.is_none_or(|c| k.area.abs() < c.area.abs()) {
                    inner = Some(k);
                }
            }
        }
        (inside, inner)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::point_in_loop;
    use crate::geom::Segment;

    /// Every segment of every closed contour, with the heights it spans
    /// (grown by a micron: only segments that cannot meet the ray are passed over).
    fn every_segment(contours: &crate::contour::Contours) -> Vec<(f64, f64, &Segment)> {
        contours
            .contours
            .iter()
            .filter(|c| c.is_closed())
            .flat_map(|c| c.segments.iter())
            .map(|s| {
                let b = s.bbox();
                (b.min.y - 1e-6, b.max.y + 1e-6, s)
            })
            .collect()
    }

    /// The even-odd rule over every segment of every closed contour (what
    /// the band scan computed): the reference.
    fn by_every_segment(segments: &[(f64, f64, &Segment)], p: Point) -> bool {
        let p = Point::new(p.x + 0.754_877_666e-7, p.y + 0.569_840_291e-7);
        segments
            .iter()
            .filter(|&&(lo, hi, s)| {
                lo <= p.y && p.y <= hi && point_in_loop(p, std::slice::from_ref(s))
            })
            .count()
            % 2
            == 1
    }

    #[test]
    fn the_same_material_as_every_segment_on_real_drawings() {
        let mut f = crate::test_rng::unit(0x2545_F491_4F6C_DD1Du64);
        let mut tested = 0;
        for (path, out) in super::super::corpus::runs() {
            let m = Material::new(&out.contours);
            let segments = every_segment(&out.contours);
            let mut ext = BBox::EMPTY;
            for c in &out.contours.contours {
                ext.union(&c.bbox);
            }
            if ext.is_empty() {
                continue;
            }
            // Random points over the drawing and a margin, and every
            // vertex (on the drawn lines).
            let (w, h) = (ext.max.x - ext.min.x, ext.max.y - ext.min.y);
            let mut points: Vec<Point> = (0..400)
                .map(|_| {
                    Point::new(
                        ext.min.x - 0.1 * w + 1.2 * w * f(),
                        ext.min.y - 0.1 * h + 1.2 * h * f(),
                    )
                })
                .collect();
            points.extend(
                out.contours
                    .contours
                    .iter()
                    .flat_map(|c| c.segments.iter().map(|s| s.a))
                    .take(400),
            );
            for p in points {
                assert_eq!(
                    m.contains(p),
                    by_every_segment(&segments, p),
                    "{} at {p:?}",
                    path.display()
                );
                tested += 1;
            }
        }
        assert!(tested > 1000);
    }
}
