//! The swept kerf's reach into part material: each cutting move sampled at
//! most a raster cell apart, each sample's distance to the drawn contours
//! and whether it lies in a part giving how deep the kerf disc reaches
//! past a drawn edge (paper 004's swept-envelope check).
//!
//! Each move gathers once the drawn segments that may come within the
//! sample's look-up distance of it, and each of its samples measures only
//! those, nearest last time first, skipping a segment whose box is farther
//! than the nearest found. (Every sample looked its cells up in the
//! contour index and measured every segment there: 2.6 s of samples on a
//! 22k-contour sheet, issue 17.) When the nearest of them lies past the
//! look-up distance, the sample asks the index as before, so the
//! distances, and the check, are the same.

use super::material::Material;
use super::raster::{Raster, CELLS_MAX};
use crate::geom::{Along, BBox, Point, Segment, SegmentDistance};
use crate::plan::clearance::{index_box, Obstacles};
use crate::plan::{CutPlan, PlanInput, Role};

/// A move gathering more drawn segments than this (a long diagonal over
/// the sheet) asks the index at each sample instead.
const MOST_NEAR: usize = 48;

/// A drawn segment near a move: its index box and distance.
struct Near {
    bx: BBox,
    dist: SegmentDistance,
}

/// The drawn segments near one move.
struct Nearby<'o> {
    obstacles: &'o Obstacles,
    /// How far a sample looks (the index look-up's reach).
    reach: f64,
    near: Vec<Near>,
    /// False when the move gathered too many: each sample asks the index.
    gathered: bool,
    /// The one nearest the last sample.
    last: usize,
    /// The numbers of those gathered.
    taken: Vec<u32>,
}

impl<'o> Nearby<'o> {
    fn new(obstacles: &'o Obstacles, reach: f64) -> Nearby<'o> {
        Nearby {
            obstacles,
            reach,
            near: Vec::new(),
            gathered: false,
            last: 0,
            taken: Vec::new(),
        }
    }

    /// Gathers the drawn segments that may come within the reach of `s`:
    /// every one within it of a point of `s` has its index box within it
    /// of `s`'s box.
    fn gather(&mut self, s: &Segment) {
        let grown = s.bbox().grown(self.reach);
        self.near.clear();
        self.last = 0;
        self.taken.clear();
        let (obstacles, near, taken) = (self.obstacles, &mut self.near, &mut self.taken);
        self.gathered = obstacles.each_index_near(&grown, |i| {
            let seg = obstacles.segment(i);
            let bx = index_box(seg);
            if bx.overlaps(&grown, 0.0) && !taken.contains(&i) {
                if near.len() == MOST_NEAR {
                    return false;
                }
                taken.push(i);
                near.push(Near {
                    bx,
                    dist: SegmentDistance::new(seg),
                });
            }
            true
        });
    }

    /// What `Obstacles::distance(p, reach)` gives, for `p` on the move.
    fn distance(&mut self, p: Point) -> f64 {
        if !self.gathered {
            return self.obstacles.distance(p, self.reach);
        }
        let mut least = f64::INFINITY;
        if let Some(n) = self.near.get(self.last) {
            least = least.min(n.dist.to(p));
        }
        for (i, n) in self.near.iter().enumerate() {
            if i == self.last {
                continue;
            }
            // The box holds the segment: nothing of it is nearer.
            let dx = (n.bx.min.x - p.x).max(p.x - n.bx.max.x).max(0.0);
            let dy = (n.bx.min.y - p.y).max(p.y - n.bx.max.y).max(0.0);
            if dx * dx + dy * dy > least * least {
                continue;
            }
            let d = n.dist.to(p);
            if d < least {
                least = d;
                self.last = i;
            }
        }
        if least <= self.reach {
            // Every segment within the reach was measured: the least
            // distance, as the index gives it.
            least
        } else {
            self.obstacles.distance(p, self.reach)
        }
    }
}

/// What the swept kerf takes from the parts.
pub(super) struct Swept<'a> {
    /// Every cell of part material taken.
    pub(super) raster: Raster,
    /// The parts' material the raster was tested against.
    pub(super) material: Material<'a>,
    /// The deepest reach past a drawn edge, mm, and where (the first
    /// sample that deep).
    pub(super) deepest: f64,
    pub(super) deepest_at: Option<Point>,
}

/// Samples every cutting move of `plan` (not marks, spots or tabs) over the
/// parts of `input`: kerf radius `r`, cells of `cell` mm, `slack` the
/// geometry's rounding.
pub(super) fn sweep<'a>(
    input: &PlanInput<'a>,
    plan: &CutPlan,
    r: f64,
    cell: f64,
    slack: f64,
) -> Swept<'a> {
    let obstacles = Obstacles::new(input.contours, input.tolerance);
    let mut out = Swept {
        raster: Raster::new(cell, CELLS_MAX),
        material: Material::new(input.contours),
        deepest: 0.0,
        deepest_at: None,
    };
    let mut nearby = Nearby::new(&obstacles, r + cell + slack);
    for cut in plan.cuts.iter().filter(|c| !c.spot) {
        // Whether the torch is inside a part, while known: it changes only
        // where a move crosses a drawn edge (d = 0), and d changes no faster
        // than the torch moves (the same reasoning as `scrap::intrusion`).
        let mut inside: Option<bool> = None;
        let mut last_d = 0.0_f64;
        for s in cut
            .steps
            .iter()
            .filter(|s| s.role != Role::Mark && s.role != Role::Tab)
        {
            let s = &s.segment;
            let len = s.length();
            if !len.is_finite() {
                continue;
            }
            nearby.gather(s);
            let along = Along::new(s);
            // Samples at most a cell of the raster's first size apart.
            let n = ((len / cell).ceil() as usize).clamp(1, 200_000);
            for k in 0..=n {
                let p = along.at(k as f64 / n as f64);
                let d = nearby.distance(p);
                let d = if d.is_finite() { d } else { r + cell + slack };
                if last_d + d <= cell {
                    inside = None;
                }
                last_d = d;
                let depth = if r <= slack && d <= slack {
                    // No kerf, on a drawn line: takes nothing from either side.
                    0.0
                } else if *inside.get_or_insert_with(|| out.material.contains(p)) {
                    r + d
                } else {
                    (r - d).max(0.0)
                };
                if depth <= slack {
                    continue;
                }
                if depth > out.deepest {
                    out.deepest = depth;
                    out.deepest_at = Some(p);
                }
                out.raster.stamp(p, r, depth, &out.material);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On every corpus drawing: the distance a move's samples measure is
    /// the contour index's, bit for bit, along the planned cuts and along
    /// random moves across the drawing (long ones gather too many).
    #[test]
    fn the_same_distances_as_the_index_on_real_drawings() {
        let mut f = crate::test_rng::unit(0x6A09_E667_F3BC_C909u64);
        let (mut gathered, mut asked) = (0, 0);
        for (path, out) in super::super::corpus::runs() {
            let obstacles = Obstacles::new(&out.contours, 0.001);
            let reach = 0.75 + 0.1875 + 0.01;
            let mut ext = BBox::EMPTY;
            for c in &out.contours.contours {
                ext.union(&c.bbox);
            }
            let mut moves: Vec<Segment> = out
                .plan
                .cuts
                .iter()
                .flat_map(|c| c.steps.iter().map(|s| s.segment))
                .take(3000)
                .collect();
            if !ext.is_empty() {
                let (w, h) = (ext.max.x - ext.min.x, ext.max.y - ext.min.y);
                let mut at = || Point::new(ext.min.x + w * f(), ext.min.y + h * f());
                for k in 0..50 {
                    let (a, b) = (at(), at());
                    let bulge = if k % 2 == 0 { 0.0 } else { 0.5 };
                    moves.push(Segment { a, b, bulge });
                }
            }
            let mut nearby = Nearby::new(&obstacles, reach);
            for m in &moves {
                nearby.gather(m);
                if nearby.gathered {
                    gathered += 1;
                } else {
                    asked += 1;
                }
                for t in (0..=16).map(|k| k as f64 / 16.0).chain([f(), f()]) {
                    let p = m.point_at(t);
                    let (got, want) = (nearby.distance(p), obstacles.distance(p, reach));
                    assert!(
                        got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                        "{}: {got} vs {want} at {p:?} on {m:?}",
                        path.display()
                    );
                }
            }
        }
        assert!(
            gathered > 10_000 && asked > 100,
            "{gathered} gathered, {asked} asked"
        );
    }
}
