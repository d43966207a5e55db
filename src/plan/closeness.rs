//! Parts the kerf eats into, said on every run (issue 45 §1): a cutting
//! move (a kerf path, a lead, a link) whose disc of radius w/2 reaches
//! into another part's material. Parts drawn or nested closer than the
//! kerf (a finger-jointed panel laid out tight, lettering) lose what the
//! neighbour's cut takes; only `--verify` (the full sweep, [`super::verify`])
//! said so before.
//!
//! Each cutting move first asks whether another part's box lies within
//! w/2 of its own ([`PartBoxes`]); on a sheet spaced for the kerf nearly
//! every move finds none, and the segment index is not even built. A move
//! near one asks the drawn-contour index ([`Obstacles`]) for the segments
//! of *other* parts within w/2 of its box. A move that
//! finds some is sampled at most a quarter kerf apart: at each sample, the
//! nearest such segment gives the depth the disc reaches into that part's
//! material (w/2 − d outside it, w/2 + d where the move runs inside it),
//! and depth × step the area taken along the stretch.
//!
//! It also says which loops lose material (by identity, for the page to
//! mark) and where: the samples binned on a grid of the sample step, each
//! cell with the deepest reach in it, as the verification's heat map.

use std::sync::OnceLock;

use super::clearance::{index_box, Obstacles};
use super::part_boxes::PartBoxes;
use super::{CutPlan, PlanInput, Role};
use crate::contour::{point_in_loop, ContourKind};
use crate::fx::FxSet;
use crate::geom::{Along, BBox, Point, Segment, SegmentDistance};
use crate::par::Threads;
use crate::source::ContourRef;
use crate::text;
use crate::warning::{dec, Warning};

/// Cuts a thread checks at least.
const CHUNK: usize = 1024;

/// What the cuts take from other parts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Closeness {
    /// Parts losing material (1-based part numbers), ascending.
    pub parts: Vec<usize>,
    /// Deepest reach of a disc into another part, mm.
    pub depth: f64,
    /// Where.
    pub at: Option<Point>,
    /// Material taken, mm² (about: depth × length sampled).
    pub area: f64,
    /// The loops losing material (outlines or holes), by identity, sorted.
    pub loops: Vec<ContourRef>,
    /// Where: centres of the cells of side [`Closeness::cell`] holding a
    /// sample whose disc reaches into another part, with the deepest
    /// reach in each, in raster order.
    pub cells: Vec<(Point, f64)>,
    /// The side of those cells, mm.
    pub cell: f64,
}

/// Per thread: the figures, the loops (contour indices) and the cells.
#[derive(Default)]
struct Found {
    close: Closeness,
    loops: FxSet<usize>,
    /// The parts in `close.parts`.
    parts: FxSet<usize>,
    /// Each sample's cell and depth (a run of samples in one cell once),
    /// in the order met: appended, then sorted once, where a map by cell
    /// spent most of a dense drawing's check waiting on memory.
    cells: Vec<((i64, i64), f64)>,
}

impl Closeness {
    fn add(&mut self, o: Closeness) {
        self.parts.extend(o.parts);
        if o.depth > self.depth {
            self.depth = o.depth;
            self.at = o.at;
        }
        self.area += o.area;
    }

    /// The warning, or none when no part loses material.
    pub fn warning(&self, kerf: f64) -> Option<Warning> {
        if self.parts.is_empty() {
            return None;
        }
        let n = self.parts.len();
        let mut list: Vec<String> = self.parts.iter().take(10).map(|p| p.to_string()).collect();
        if n > 10 {
            list.push("…".into());
        }
        let list = list.join(", ");
        let (depth, area) = (self.depth, self.area);
        let mut w = Warning::new(
            "parts-closer-than-kerf",
            text!("the cuts take material from {n} part(s) ({list}) lying closer than the kerf ({kerf} mm) to another part's cut: up to {depth:.2} mm deep, about {area:.1} mm² (Verify, or --verify, sweeps the kerf in full)";
                  "os cortes removem material de {n} peça(s) ({list}) mais próximas que a sangria ({} mm) do corte de outra peça: até {} mm de profundidade, cerca de {} mm² (Verificar, ou --verify, varre a sangria por completo)",
                  dec(kerf), dec((depth * 100.0).round() / 100.0), dec((area * 10.0).round() / 10.0)),
        );
        w.at = self.at;
        Some(w.with_loops(self.loops.iter().copied()))
    }
}

/// What the cutting moves of `plan` take from parts other than their own.
pub fn closeness(input: &PlanInput, plan: &CutPlan, threads: Threads) -> Closeness {
    let r = input.process.kerf / 2.0;
    let tol = input.tolerance.max(1e-6);
    let slack = 10.0 * tol;
    if r <= slack {
        return Closeness::default();
    }
    let contours = &input.contours.contours;
    // The segment index only once a move comes near another part's box.
    let boxes = PartBoxes::new(input.contours);
    let index: OnceLock<Obstacles> = OnceLock::new();
    let part_of = |c: usize| contours.get(c).and_then(|c| c.part);
    let checked = |s: &&super::Step| {
        !matches!(s.role, Role::Mark | Role::Tab)
            // An open contour cut on its line (a weld, an engraving) runs
            // over its part on purpose.
            && s.contour
                .and_then(|c| contours.get(c))
                .is_none_or(|c| c.is_closed())
    };
    let cuts: Vec<&super::Cut> = plan.cuts.iter().filter(|c| !c.spot).collect();
    let cell = (r / 4.0).clamp(0.02, 0.5);
    let found = crate::par::map_ranges(cuts.len(), threads, CHUNK, |range| {
        let mut found = Found::default();
        let out = &mut found.close;
        // The other parts' segments near a move, each with its index box:
        // a sample skips a segment whose box is already farther than the
        // nearest found (or than the reach), which spares most distances
        // where many parts' outlines run side by side (graded garment
        // patterns: the corpus's 1.4 MB ASTM file spent most of its plan here).
        let mut near: Vec<(u32, SegmentDistance, BBox)> = Vec::new();
        // Segments already looked at for this move: the index reports a
        // segment once per cell it meets.
        let mut seen: Vec<u32> = Vec::new();
        let mut stamp = 0u32;
        let mut moves: Vec<(&Segment, Option<usize>, BBox)> = Vec::new();
        let mut spans = Spans::default();
        for cut in &cuts[range] {
            moves.clear();
            moves.extend(cut.steps.iter().filter(checked).map(|s| {
                let own = s.contour.and_then(part_of);
                (&s.segment, own, s.segment.bbox())
            }));
            // A cut of one part near no other part's box takes nothing.
            if let Some(&(_, Some(own), b)) = moves.first() {
                if moves.iter().all(|m| m.1 == Some(own)) {
                    let mut all = b;
                    for m in &moves {
                        all.union(&m.2);
                    }
                    if !boxes.others_near(&all.grown(r), Some(own)) {
                        continue;
                    }
                }
            }
            for &(seg, own, b) in &moves {
                let grown = b.grown(r);
                if !boxes.others_near(&grown, own) {
                    continue;
                }
                let obstacles = index.get_or_init(|| Obstacles::with_owners(input.contours, tol));
                if seen.len() != obstacles.len() {
                    seen = vec![0; obstacles.len()];
                }
                stamp = stamp.wrapping_add(1);
                if stamp == 0 {
                    seen.fill(0);
                    stamp = 1;
                }
                near.clear();
                obstacles.each_index_near(&grown, |i| {
                    if std::mem::replace(&mut seen[i as usize], stamp) == stamp {
                        return true;
                    }
                    let c = obstacles.owner(i);
                    let s = obstacles.segment(i);
                    // The move's own part's segments are passed over at once:
                    // on a spaced sheet they are all a move finds.
                    let part = part_of(c);
                    let ib = index_box(s);
                    if part.is_some() && (own.is_none() || part != own) && ib.overlaps(&grown, 0.0) {
                        near.push((i, SegmentDistance::new(s), ib));
                    }
                    true
                });
                // A move of no contour (the drawing order's, on the drawn
                // lines) is its own part's where it runs on that part's outline.
                let mid = seg.point_at(0.5);
                let own = own.or_else(|| {
                    near.iter()
                        .map(|(i, sd, _)| (*i, sd.to(mid)))
                        .filter(|&(_, d)| d < slack)
                        .min_by(|a, b| a.1.total_cmp(&b.1))
                        .and_then(|(i, _)| part_of(obstacles.owner(i)))
                });
                near.retain(|(i, _, _)| part_of(obstacles.owner(*i)) != own);
                if near.is_empty() {
                    continue;
                }
                let len = seg.length();
                let n = (len / cell).ceil().max(1.0) as usize;
                let step = len / n as f64;
                let along = Along::new(seg);
                spans.prepare(seg, n, r + slack, &near);
                for k in 0..=n {
                    let p = along.at(k as f64 / n as f64);
                    // The nearest segment closer than the reach (the first
                    // of equals); samples with none take nothing.
                    let mut reach = r - slack;
                    let mut nearest = None;
                    for &j in spans.at(k) {
                        let (i, sd, ib) = &near[j as usize];
                        if ib.gap_sq(p).sqrt() > reach + slack {
                            continue;
                        }
                        // Surely not nearer than the reach: no `hypot`.
                        if sd.to_sq_about(p) > reach * reach * (1.0 + 1e-9) {
                            continue;
                        }
                        let d = sd.to(p);
                        if d < reach {
                            reach = d;
                            nearest = Some((*i, d));
                        }
                    }
                    let Some((i, d)) = nearest else {
                        continue;
                    };
                    let c = obstacles.owner(i);
                    let inside = in_material(p, &contours[c]);
                    found.loops.insert(c);
                    let depth = if inside { r + d } else { r - d };
                    // The ends of a move count half: its neighbour samples them too.
                    let w = if k == 0 || k == n { 0.5 } else { 1.0 };
                    out.area += depth.min(2.0 * r) * step * w;
                    if depth > out.depth {
                        out.depth = depth;
                        out.at = Some(p);
                    }
                    let key = ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
                    let depth = depth.min(2.0 * r);
                    match found.cells.last_mut() {
                        Some((k, deepest)) if *k == key => *deepest = deepest.max(depth),
                        _ => found.cells.push((key, depth)),
                    }
                    if let Some(part) = part_of(c) {
                        // A set beside the list: a garment pattern's nest has
                        // thousands of parts, and every sample asked the list.
                        if found.parts.insert(part) {
                            out.parts.push(part);
                        }
                    }
                }
            }
        }
        found
    });
    let mut all = Closeness {
        cell,
        ..Closeness::default()
    };
    let mut loops = Vec::new();
    let mut cells: Vec<((i64, i64), f64)> = Vec::new();
    for f in found {
        all.add(f.close);
        loops.extend(f.loops);
        cells.extend(f.cells);
    }
    crate::sort::sort_indices(&mut all.parts);
    all.parts.dedup();
    all.loops = loops.iter().map(|&c| contours[c].source).collect();
    crate::sort::sort_by(&mut all.loops, Ord::cmp);
    all.loops.dedup();
    // Raster order, then each cell once with its deepest reach.
    crate::sort::sort_cells(&mut cells);
    cells.dedup_by(|later, kept| {
        let same = later.0 == kept.0;
        if same {
            kept.1 = kept.1.max(later.1);
        }
        same
    });
    all.cells = cells
        .into_iter()
        .map(|((i, j), d)| {
            let centre = Point::new((i as f64 + 0.5) * cell, (j as f64 + 0.5) * cell);
            (centre, d)
        })
        .collect();
    all
}

/// Which of a move's nearby segments each of its samples needs to look
/// at: a straight move meets a segment's box grown by the reach over one
/// stretch of its samples, so a sample skips the segments whose stretch it
/// is not in (long moves beside many outlines — graded garment patterns,
/// where each sample used to test every segment near the whole move).
/// Conservative by a sample at each end: what a sample looks at is a
/// superset of what can reach it, in the segments' order, so the nearest
/// (the first of equals) is the one a scan of them all finds.
#[derive(Default)]
struct Spans {
    /// Per near segment: its first and last sample.
    spans: Vec<(usize, usize)>,
    /// Near segments by first sample.
    order: Vec<u32>,
    /// Segments whose stretch holds the current sample, in near order.
    active: Vec<u32>,
    /// Next in `order` to start, and the sample `active` holds.
    next: usize,
    sample: usize,
}

impl Spans {
    /// Ready for the samples 0..=n of `seg` against `near`, each segment
    /// looked at within `reach` of its index box.
    fn prepare(&mut self, seg: &Segment, n: usize, reach: f64, near: &[(u32, SegmentDistance, BBox)]) {
        self.spans.clear();
        self.order.clear();
        self.active.clear();
        self.next = 0;
        self.sample = 0;
        let (a, d) = (seg.a, seg.b.sub(seg.a));
        for (_, _, ib) in near {
            let span = if seg.bulge != 0.0 {
                Some((0, n))
            } else {
                let g = ib.grown(reach);
                let (x0, x1) = stretch(a.x, d.x, g.min.x, g.max.x);
                let (y0, y1) = stretch(a.y, d.y, g.min.y, g.max.y);
                let (t0, t1) = (x0.max(y0).max(0.0), x1.min(y1).min(1.0));
                (t0 <= t1).then(|| {
                    let k0 = ((t0 * n as f64).floor() as usize).saturating_sub(1);
                    let k1 = ((t1 * n as f64).ceil() as usize + 1).min(n);
                    (k0, k1)
                })
            };
            // A segment no sample comes near starts after the last one.
            self.spans.push(span.unwrap_or((n + 1, n + 1)));
        }
        self.order.extend(0..near.len() as u32);
        let spans = &self.spans;
        // Any order of equal starts: `active` keeps near order itself.
        self.order.sort_unstable_by_key(|&j| spans[j as usize].0);
    }

    /// The segments sample `k` looks at; `k` counts up from 0.
    fn at(&mut self, k: usize) -> &[u32] {
        debug_assert!(k >= self.sample);
        self.sample = k;
        let spans = &self.spans;
        self.active.retain(|&j| spans[j as usize].1 >= k);
        while let Some(&j) = self.order.get(self.next) {
            if spans[j as usize].0 > k {
                break;
            }
            self.next += 1;
            if spans[j as usize].1 >= k {
                let at = self.active.partition_point(|&x| x < j);
                self.active.insert(at, j);
            }
        }
        &self.active
    }
}

/// The parameters `t` where `a + d·t` lies in [lo, hi] (one coordinate),
/// widened by a part in a billion of the coordinates for rounding.
fn stretch(a: f64, d: f64, lo: f64, hi: f64) -> (f64, f64) {
    let eps = 1e-9 * (1.0 + a.abs() + d.abs() + lo.abs() + hi.abs());
    if d == 0.0 {
        return if a >= lo - eps && a <= hi + eps {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (f64::INFINITY, f64::NEG_INFINITY)
        };
    }
    let (u, v) = ((lo - eps - a) / d, (hi + eps - a) / d);
    (u.min(v), u.max(v))
}

/// True when `p` lies in the material of contour `c`: inside an outer
/// loop, outside a hole.
fn in_material(p: Point, c: &crate::contour::Contour) -> bool {
    point_in_loop(p, &c.segments) == (c.kind != ContourKind::Hole)
}

#[cfg(test)]
#[path = "closeness_tests.rs"]
mod tests;
