//! The raster the overcut area is counted on ([`super::verify`]): the
//! cells of part material a kerf disc covers, each with the depth of the
//! deepest disc that covered it, in a map (a clean plan stamps nothing).
//!
//! Bounded (issue 17, sheet scale): a plan cut on the drawn lines stamps
//! a band of kerf along every cut, 4.7M cells of r/4 on the 0.2 MB nest
//! (800 MB and 23 s). Past [`CELLS_MAX`] cells the raster is coarsened —
//! cells twice the size, the depths merged by the deepest — until it
//! holds at most half that, and counting goes on at the new size, every
//! cell the disc reaches counted (it is taken at least as wide as a
//! cell's half-diagonal): the area of a plan that overcuts everywhere is
//! then an upper bound counted on coarser cells (the warning says so and
//! how coarse), a clean plan's never. The depths are still sampled at the
//! first cell size.

use super::material::Material;
use crate::fx::FxMap;
use crate::geom::Point;

/// Most cells the raster holds (~40 MB of map).
pub(super) const CELLS_MAX: usize = 1 << 20;

pub(super) struct Raster {
    /// Cell side, mm.
    pub cell: f64,
    /// The side the raster started with, mm.
    pub first: f64,
    /// Cells stamped: whether part material, the deepest disc's depth.
    cells: FxMap<(i64, i64), (bool, f64)>,
    max: usize,
}

impl Raster {
    /// An empty raster of `cell` mm cells holding at most `max`.
    pub(super) fn new(cell: f64, max: usize) -> Raster {
        Raster {
            cell,
            first: cell,
            cells: FxMap::default(),
            max: max.max(16),
        }
    }

    fn key(&self, v: f64) -> i64 {
        (v / self.cell).floor().clamp(-1e12, 1e12) as i64
    }

    fn centre(&self, i: i64, j: i64) -> Point {
        Point::new((i as f64 + 0.5) * self.cell, (j as f64 + 0.5) * self.cell)
    }

    /// Stamps the disc of radius `r` at `p`, `depth` deep: the cells whose
    /// centre it covers, column by column (the column's chord of the
    /// disc). On a coarsened raster the disc is taken at least as wide as
    /// a cell's half-diagonal, so it always stamps the cell it is in.
    pub(super) fn stamp(&mut self, p: Point, r: f64, depth: f64, material: &Material) {
        let r = if self.cell > self.first {
            r.max(self.cell * std::f64::consts::FRAC_1_SQRT_2)
        } else {
            r
        };
        let cell = self.cell;
        for i in self.key(p.x - r)..=self.key(p.x + r) {
            let dx = (i as f64 + 0.5) * cell - p.x;
            let half = r * r - dx * dx;
            if half < 0.0 {
                continue;
            }
            let half = half.sqrt();
            let lo = ((p.y - half) / cell - 0.5).ceil() as i64;
            let hi = ((p.y + half) / cell - 0.5).floor() as i64;
            for j in lo..=hi {
                self.take(i, j, depth, material);
            }
        }
        if self.cells.len() > self.max {
            self.coarsen(material);
        }
    }

    /// Cell `(i, j)` taken `depth` deep: the deepest that took it kept,
    /// whether it is part material tested once, at its centre.
    fn take(&mut self, i: i64, j: i64, depth: f64, material: &Material) {
        let c = self.centre(i, j);
        let m = self
            .cells
            .entry((i, j))
            .or_insert_with(|| (material.contains(c), 0.0));
        m.1 = m.1.max(depth);
    }

    /// Doubles the cell side until at most half [`Raster::max`] cells are
    /// left: four cells become one, as deep as the deepest, part material
    /// if its centre is.
    fn coarsen(&mut self, material: &Material) {
        while self.cells.len() > self.max / 2 {
            self.cell *= 2.0;
            let old = std::mem::take(&mut self.cells);
            for ((i, j), (_, d)) in old {
                self.take(i.div_euclid(2), j.div_euclid(2), d, material);
            }
        }
    }

    /// The cells of part material: centre and depth, in raster order.
    pub(super) fn material_cells(mut self) -> Vec<(Point, f64)> {
        let mut cells: Vec<((i64, i64), f64)> = std::mem::take(&mut self.cells)
            .into_iter()
            .filter(|(_, (m, _))| *m)
            .map(|(k, (_, d))| (k, d))
            .collect();
        crate::sort::sort_cells(&mut cells);
        cells
            .into_iter()
            .map(|((i, j), d)| (self.centre(i, j), d))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2,000 x 1,000 mm plate: part material everywhere it is stamped.
    fn plate() -> crate::contour::Contours {
        let sq = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n2000\n20\n0\n10\n2000\n20\n1000\n10\n0\n20\n1000\n";
        let dxf = format!("0\nSECTION\n2\nENTITIES\n{sq}0\nENDSEC\n0\nEOF\n");
        let s = crate::Settings::new(1.0, 0.001, 1000.0).unwrap();
        crate::run(dxf.as_bytes(), &s).unwrap().contours
    }

    /// A band 2r wide and 1,000 mm long stamped by discs of radius `r`
    /// every 0.1 mm, the 101st 3 mm deep (before any coarsening), on
    /// 0.5 mm cells, at most `max` of them: the final cell side and the
    /// material cells.
    fn band(contours: &crate::contour::Contours, r: f64, max: usize) -> (f64, Vec<(Point, f64)>) {
        let m = Material::new(contours);
        let mut raster = Raster::new(0.5, max);
        for k in 0..=10_000 {
            let depth = if k == 100 { 3.0 } else { 1.0 };
            raster.stamp(Point::new(500.0 + k as f64 * 0.1, 500.0), r, depth, &m);
        }
        (raster.cell, raster.material_cells())
    }

    #[test]
    fn a_band_counts_its_area_and_a_bounded_raster_coarsens() {
        let contours = plate();
        let (fine, cells) = band(&contours, 2.0, CELLS_MAX);
        assert_eq!(fine, 0.5);
        let area = cells.len() as f64 * 0.25;
        assert!((area - 4000.0).abs() < 0.03 * 4000.0, "{area}");
        assert!(cells.iter().any(|c| c.1 == 3.0));
        // At most 2,000 cells: coarsened (4 mm).
        let (coarse, cells) = band(&contours, 2.0, 2000);
        assert!(coarse > 0.5);
        assert!(cells.len() <= 2000, "{}", cells.len());
        let area = cells.len() as f64 * coarse * coarse;
        assert!(
            (4000.0..2.5 * 4000.0).contains(&area),
            "{area} on {coarse} mm cells"
        );
        // The deepest disc survives the merges, where it was (x = 510).
        let deep: Vec<_> = cells.iter().filter(|c| c.1 == 3.0).collect();
        assert!(!deep.is_empty() && deep.iter().all(|c| (c.0.x - 510.0).abs() < 2.0 * coarse));
        // A thin band (1,000 mm²) on cells wider than the disc: each
        // disc still counts the cell it is in.
        let (coarse, cells) = band(&contours, 0.5, 300);
        assert!(coarse > 1.0, "{coarse}");
        let area = cells.len() as f64 * coarse * coarse;
        assert!(area >= 1000.0, "{area} on {coarse} mm cells");
    }

    #[test]
    fn coarsening_keeps_the_deepest_of_the_cells_it_merges() {
        let contours = plate();
        let m = Material::new(&contours);
        let mut r = Raster::new(1.0, 16);
        let depth = |i: i64, j: i64| ((i * 7 + j * 3) % 10) as f64;
        for i in 0..8 {
            for j in 0..8 {
                r.cells.insert((i + 100, j + 100), (true, depth(i, j)));
            }
        }
        r.coarsen(&m);
        // 64 cells of 1 mm, at most 8 left: 4 of 4 mm.
        assert_eq!(r.cell, 4.0);
        assert_eq!(r.cells.len(), 4);
        for ((bi, bj), (_, d)) in &r.cells {
            let want = (0..8)
                .flat_map(|i| (0..8).map(move |j| (i, j)))
                .filter(|&(i, j)| (i + 100) / 4 == *bi && (j + 100) / 4 == *bj)
                .map(|(i, j)| depth(i, j))
                .fold(0.0, f64::max);
            assert_eq!(*d, want, "cell {bi}, {bj}");
        }
    }
}
