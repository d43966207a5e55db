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
use crate::fx::{FxMap, FxSet};
use crate::geom::{BBox, Point, Segment, SegmentDistance};
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
    cells: FxMap<(i64, i64), f64>,
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
            text!("the cuts take material from {n} part(s) ({list}) lying closer than the kerf ({kerf} mm) to another part's cut: up to {depth:.2} mm deep, about {area:.1} mm² (Verify sweeps the kerf in full)";
                  "os cortes removem material de {n} peça(s) ({list}) mais próximas que a sangria ({} mm) do corte de outra peça: até {} mm de profundidade, cerca de {} mm² (Verificar varre a sangria por completo)",
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
                for k in 0..=n {
                    let p = seg.point_at(k as f64 / n as f64);
                    // The nearest segment closer than the reach (the first
                    // of equals); samples with none take nothing.
                    let mut reach = r - slack;
                    let mut nearest = None;
                    for (i, sd, ib) in &near {
                        if ib.gap_sq(p).sqrt() > reach + slack {
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
                    let deepest = found.cells.entry(key).or_insert(0.0);
                    *deepest = deepest.max(depth.min(2.0 * r));
                    if let Some(part) = part_of(c) {
                        if !out.parts.contains(&part) {
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
    let mut cells: FxMap<(i64, i64), f64> = FxMap::default();
    for f in found {
        all.add(f.close);
        loops.extend(f.loops);
        for (k, d) in f.cells {
            let e = cells.entry(k).or_insert(0.0);
            *e = e.max(d);
        }
    }
    crate::sort::sort_indices(&mut all.parts);
    all.parts.dedup();
    all.loops = loops.iter().map(|&c| contours[c].source).collect();
    crate::sort::sort_by(&mut all.loops, Ord::cmp);
    all.loops.dedup();
    let mut cells: Vec<((i64, i64), f64)> = cells.into_iter().collect();
    crate::sort::sort_cells(&mut cells);
    all.cells = cells
        .into_iter()
        .map(|((i, j), d)| {
            let centre = Point::new((i as f64 + 0.5) * cell, (j as f64 + 0.5) * cell);
            (centre, d)
        })
        .collect();
    all
}

/// True when `p` lies in the material of contour `c`: inside an outer
/// loop, outside a hole.
fn in_material(p: Point, c: &crate::contour::Contour) -> bool {
    point_in_loop(p, &c.segments) == (c.kind != ContourKind::Hole)
}

#[cfg(test)]
#[path = "closeness_tests.rs"]
mod tests;
