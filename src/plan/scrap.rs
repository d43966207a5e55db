//! Where a torch-on move may run: in scrap, at least half the kerf away
//! from every part's material (issue 14). A kerf of width w removes a disc
//! of radius w/2 around the torch; a move whose disc reaches into a part
//! eats it. The kerf path of a part runs exactly w/2 from its drawn edge, so
//! it is the nearest a move may come.
//!
//! Used twice: by the planners, to accept a torch-on link (an Eulerian bridge,
//! a chain link), and after planning, to measure how far each order's
//! torch-on moves cut into parts ([`intrusion`], shown by Compare).

use super::clearance::Obstacles;
use super::CutPlan;
use crate::contour::{point_in_loop, ContourKind, Contours};
use std::collections::HashMap;

use crate::geom::Point;

/// The drawn parts, for torch-on moves of one kerf.
pub struct Scrap<'a> {
    obstacles: &'a Obstacles,
    contours: &'a Contours,
    /// Half the kerf, mm.
    radius: f64,
    tol: f64,
    /// Closed contours by the grid cells their boxes cover, for the inside test.
    boxes: BoxGrid,
}

/// Most cells one contour's box is filed under; bigger ones are always tested.
const MAX_BOX_CELLS: i64 = 4096;

/// Closed contours filed by the cells of a uniform grid that their boxes
/// cover: a point is tested only against the contours whose box may hold it
/// (a sheet of a thousand parts would otherwise test all of them each time).
struct BoxGrid {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<u32>>,
    always: Vec<u32>,
}

impl BoxGrid {
    fn new(contours: &Contours) -> BoxGrid {
        let closed: Vec<u32> = (0..contours.contours.len() as u32)
            .filter(|&i| contours.contours[i as usize].kind != ContourKind::Open)
            .collect();
        let mut ext = crate::geom::BBox::EMPTY;
        for &i in &closed {
            ext.union(&contours.contours[i as usize].bbox);
        }
        let area = if ext.is_empty() {
            1.0
        } else {
            ((ext.max.x - ext.min.x) * (ext.max.y - ext.min.y)).max(1.0)
        };
        // About one contour per cell.
        let cell = (area / closed.len().max(1) as f64).sqrt().max(1e-3);
        let mut g = BoxGrid {
            cell,
            cells: HashMap::new(),
            always: Vec::new(),
        };
        for i in closed {
            let b = &contours.contours[i as usize].bbox;
            let (lo, hi) = (g.key(b.min), g.key(b.max));
            if (hi.0 - lo.0 + 1).saturating_mul(hi.1 - lo.1 + 1) > MAX_BOX_CELLS {
                g.always.push(i);
                continue;
            }
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    g.cells.entry((x, y)).or_default().push(i);
                }
            }
        }
        g
    }
    fn key(&self, p: Point) -> (i64, i64) {
        let f = |v: f64| (v / self.cell).floor().clamp(-1e15, 1e15) as i64;
        (f(p.x), f(p.y))
    }
    /// Contours whose box may hold `p`.
    fn at(&self, p: Point) -> impl Iterator<Item = usize> + '_ {
        let here = self.cells.get(&self.key(p)).map_or(&[][..], |v| &v[..]);
        here.iter().chain(&self.always).map(|&i| i as usize)
    }
}

impl<'a> Scrap<'a> {
    /// Parts of `contours` (indexed in `obstacles`), for a kerf of
    /// `kerf_width` mm; `tol` is the one tolerance.
    pub fn new(
        obstacles: &'a Obstacles,
        contours: &'a Contours,
        kerf_width: f64,
        tol: f64,
    ) -> Self {
        let radius = if kerf_width.is_finite() {
            (kerf_width / 2.0).max(0.0)
        } else {
            0.0
        };
        Scrap {
            obstacles,
            contours,
            radius,
            tol,
            boxes: BoxGrid::new(contours),
        }
    }

    /// True when the straight torch-on move `p → q` removes no part's
    /// material: its kerf disc keeps half the kerf from every drawn closed
    /// contour (with no kerf: it crosses none, except at its own ends), and
    /// it does not run inside a part.
    pub fn line_ok(&self, p: Point, q: Point) -> bool {
        if !(p.is_finite() && q.is_finite()) {
            return false;
        }
        let clear = if self.radius > self.tol {
            self.obstacles.line_distance(p, q, self.radius) >= self.radius - self.tol
        } else {
            self.obstacles.line_is_clear(p, q, &[p, q])
        };
        clear && !self.in_material(p.add(q).scale(0.5))
    }

    /// True when a kerf disc at `p` takes nothing from any part.
    pub fn point_ok(&self, p: Point) -> bool {
        p.is_finite()
            && self.obstacles.distance(p, self.radius + 1.0) >= self.radius - self.tol
            && !self.in_material(p)
    }

    /// True when `p` lies in a part's material: inside an odd number of
    /// closed contours (an outer, not in one of its holes, or an island).
    pub fn in_material(&self, p: Point) -> bool {
        // Nudged off the lines of arcs' chords and of vertices (a pierce at a
        // hole's centre lies on its halves' common chord, where the even-odd
        // test is undecided); far below the tolerance the callers keep.
        let p = Point::new(p.x + 0.754_877_666e-7, p.y + 0.569_840_291e-7);
        let inside = self
            .boxes
            .at(p)
            .filter_map(|i| self.contours.contours.get(i))
            .filter(|c| {
                p.x >= c.bbox.min.x
                    && p.x <= c.bbox.max.x
                    && p.y >= c.bbox.min.y
                    && p.y <= c.bbox.max.y
            })
            .filter(|c| point_in_loop(p, &c.segments))
            .count();
        inside % 2 == 1
    }
}

/// How far a plan's torch-on moves cut into parts.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Intrusion {
    /// Length of torch-on travel whose kerf reaches into a part, mm.
    pub length: f64,
    /// Deepest reach of the kerf into a part, mm.
    pub depth: f64,
}

impl Intrusion {
    /// True when some move cuts into a part.
    pub fn cuts_parts(&self) -> bool {
        self.length > 0.0
    }
}

/// Deepest reach counted as cutting into a part: a kerf path runs exactly
/// half the kerf from its part, so this is the geometry's rounding, not a cut.
fn slack(tol: f64) -> f64 {
    (2.0 * tol).max(1e-6)
}

/// Samples every feed move of `plan` (lead-ins, contours, links, repeats,
/// lead-outs) at most every half kerf (0.1–2 mm; a corner poking between two
/// samples is missed by at most r(1 − √3/2), under a tenth of the kerf) and
/// measures how far the kerf disc there reaches into the drawn parts.
///
/// A sample at distance d from the nearest drawn contour reaches w/2 − d
/// into a part when outside it, w/2 + d when inside. Whether a sample is
/// inside is tested only when it could have changed since the last one
/// known (a move crosses a contour only where d = 0, and d changes no faster
/// than the torch moves), so a plan costs about one grid query per sample.
pub fn intrusion(plan: &CutPlan, scrap: &Scrap) -> Intrusion {
    let r = scrap.radius;
    let slack = slack(scrap.tol);
    let step = r.clamp(0.1, 2.0);
    let mut out = Intrusion::default();
    for cut in &plan.cuts {
        // Whether the torch is inside a part, while known (a rapid forgets it).
        let mut inside: Option<bool> = None;
        let mut last_d = 0.0_f64;
        for s in &cut.steps {
            let len = s.segment.length();
            if !len.is_finite() {
                continue;
            }
            // A hundred thousand samples at most per move: a move that long
            // is a drawing's error and is measured coarsely.
            let n = ((len / step).ceil() as usize).clamp(1, 100_000);
            let mut bad = 0usize;
            for k in 0..=n {
                let p = s.segment.point_at(k as f64 / n as f64);
                let d = scrap.obstacles.distance(p, r + step + slack);
                let d = if d.is_finite() { d } else { r + step + slack };
                // Between two samples at most `step` apart, a contour crossed
                // at distance a from one is within a of it and step − a of
                // the other: no crossing when their distances sum to more.
                if last_d + d <= step {
                    inside = None;
                }
                last_d = d;
                // With no kerf, a move on a drawn line takes nothing from either side.
                let depth = if r <= slack && d <= slack {
                    0.0
                } else if *inside.get_or_insert_with(|| scrap.in_material(p)) {
                    r + d
                } else {
                    (r - d).max(0.0)
                };
                if depth > slack {
                    out.depth = out.depth.max(depth);
                    if k > 0 {
                        bad += 1;
                    }
                }
            }
            out.length += len * bad as f64 / n as f64;
        }
    }
    out
}
