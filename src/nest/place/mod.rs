//! The constructive placer: copies one by one, in a given order, each at
//! the best of a set of touching positions (bottom-left fill), then slid
//! left and down until it touches.
//!
//! Candidate positions are where a vertex of the new copy meets a vertex of
//! a copy already placed, or the copy's box meets the sheet's lower or upper
//! edge at the left or beside a placed copy's box (the "touching
//! positions" of bottom-left fill, Dowsland, Vaid & Dowsland, EJOR 2002,
//! without the no-fit polygon). They are tried best first, ranked by the
//! length the sheet would then use, then the copy's right edge, then its
//! bottom: the first one free of overlaps is taken. The choice of rotation
//! and mirror is made here, greedily, among the part's allowed ones.

mod best_first;
mod container;

use super::collide::{boxes_overlap, overlaps_near, within, Shape};
use crate::geom::{fmax, fmin, Point};
use best_first::{BestFirst, Cand, Room};
pub(crate) use container::range_of;
pub use container::{Container, Placed, Variant};

/// Most levels tried past everything placed when no candidate is free.
const MAX_LEVELS: usize = 32;
/// Most vertex-meets-vertex candidates from one placed copy and one variant.
const VERTEX_PAIRS: usize = 4096;
/// Most vertex-meets-vertex candidates from all placed copies together,
/// per variant: on a sheet of hundreds of many-vertex copies the pairs
/// grow with the square of the copies placed, and placing the 160th copy
/// of a 60-vertex profile made 2 million candidates (a 160-copy sheet took
/// 54 s). Above this, every copy contributes every k-th vertex. Benchmark
/// instances (tens of copies of tens of vertices) stay under it.
const VERTEX_BUDGET: usize = 65_536;
/// The placer's work ([`Bin::work`]) of one pair of shapes whose boxes
/// overlap, and the vertices of the pair a further unit costs. A unit is
/// about a candidate made (12.8 ns on this machine kind): fitted to the
/// CPU time of the first nest and the sequence search on the 7 ESICUP and
/// 6 real-part instances of scripts/bench-nest.sh (made, pairs and their
/// vertices counted; 262 ns a pair and 1.3 ns a vertex of it). Each
/// instance's time per unit is then within 0.64–1.32 of the mean, where a
/// count of the copies tested against, weighted by vertices, ranged from
/// 1.2 ns (keyboard plates: 50 copies, nearly all refused by their boxes)
/// to 15.6 ns (jakobs1).
const PAIR_WORK: u64 = 20;
const VERTICES_A_UNIT: usize = 8;

/// Candidates beyond this many times the number tried are never given:
/// only the best ones are ranked ([`BestFirst`]).
const SELECT_FACTOR: usize = 4;

/// The copies in one container, and the length they use (right edge of
/// the rightmost grown shape).
#[derive(Clone, Debug)]
pub struct Bin {
    /// The room's box.
    pub container: Container,
    /// The room's outline when it is not the box (a hole, an irregular
    /// sheet): grown shapes lie within it.
    pub bound: Option<Shape>,
    /// No-go zones (a remnant's holes and defects, grown by the margin).
    pub obstacles: Vec<Shape>,
    /// What is in it.
    pub placed: Vec<Placed>,
    /// Rightmost x of a grown shape (container x0 when empty).
    pub right: f64,
    /// The copy the last refused position overlapped.
    last_hit: std::cell::Cell<usize>,
    /// The work of the exact tests since [`Bin::place`] last counted it.
    exact: std::cell::Cell<u64>,
    /// Work done placing here: candidates made, positions tested, and the
    /// exact tests they needed, by vertices ([`PAIR_WORK`]). A count, not a clock,
    /// so the search can share out its effort the same on every run.
    pub work: u64,
    /// Memory of the candidate lists, kept from copy to copy (empty: a
    /// clone copies nothing). A new list each copy was page faults.
    room: Room,
}

impl Bin {
    /// An empty bin.
    pub fn new(container: Container) -> Bin {
        Bin {
            container,
            bound: None,
            obstacles: Vec::new(),
            placed: Vec::new(),
            right: container.x0,
            last_hit: Default::default(),
            exact: Default::default(),
            work: 0,
            room: Default::default(),
        }
    }

    /// An empty bin whose room is `bound` (within the box `clip`, which
    /// may be infinite), less the `obstacles`.
    pub fn within(bound: Shape, clip: Container, obstacles: Vec<Shape>) -> Bin {
        let b = *bound.bbox();
        let mut bin = Bin::new(Container {
            x0: fmax(b.min.x, clip.x0),
            y0: fmax(b.min.y, clip.y0),
            x1: fmin(b.max.x, clip.x1),
            y1: fmin(b.max.y, clip.y1),
        });
        bin.bound = Some(bound);
        bin.obstacles = obstacles;
        bin
    }

    /// This bin as it stood with only its first `m` copies placed and
    /// `work` done: the same bin as placing them again gives. The right
    /// edge is the same maxima taken in the same order as [`Bin::place_as`]
    /// took them, so it is the same number; the copy last hit is where
    /// [`Bin::free`] starts looking, never its answer, and each placement
    /// starts it afresh.
    pub fn first(&self, m: usize, work: u64) -> Bin {
        let placed = self.placed[..m.min(self.placed.len())].to_vec();
        let right = placed
            .iter()
            .fold(self.container.x0, |r, p| fmax(r, p.shape.bbox().max.x));
        Bin {
            container: self.container,
            bound: self.bound.clone(),
            obstacles: self.obstacles.clone(),
            placed,
            right,
            last_hit: Default::default(),
            exact: Default::default(),
            work,
            room: Default::default(),
        }
    }

    /// True when `s` lies in the container and overlaps nothing placed.
    /// The copy it last collided with is tried first: neighbouring
    /// candidates mostly hit the same one.
    pub fn free(&self, s: &Shape, eps: f64) -> bool {
        let b = s.bbox();
        let c = &self.container;
        if !(b.min.x >= c.x0 - eps
            && b.min.y >= c.y0 - eps
            && b.max.x <= c.x1 + eps
            && b.max.y <= c.y1 + eps)
        {
            return false;
        }
        // Only pairs whose boxes overlap cost an exact test: counted by
        // their vertices (PAIR_WORK).
        let exact = |a: &Shape| {
            let n = a.poly.pts.len() + s.poly.pts.len();
            self.exact
                .set(self.exact.get() + PAIR_WORK + (n / VERTICES_A_UNIT) as u64);
        };
        if let Some(room) = &self.bound {
            exact(room);
            if !within(room, s, eps) {
                return false;
            }
        }
        let overlaps = |a: &Shape| {
            boxes_overlap(a.bbox(), b, eps) && {
                exact(a);
                overlaps_near(a, s, eps)
            }
        };
        if self.obstacles.iter().any(overlaps) {
            return false;
        }
        let last = self.last_hit.get();
        if let Some(p) = self.placed.get(last) {
            if overlaps(&p.shape) {
                return false;
            }
        }
        // (The copy just asked overlaps not: not asked again.)
        let hit = self
            .placed
            .iter()
            .enumerate()
            .position(|(i, p)| i != last && overlaps(&p.shape));
        match hit {
            Some(i) => {
                self.last_hit.set(i);
                false
            }
            None => true,
        }
    }

    /// Places a copy of `item` at its best position, if it has one.
    pub fn place(
        &mut self,
        item: usize,
        variants: &[Variant],
        eps: f64,
        max_candidates: usize,
    ) -> bool {
        self.place_as(item, variants, None, eps, max_candidates)
    }

    /// [`Bin::place`], turned only as variant `only` when given.
    pub fn place_as(
        &mut self,
        item: usize,
        variants: &[Variant],
        only: Option<usize>,
        eps: f64,
        max_candidates: usize,
    ) -> bool {
        // Where `free` starts looking decides which exact tests are made,
        // so the work counted: every placement starts at the first copy,
        // and a bin had back by [`Bin::first`] counts as the bin it was.
        // Tests asked outside a placement (the separator's rooms) are no
        // placement's work.
        self.last_hit.set(0);
        self.exact.set(0);
        let c = self.container;
        let mut cands = std::mem::take(&mut self.room);
        let mut beyond = Vec::new();
        for (vi, v) in variants.iter().enumerate() {
            if !c.fits(v) || only.is_some_and(|o| o != vi) {
                continue;
            }
            let vb = *v.shape.bbox();
            let (w, h) = (vb.max.x - vb.min.x, vb.max.y - vb.min.y);
            let mut push = |t: Point| {
                let (x0, y0) = (t.x + vb.min.x, t.y + vb.min.y);
                if x0 < c.x0 - eps || y0 < c.y0 - eps || x0 + w > c.x1 + eps || y0 + h > c.y1 + eps
                {
                    return;
                }
                let right = x0 + w;
                cands.push(Cand::new(fmax(right, self.right), right, y0, vi, t));
            };
            let at = |x: f64, y: f64| Point::new(x - vb.min.x, y - vb.min.y);
            // Past everything placed, at the bottom, the top and the
            // level of each placed copy's bottom and top: free when the
            // sheet is long enough (always on a strip). When none of the
            // best candidates is free, each is slid left and down and the
            // one that ends leftmost is taken.
            let levels = [c.y0, c.y1 - h].into_iter().chain(
                self.placed
                    .iter()
                    .flat_map(|p| [p.shape.bbox().min.y, p.shape.bbox().max.y]),
            );
            let first = beyond.len();
            for y in levels.take(MAX_LEVELS) {
                let t = at(fmax(self.right, c.x0), y);
                // Copies in a row share their bottom: one slide a level
                // (a slide tries dozens of steps).
                if y >= c.y0 - eps && y + h <= c.y1 + eps && !beyond[first..].contains(&(vi, t)) {
                    beyond.push((vi, t));
                }
            }
            push(at(c.x0, c.y0));
            push(at(c.x0, c.y1 - h));
            // Vertex meets vertex with the room's outline and the no-go
            // zones, every k-th vertex as below.
            for o in self.bound.iter().chain(&self.obstacles) {
                let (nq, nr) = (o.poly.pts.len(), v.shape.poly.pts.len());
                let k = ((nq * nr) as f64 / VERTEX_PAIRS as f64)
                    .sqrt()
                    .ceil()
                    .max(1.0) as usize;
                for &q in o.poly.pts.iter().step_by(k) {
                    for &r in v.shape.poly.pts.iter().step_by(k) {
                        push(q.sub(r));
                    }
                }
                let ob = o.bbox();
                push(at(ob.max.x, c.y0));
                push(at(c.x0, ob.max.y));
                push(at(ob.max.x, ob.min.y));
                push(at(ob.min.x, ob.max.y));
            }
            let nr = v.shape.poly.pts.len();
            let pairs: usize = self
                .placed
                .iter()
                .map(|p| p.shape.poly.pts.len() * nr)
                .sum();
            let k_all = ((pairs as f64 / VERTEX_BUDGET as f64).sqrt().ceil()).max(1.0) as usize;
            for p in &self.placed {
                let pb = p.shape.bbox();
                push(at(pb.max.x, c.y0));
                push(at(pb.max.x, c.y1 - h));
                push(at(pb.max.x, pb.min.y));
                push(at(pb.min.x, pb.max.y));
                push(at(c.x0, pb.max.y));
                push(at(pb.max.x - w, pb.max.y));
                // Vertex meets vertex; on finely curved outlines (many
                // vertices) every k-th vertex, so one pair gives at most
                // about VERTEX_PAIRS candidates.
                let nq = p.shape.poly.pts.len();
                let k = ((nq * nr) as f64 / VERTEX_PAIRS as f64)
                    .sqrt()
                    .ceil()
                    .max(1.0) as usize;
                let k = k.max(k_all);
                for &q in p.shape.poly.pts.iter().step_by(k) {
                    for &r in v.shape.poly.pts.iter().step_by(k) {
                        push(q.sub(r));
                    }
                }
            }
        }
        let made = cands.len() + beyond.len();
        let keep = max_candidates.saturating_mul(SELECT_FACTOR);
        // One shape moved to each position in turn (no allocation a try).
        let mut s = match variants.iter().find(|v| c.fits(v)) {
            Some(v) => v.shape.clone(),
            None => return false,
        };
        let fallback = |s: &mut Shape, tests: &mut u64| {
            beyond
                .iter()
                .filter_map(|&(vi, t)| {
                    s.move_from(&variants[vi].shape, t);
                    *tests += 1;
                    self.free(s, eps).then(|| {
                        let (t, s) = self.slide(&variants[vi].shape, t, s.clone(), eps, tests);
                        (vi, t, s)
                    })
                })
                .min_by(|a, b| {
                    let (ba, bb) = (a.2.bbox(), b.2.bbox());
                    ba.max
                        .x
                        .total_cmp(&bb.max.x)
                        .then(ba.min.y.total_cmp(&bb.min.y))
                })
        };
        // Best first ([`best_first`]), the first `max_candidates` distinct
        // ones, tried until one is free: the sequence of sorting them all,
        // deduplicating and truncating.
        let mut tried = 0u64;
        let mut last: Option<(usize, Point)> = None;
        let mut found = None;
        let mut best_first = BestFirst::new(cands, keep);
        for Cand { variant: vi, t, .. } in best_first.by_ref() {
            if last == Some((vi, t)) {
                continue;
            }
            last = Some((vi, t));
            if tried == max_candidates as u64 {
                break;
            }
            tried += 1;
            s.move_from(&variants[vi].shape, t);
            if self.free(&s, eps) {
                found = Some((
                    vi,
                    self.slide(&variants[vi].shape, t, s.clone(), eps, &mut tried),
                ));
                break;
            }
        }
        let best = found
            .map(|(vi, (t, s))| (vi, t, s))
            .or_else(|| fallback(&mut s, &mut tried));
        self.room = best_first.into_room();
        // Every test counts: the candidates', the fallback's and each step
        // of a slide (with 24 turns a full sheet's fallback slides hundreds
        // of copies: uncounted, 58 decodes of keyboard plates took 24 s of
        // the sequence search's 6, scripts/bench-nest.sh), and within each
        // the exact tests of the pairs past the boxes, by their vertices.
        self.work += made as u64 + tried + self.exact.take();
        if let Some((vi, t, s)) = best {
            self.right = fmax(self.right, s.bbox().max.x);
            self.placed.push(Placed {
                item,
                variant: vi,
                t,
                shape: s,
            });
            return true;
        }
        false
    }

    /// Moves a free shape left, then down, by halving steps while it stays
    /// free, until neither gains more than `eps`; each step tried adds one
    /// to `tests`.
    fn slide(
        &self,
        base: &Shape,
        mut t: Point,
        mut s: Shape,
        eps: f64,
        tests: &mut u64,
    ) -> (Point, Shape) {
        let b = base.bbox();
        let size = (b.max.x - b.min.x).max(b.max.y - b.min.y);
        let floor = (size * 1e-4).max(eps * 10.0);
        let mut s2 = s.clone();
        for _round in 0..4 {
            let mut moved = false;
            for dir in [Point::new(-1.0, 0.0), Point::new(0.0, -1.0)] {
                let mut step = size / 4.0;
                while step > floor {
                    let t2 = t.add(dir.scale(step));
                    s2.move_from(base, t2);
                    *tests += 1;
                    if self.free(&s2, eps) {
                        t = t2;
                        std::mem::swap(&mut s, &mut s2);
                        moved = true;
                    } else {
                        step /= 2.0;
                    }
                }
            }
            if !moved {
                break;
            }
        }
        (t, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::collide::overlaps;
    use crate::nest::shape::Polygon;

    /// An empty bin from the origin, `length` by `height`.
    fn sheet(length: f64, height: f64) -> Bin {
        Bin::new(Container {
            x0: 0.0,
            y0: 0.0,
            x1: length,
            y1: height,
        })
    }

    fn square(side: f64) -> Variant {
        Variant {
            rotation: 0.0,
            mirror: false,
            shape: Shape::new(Polygon::new(vec![
                Point::new(0.0, 0.0),
                Point::new(side, 0.0),
                Point::new(side, side),
                Point::new(0.0, side),
            ])),
            holes: Vec::new(),
        }
    }

    #[test]
    fn four_squares_fill_a_two_by_two_box_exactly() {
        let mut bin = sheet(f64::INFINITY, 20.0);
        for _ in 0..4 {
            assert!(bin.place(0, &[square(10.0)], 1e-9, 100_000));
        }
        assert!((bin.right - 20.0).abs() < 1e-9, "{}", bin.right);
        for (i, a) in bin.placed.iter().enumerate() {
            for b in &bin.placed[i + 1..] {
                assert!(!overlaps(&a.shape, &b.shape, 1e-9));
            }
        }
    }

    #[test]
    fn on_a_strip_every_copy_is_placed_however_few_candidates_are_tried() {
        let mut bin = sheet(f64::INFINITY, 25.0);
        // One candidate per copy: the best one is taken by the first copy,
        // the rest go past everything placed.
        for _ in 0..6 {
            assert!(bin.place(0, &[square(10.0)], 1e-9, 1));
        }
        assert_eq!(bin.placed.len(), 6);
    }

    #[test]
    fn the_work_of_a_placement_counts_the_steps_of_its_slide() {
        let mut bin = sheet(100.0, 20.0);
        assert!(bin.place(0, &[square(10.0)], 1e-9, 100_000));
        // Four candidates made (the corners and two past everything) and
        // one tried: 5 without the slide. The slide from the corner tries
        // halving steps left and down from 2.5 mm to 1 µm, each refused.
        let steps = 2 * (2.5f64 / 1e-3).log2().floor() as u64;
        assert!(bin.work >= 5 + steps, "{}", bin.work);
    }

    #[test]
    fn the_work_of_a_placement_counts_its_exact_tests() {
        let mut bin = sheet(100.0, 10.0);
        assert!(bin.place(0, &[square(10.0)], 1e-9, 100_000));
        let alone = bin.work;
        // The second square's slide left steps into the first from 2.5 mm
        // down: each step refused is one exact test past the boxes.
        assert!(bin.place(0, &[square(10.0)], 1e-9, 100_000));
        let refused = (2.5f64 / 1e-3).log2().floor() as u64;
        assert!(
            bin.work - alone >= refused * PAIR_WORK,
            "{alone} {}",
            bin.work
        );
    }

    #[test]
    fn a_copy_too_big_for_the_sheet_is_not_placed() {
        let mut bin = sheet(100.0, 20.0);
        assert!(!bin.place(0, &[square(30.0)], 1e-9, 100_000));
        assert!(bin.placed.is_empty());
    }
}
