//! Containment depth of closed contours.
//!
//! Paper 000 takes the largest contour as the outer and all others as holes;
//! a sheet of many parts needs more: a contour's depth is the number of closed
//! contours that contain it. Even depth = outer boundary of a part, odd = hole.
//!
//! Containment is tested with a point of the inner contour that is not on the
//! outer one's boundary, by exact even-odd crossing with arcs: an arc's region
//! is its chord's polygon XOR its circular segment.

use super::box_grid::{BoxGrid, Lists};
use super::{Contour, ContourKind};
use crate::geom::{dist_to_segment, Point, Segment, Tolerance};
use crate::par::Threads;
use crate::text;
use crate::warning::Warning;

/// Even-odd inside test of `p` against a closed loop of lines and arcs.
pub fn point_in_loop(p: Point, segs: &[Segment]) -> bool {
    parity(p, segs)
}

/// [`point_in_loop`] over any run of the loop's segments: the parity of the
/// crossings of a ray from `p` to +x.
fn parity<'s>(p: Point, segs: impl IntoIterator<Item = &'s Segment>) -> bool {
    let mut inside = false;
    for s in segs {
        let (a, b) = (s.a, s.b);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if x > p.x {
                inside = !inside;
            }
        }
        if let Some((c, r)) = s.arc_center() {
            // Inside the circular segment between chord and arc?
            let chord = b.sub(a);
            let mid = s.point_at(0.5);
            let side_p = chord.cross(p.sub(a));
            let side_m = chord.cross(mid.sub(a));
            if p.dist(c) < r && side_p * side_m > 0.0 {
                inside = !inside;
            }
        }
    }
    inside
}

/// A contour's segments sorted into horizontal bands by their box's Y
/// range, so a point test looks only at the segments of its band: big
/// outlines (a spline flattened to 50 000 lines) are tested in O(√n).
struct Bands {
    y0: f64,
    height: f64,
    n: usize,
    index: BandIndex,
}

/// Loops of up to this many segments keep each segment's range of bands
/// inline instead of lists per band: a sheet's 70k rectangles built four
/// vectors each (issue 17).
const INLINE: usize = 8;

/// Which segments lie in which bands.
enum BandIndex {
    /// Each segment's first and last band (a short loop of `.0` segments).
    Ranges(usize, [(u32, u32); INLINE]),
    /// The segments of each band.
    Lists(Lists),
}

impl Bands {
    /// The bands of `segs`, whose box is `bb`.
    fn new(segs: &[Segment], bb: &crate::geom::BBox) -> Bands {
        let n = ((segs.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let height = ((bb.max.y - bb.min.y) / n as f64).max(1e-9);
        let range = |s: &Segment| {
            let b = s.bbox();
            (
                Self::at(bb.min.y, height, n, b.min.y),
                Self::at(bb.min.y, height, n, b.max.y),
            )
        };
        let index = if segs.len() <= INLINE {
            let mut ranges = [(0, 0); INLINE];
            for (r, s) in ranges.iter_mut().zip(segs) {
                let (lo, hi) = range(s);
                *r = (lo as u32, hi as u32);
            }
            BandIndex::Ranges(segs.len(), ranges)
        } else {
            let mut pairs = Vec::with_capacity(segs.len());
            for (k, s) in segs.iter().enumerate() {
                let (lo, hi) = range(s);
                pairs.extend((lo..=hi).map(|band| (band as u32, k as u32)));
            }
            BandIndex::Lists(Lists::new(n, &pairs))
        };
        Bands {
            y0: bb.min.y,
            height,
            n,
            index,
        }
    }
    fn at(y0: f64, height: f64, n: usize, y: f64) -> usize {
        (crate::geom::floor((y - y0) / height).max(0.0) as usize).min(n - 1)
    }
    /// The segments listed in the bands that may come within `tol` of `y`
    /// (a segment spanning several bands may come more than once).
    fn near(&self, y: f64, tol: f64) -> impl Iterator<Item = u32> + '_ {
        let (lo, hi) = (
            Self::at(self.y0, self.height, self.n, y - tol),
            Self::at(self.y0, self.height, self.n, y + tol),
        );
        let (ranges, lists) = match &self.index {
            BandIndex::Ranges(len, r) => (Some((*len as u32, r)), None),
            BandIndex::Lists(l) => (None, Some(l)),
        };
        // Short loops: each segment once if its bands meet lo..=hi.
        let short = ranges.into_iter().flat_map(move |(len, r)| {
            (0..len).filter(move |&k| {
                let (first, last) = r[k as usize];
                first as usize <= hi && lo <= last as usize
            })
        });
        let long = lists
            .into_iter()
            .flat_map(move |l| (lo..=hi).flat_map(move |b| l.get(b).iter().copied()));
        short.chain(long)
    }
}

/// A closed contour ready for point tests.
struct Loop<'c> {
    segs: &'c [Segment],
    bands: Bands,
}

impl<'c> Loop<'c> {
    fn new(segs: &'c [Segment], bbox: &crate::geom::BBox) -> Self {
        Loop {
            segs,
            bands: Bands::new(segs, bbox),
        }
    }
    /// Even-odd inside test, as [`point_in_loop`] but over the point's band only
    /// (a segment that can change the parity spans the point's Y; with no
    /// margin the point is in one band).
    fn contains(&self, p: Point) -> bool {
        parity(p, self.bands.near(p.y, 0.0).map(|k| &self.segs[k as usize]))
    }
    /// True when `p` is farther than `tol` from every segment (a segment
    /// listed in two bands is tested twice, to the same answer).
    fn clear_of(&self, p: Point, tol: f64) -> bool {
        self.bands
            .near(p.y, tol)
            .all(|k| dist_to_segment(p, &self.segs[k as usize]) > tol)
    }
}

/// A point of `inner` farther than `tol` from `outer`'s boundary, if any.
fn probe(inner: &[Segment], outer: &Loop, tol: f64) -> Option<Point> {
    let candidates = inner
        .iter()
        .map(|s| s.point_at(0.5))
        .chain(inner.iter().map(|s| s.a));
    candidates.take(64).find(|&q| outer.clear_of(q, tol))
}

/// No contour (parent, loop slot), or no depth (an open contour): contour
/// counts stay far below it.
pub const NONE: u32 = u32::MAX;

/// Each contour's depth (NONE for an open one: not classified) and
/// parent (NONE for none), by index.
pub struct Nesting {
    pub depth: Vec<u32>,
    pub parent: Vec<u32>,
}

impl Nesting {
    /// What contour `i` is: even depth an outer, odd a hole.
    pub fn kind(&self, i: usize) -> ContourKind {
        match self.depth[i] {
            NONE => ContourKind::Open,
            d if d.is_multiple_of(2) => ContourKind::Outer,
            _ => ContourKind::Hole,
        }
    }
}

/// Depth and parent of the closed contours (the caller writes them and
/// the kinds into the contours, in one pass in index order with the part
/// numbers: writing them here went over the contours in area order).
/// The order [`classify`] searches in: the contours with an area (`areas`,
/// None for an open one) by decreasing |area|, then by index. Larger
/// first: only a larger contour can contain a smaller one.
pub fn by_area(areas: &[Option<f64>]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..areas.len()).filter(|&i| areas[i].is_some()).collect();
    // By decreasing |area| (its negation's increasing order: negation
    // reverses `total_cmp`), then by index.
    crate::sort::sort_by_number_then(
        &mut order,
        |&i| -areas[i].unwrap_or(0.0).abs(),
        |i, j| i.cmp(j),
    );
    order
}

/// `order`: [`by_area`] of the contours' areas (None for the open ones).
pub fn classify(
    contours: &[Contour],
    order: Vec<usize>,
    tol: Tolerance,
    threads: Threads,
    warnings: &mut Vec<Warning>,
) -> Nesting {
    let t = tol.mm();
    // Ranks, depths, parents and loop slots as u32 (contour indices fit:
    // the grid's lists already hold them so), a quarter of the pages of
    // usize and Option<usize> arrays over a sheet's 137k contours (issue 17).
    let mut rank = vec![u32::MAX; contours.len()];
    for (r, &i) in order.iter().enumerate() {
        rank[i] = r as u32;
    }
    let grid = BoxGrid::new(contours, &order, threads);
    // Each contour's containers are found on their own: ranges of the
    // order on the threads, each with its own containers' point-test
    // indexes, the warnings joined in the order's order.
    let found = crate::par::map_ranges(order.len(), threads, 4096, |r| {
        (r.clone(), containers(contours, &order[r], &rank, &grid, t))
    });
    let mut depth = vec![NONE; contours.len()];
    let mut parent = vec![NONE; contours.len()];
    for (range, found) in found {
        for (&i, (d, p)) in order[range].iter().zip(found.depth_parent) {
            depth[i] = d;
            parent[i] = p;
        }
        warnings.extend(found.warnings);
    }
    Nesting { depth, parent }
}

/// The depth and parent of each contour of `order` (a range of the whole
/// order), and the warnings met, in that order.
struct Found {
    depth_parent: Vec<(u32, u32)>,
    warnings: Vec<Warning>,
}

/// [`classify`]'s search for the contours of `order`.
fn containers(
    contours: &[Contour],
    order: &[usize],
    rank: &[u32],
    grid: &BoxGrid,
    t: f64,
) -> Found {
    let mut found = Found {
        depth_parent: Vec::with_capacity(order.len()),
        warnings: Vec::new(),
    };
    // Point-test indexes of the containers, built when first needed: each
    // contour's slot in `loops` (NONE until built). A slot array, not an
    // `Option<Loop>` per contour: those were 120 B each (16 MB of fresh
    // pages on a sheet, written as None and dropped again) where only the
    // containers (half the sheet's contours) need one. Room for every
    // closed contour up front: pages are touched only as loops are built,
    // where growing by doubling copied them into fresh pages again.
    let mut slot = vec![NONE; contours.len()];
    let mut loops: Vec<Loop> = Vec::with_capacity(order.len());
    let mut candidates: Vec<usize> = Vec::new();
    for &i in order {
        let ci = &contours[i];
        let (mut depth, mut parent) = (0, NONE);
        // Any container holds i's first point, so it is registered in that point's cell.
        candidates.clear();
        candidates.extend(
            grid.at(ci.start())
                .iter()
                .map(|&j| j as usize)
                .filter(|&j| rank[j] < rank[i]),
        );
        crate::sort::sort_by_key(&mut candidates, |&j| rank[j]);
        for &j in &candidates {
            let cj = &contours[j];
            if !cj.bbox.contains_box(&ci.bbox, t) {
                continue;
            }
            if slot[j] == NONE {
                slot[j] = loops.len() as u32;
                loops.push(Loop::new(&cj.segments, &cj.bbox));
            }
            let outer = &loops[slot[j] as usize];
            match probe(&ci.segments, outer, t) {
                Some(q) => {
                    if outer.contains(q) {
                        depth += 1;
                        // Candidates go by decreasing area: the last container found is the smallest.
                        parent = j as u32;
                    }
                }
                None => {
                    if (ci.area.abs() - cj.area.abs()).abs() <= t * ci.length {
                        found.warnings.push(Warning::at(
                            "contour-twice",
                            text!("contour drawn twice: the copy is cut as a separate contour";
                                  "contorno desenhado duas vezes: a cópia é cortada como contorno separado"),
                            ci.start(),
                        ));
                    }
                }
            }
        }
        found.depth_parent.push((depth, parent));
    }
    drop(loops);
    found
}

#[cfg(test)]
#[path = "depth_tests.rs"]
mod tests;
