//! Slots and notches of one part narrower than the kerf (issue 45 §1):
//! where two stretches of a part's outline face each other across the
//! scrap closer than the kerf width, the compensated path cannot enter
//! between them without cutting into their walls, so it passes by and the
//! material between them stays (the offset drops the loop it would make:
//! paper 000's invalid loops). The drawing asked for a cut there; the
//! operator is told where, how narrow, and about how much stays.
//!
//! Found on the drawn outline alone: at samples a quarter kerf apart, a ray
//! along the scrap-side normal; the first point where it meets the same
//! contour again is the feature's width there. Stretches narrower than the
//! kerf along at least a kerf's length are features (a sharp corner's
//! rounding, shorter, is the invalid-vertices warning's). Stretches whose
//! rays meet each other are the two walls of one feature.

use super::{crossing::crossings, PlanInput};
use crate::contour::{Contour, ContourKind};
use crate::geom::{nearest_param, BBox, Point, Segment};
use crate::par::Threads;
use crate::source::ContourRef;
use crate::text;
use crate::warning::{dec, Warning};

/// Contours a thread checks at least.
const CHUNK: usize = 256;

/// Features of parts narrower than the kerf.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Narrow {
    /// Parts with such features (1-based part numbers), ascending.
    pub parts: Vec<usize>,
    /// How many features (slots, notches).
    pub features: usize,
    /// The narrowest width found, mm.
    pub width: f64,
    /// Where.
    pub at: Option<Point>,
    /// Outline length along which the walls are closer than the kerf, mm.
    pub length: f64,
    /// Material left between them, mm² (about: width × length / 2).
    pub area: f64,
    /// The loops with such features, by identity (for the page to mark).
    pub loops: Vec<ContourRef>,
}

impl Narrow {
    fn add(&mut self, o: Narrow) {
        if o.features == 0 {
            return;
        }
        if self.features == 0 || o.width < self.width {
            self.width = o.width;
            self.at = o.at;
        }
        self.parts.extend(o.parts);
        self.loops.extend(o.loops);
        self.features += o.features;
        self.length += o.length;
        self.area += o.area;
    }

    /// The warning, or none without such features. `controller_comp`: the
    /// program leaves the offset to the controller (G41/G42).
    pub fn warning(&self, kerf: f64, controller_comp: bool) -> Option<Warning> {
        if self.features == 0 {
            return None;
        }
        let (n, parts) = (self.features, self.parts.len());
        let mut list: Vec<String> = self.parts.iter().take(10).map(|p| p.to_string()).collect();
        if parts > 10 {
            list.push("…".into());
        }
        let list = list.join(", ");
        let (width, length, area) = (self.width, self.length, self.area);
        let text = if controller_comp {
            text!("{n} slot(s) or notch(es) of {parts} part(s) ({list}) narrower than the kerf ({kerf} mm), down to {width:.2} mm wide along {length:.1} mm of outline: the controller's compensation cannot enter them without cutting into their walls (expect them uncut, about {area:.1} mm² left, or a gouging error)";
                  "{n} fenda(s) ou entalhe(s) de {parts} peça(s) ({list}) mais estreitos que a sangria ({} mm), com até {} mm de largura ao longo de {} mm de contorno: a compensação do controlador não entra neles sem cortar as paredes (espere-os sem corte, cerca de {} mm² restantes, ou um erro de goivagem)",
                  dec(kerf), dec(round2(width)), dec(round1(length)), dec(round1(area)))
        } else {
            text!("{n} slot(s) or notch(es) of {parts} part(s) ({list}) narrower than the kerf ({kerf} mm), down to {width:.2} mm wide along {length:.1} mm of outline: the kerf path cannot enter them without cutting into their walls, so they are left uncut (about {area:.1} mm² of material stays)";
                  "{n} fenda(s) ou entalhe(s) de {parts} peça(s) ({list}) mais estreitos que a sangria ({} mm), com até {} mm de largura ao longo de {} mm de contorno: o caminho da sangria não entra neles sem cortar as paredes, então ficam sem corte (cerca de {} mm² de material ficam)",
                  dec(kerf), dec(round2(width)), dec(round1(length)), dec(round1(area)))
        };
        let mut w = Warning::new("features-narrower-than-kerf", text);
        w.at = self.at;
        Some(w.with_loops(self.loops.iter().copied()))
    }
}

fn round1(x: f64) -> f64 {
    (x * 10.0).round() / 10.0
}

fn round2(x: f64) -> f64 {
    (x * 100.0).round() / 100.0
}

/// The features narrower than the kerf of every part contour the kerf
/// stage compensated.
pub fn narrow(input: &PlanInput, threads: Threads) -> Narrow {
    let w = input.process.kerf;
    let slack = 10.0 * input.tolerance.max(1e-6);
    // Also when the width is NaN.
    if w.is_nan() || w / 2.0 <= slack {
        return Narrow::default();
    }
    let contours = &input.contours.contours;
    let paths = &input.kerf.paths;
    let found = crate::par::map_ranges(paths.len(), threads, CHUNK, |range| {
        let mut out = Narrow::default();
        let mut scratch = Scratch::default();
        for p in &paths[range] {
            if let Some(c) = contours.get(p.contour) {
                if c.part.is_some() && c.is_closed() {
                    out.add(of_contour(c, w, slack, &mut scratch));
                }
            }
        }
        out
    });
    let mut all = Narrow::default();
    for f in found {
        all.add(f);
    }
    crate::sort::sort_indices(&mut all.parts);
    all.parts.dedup();
    all
}

/// One sample of the outline narrower than the kerf.
#[derive(Clone, Copy, Debug)]
struct Sample {
    /// Position along the contour, mm from its start.
    s: f64,
    /// Outline length it stands for, mm.
    step: f64,
    /// Distance across the scrap to the facing wall, mm.
    width: f64,
    /// Position along the contour of the facing wall's point.
    facing: f64,
    at: Point,
}

/// Buffers reused from contour to contour (a sheet has tens of thousands).
#[derive(Default)]
pub(crate) struct Scratch {
    start: Vec<f64>,
    boxes: Vec<BBox>,
    order: Vec<usize>,
    pairs: Vec<(usize, usize)>,
    samples: Vec<Sample>,
    /// Per segment, a line's start, unit direction, scrap-side unit normal
    /// and length ([`in_reach`]); `None` for arcs and points.
    frames: Vec<Option<Frame>>,
}

/// [`Scratch::frames`]' entry.
#[derive(Clone, Copy, Debug)]
struct Frame {
    start: Point,
    along: Point,
    normal: Point,
    len: f64,
}

impl Frame {
    fn of(s: &Segment, left_is_scrap: bool) -> Option<Frame> {
        let d = s.b.sub(s.a);
        let len = d.dot(d).sqrt();
        if !s.is_line() || len <= 0.0 || !len.is_finite() {
            return None;
        }
        let along = d.scale(1.0 / len);
        let normal = if left_is_scrap { along.perp() } else { along.perp().scale(-1.0) };
        Some(Frame { start: s.a, along, normal, len })
    }
}

/// [`narrow`] of one closed contour of a part, kerf width `w`.
pub(crate) fn of_contour(c: &Contour, w: f64, slack: f64, scratch: &mut Scratch) -> Narrow {
    let segs = &c.segments;
    let m = segs.len();
    if m == 0 || !segs.iter().all(Segment::is_finite) || is_circle(segs, slack) {
        return Narrow::default();
    }
    // The scrap lies left of travel in a clockwise outer or a counter-
    // clockwise hole.
    let left_is_scrap = (c.area > 0.0) == (c.kind == ContourKind::Hole);
    facing_pairs(segs, w, left_is_scrap, slack, scratch);
    if scratch.pairs.is_empty() {
        return Narrow::default();
    }
    let Scratch {
        start,
        pairs,
        samples,
        ..
    } = scratch;
    start.clear();
    start.push(0.0);
    for s in segs {
        start.push(start.last().copied().unwrap_or(0.0) + s.length());
    }
    let len = |i: usize| start[i + 1] - start[i];
    let step = w / 4.0;
    samples.clear();
    for run in pairs.chunk_by(|x, y| x.0 == y.0) {
        let a = run[0].0;
        if len(a) <= 0.0 {
            continue;
        }
        let seg = &segs[a];
        let n = (len(a) / step).ceil().max(1.0) as usize;
        for k in 0..n {
            let t = (k as f64 + 0.5) / n as f64;
            let p = seg.point_at(t);
            let left = seg.tangent_at(t).perp();
            let normal = if left_is_scrap {
                left
            } else {
                left.scale(-1.0)
            };
            let ray = Segment::line(p.add(normal.scale(slack)), p.add(normal.scale(w)));
            let mut best: Option<(f64, usize, Point)> = None;
            for &(_, b) in run {
                for q in crossings(&ray, &segs[b]).iter() {
                    let d = p.dist(q);
                    if d > slack && best.is_none_or(|(bd, _, _)| d < bd) {
                        best = Some((d, b, q));
                    }
                }
            }
            if let Some((d, b, q)) = best {
                if d < w - slack {
                    samples.push(Sample {
                        s: start[a] + t * len(a),
                        step: len(a) / n as f64,
                        width: d,
                        facing: start[b] + nearest_param(&segs[b], q) * len(b),
                        at: p,
                    });
                }
            }
        }
    }
    let mut found = features(samples, start[m], w, c.part);
    if found.features > 0 {
        found.loops.push(c.source);
    }
    found
}

/// True for a full circle (two arcs of one circle, as contours hold it): a
/// round hole the kerf did not make vanish is wider than the kerf, and an
/// outer circle has its scrap outside. A third of the nest of
/// benches/pipeline.rs is round holes.
fn is_circle(segs: &[Segment], slack: f64) -> bool {
    matches!(segs, [a, b] if same_circle(a, b, slack))
}

/// True when `a` and `b` are arcs of one circle (centres and radii within `slack`).
fn same_circle(a: &Segment, b: &Segment, slack: f64) -> bool {
    match (a.arc_center(), b.arc_center()) {
        (Some((ca, ra)), Some((cb, rb))) => ca.dist(cb) <= slack && (ra - rb).abs() <= slack,
        _ => false,
    }
}

/// Into `scratch.pairs`, sorted: `(a, b)` for each segment `a` and each
/// segment `b` of the same contour a scrap-side ray of length `w` from `a`
/// may meet ([`may_face`]) among those whose boxes come within `w`: most
/// segments of most parts have none and are not sampled.
fn facing_pairs(segs: &[Segment], w: f64, left_is_scrap: bool, slack: f64, scratch: &mut Scratch) {
    let Scratch {
        boxes,
        order,
        pairs,
        frames,
        ..
    } = scratch;
    let m = segs.len();
    boxes.clear();
    boxes.extend(segs.iter().map(Segment::bbox));
    frames.clear();
    frames.extend(segs.iter().map(|s| Frame::of(s, left_is_scrap)));
    order.clear();
    order.extend(0..m);
    order.sort_by(|&a, &b| boxes[a].min.x.total_cmp(&boxes[b].min.x));
    pairs.clear();
    for (i, &a) in order.iter().enumerate() {
        let grown = boxes[a].grown(w);
        for &b in &order[i..] {
            if boxes[b].min.x > grown.max.x {
                break;
            }
            if !grown.overlaps(&boxes[b], 0.0) {
                continue;
            }
            if in_reach(segs, frames, boxes, a, b, w, slack) && may_face(segs, a, b, w, left_is_scrap, slack) {
                pairs.push((a, b));
            }
            if a != b
                && in_reach(segs, frames, boxes, b, a, w, slack)
                && may_face(segs, b, a, w, left_is_scrap, slack)
            {
                pairs.push((b, a));
            }
        }
    }
    pairs.sort_unstable();
}

/// False when no scrap-side ray (length `w`) from a straight segment `a` can
/// reach `b`: the rays of a line sweep a rectangle (along `a`, then `w` across
/// towards the scrap), and `b` (its ends, or an arc's box) lies wholly past
/// one of its sides. Without it a finely sampled curve (a polyline of a
/// million vertices) paired each segment with the hundreds of its neighbours
/// that a kerf's width spans, to be sorted and cast at. Arcs `a` fan their
/// rays out: kept.
fn in_reach(
    segs: &[Segment],
    frames: &[Option<Frame>],
    boxes: &[BBox],
    a: usize,
    b: usize,
    w: f64,
    slack: f64,
) -> bool {
    let Some(f) = frames[a] else {
        return true;
    };
    if a == b {
        return true;
    }
    let sb = &segs[b];
    let (mut u0, mut u1, mut v0, mut v1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    let mut add = |q: Point| {
        let r = q.sub(f.start);
        let (u, v) = (r.dot(f.along), r.dot(f.normal));
        u0 = u0.min(u);
        u1 = u1.max(u);
        v0 = v0.min(v);
        v1 = v1.max(v);
    };
    if sb.is_line() {
        add(sb.a);
        add(sb.b);
    } else {
        let bx = &boxes[b];
        add(bx.min);
        add(bx.max);
        add(Point::new(bx.min.x, bx.max.y));
        add(Point::new(bx.max.x, bx.min.y));
    }
    // The rays start `slack` off `a` and end `w` off it; a margin of `slack` on every side.
    !(u1 < -slack || u0 > f.len + slack || v1 < 0.0 || v0 > w + slack)
}

/// True unless a scrap-side ray (length `w`) from segment `a` cannot meet
/// segment `b`: `a` itself, or another arc of its circle, unless it is an
/// arc bending towards the scrap narrower than `w` across; a neighbour that
/// `a` runs into smoothly, unless that neighbour bends towards the scrap;
/// a straight neighbour meeting a straight `a` at a corner that is not
/// acute on the scrap side. Everything else within `w` may be met.
fn may_face(segs: &[Segment], a: usize, b: usize, w: f64, left_is_scrap: bool, slack: f64) -> bool {
    let (sa, sb) = (&segs[a], &segs[b]);
    // An arc bends towards the scrap when its centre lies on the scrap side
    // (left of travel for a counter-clockwise arc); rays from it cross
    // its circle again 2r away.
    let bends = |s: &Segment| !s.is_line() && s.is_ccw() == left_is_scrap;
    let narrow_arc = |s: &Segment| bends(s) && s.arc_center().is_some_and(|(_, r)| 2.0 * r < w);
    if a == b || same_circle(sa, sb, slack) {
        return narrow_arc(sa);
    }
    let m = segs.len();
    // The corner walked into: first then second.
    let corner = if (a + 1) % m == b && sa.b.dist(sb.a) <= slack {
        Some((sa, sb))
    } else if (b + 1) % m == a && sb.b.dist(sa.a) <= slack {
        Some((sb, sa))
    } else {
        None
    };
    let Some((first, second)) = corner else {
        return true;
    };
    let (t1, t2) = (first.tangent_at(1.0), second.tangent_at(0.0));
    if t1.dot(t2) > 1.0 - 1e-6 {
        return bends(sb) || narrow_arc(sa);
    }
    if !(sa.is_line() && sb.is_line()) {
        return true;
    }
    // Turning by more than a right angle, towards the scrap.
    let towards_scrap = (t1.cross(t2) > 0.0) == left_is_scrap;
    t1.dot(t2) < 0.0 && towards_scrap
}

/// The samples in stretches (consecutive along the contour, the last one
/// joining the first round the start), stretches a kerf long or more kept,
/// and kept stretches whose rays meet each other joined into features.
fn features(samples: &[Sample], perimeter: f64, w: f64, part: Option<usize>) -> Narrow {
    if samples.is_empty() {
        return Narrow::default();
    }
    let near = |a: &Sample, b: &Sample, gap: f64| gap <= 0.5 * (a.step + b.step) * 1.01 + 1e-9;
    // Stretch number of each sample.
    let mut stretch = vec![0usize; samples.len()];
    let mut count = 1;
    for i in 1..samples.len() {
        if !near(
            &samples[i - 1],
            &samples[i],
            samples[i].s - samples[i - 1].s,
        ) {
            count += 1;
        }
        stretch[i] = count - 1;
    }
    let (first, last) = (&samples[0], &samples[samples.len() - 1]);
    if count > 1 && near(last, first, first.s + perimeter - last.s) {
        let wrap = count - 1;
        for s in stretch.iter_mut().filter(|s| **s == wrap) {
            *s = 0;
        }
        count -= 1;
    }
    let mut length = vec![0.0; count];
    for (s, &k) in samples.iter().zip(&stretch) {
        length[k] += s.step;
    }
    let kept = |k: usize| length[k] >= w;
    // Which stretch holds a position along the contour.
    // Which stretch holds a position along the contour (samples ascend).
    let stretch_at = |pos: f64| -> Option<usize> {
        let i = samples.partition_point(|s| s.s < pos);
        [i.checked_sub(1), Some(i)]
            .into_iter()
            .flatten()
            .filter(|&i| i < samples.len())
            .find(|&i| (samples[i].s - pos).abs() <= 0.5 * samples[i].step * 1.01 + 1e-9)
            .map(|i| stretch[i])
    };
    let mut root: Vec<usize> = (0..count).collect();
    fn find(root: &mut [usize], k: usize) -> usize {
        let mut k = k;
        while root[k] != k {
            root[k] = root[root[k]];
            k = root[k];
        }
        k
    }
    let mut out = Narrow::default();
    for (s, &k) in samples.iter().zip(&stretch) {
        if !kept(k) {
            continue;
        }
        if let Some(j) = stretch_at(s.facing).filter(|&j| kept(j)) {
            let (a, b) = (find(&mut root, k), find(&mut root, j));
            root[a] = b;
        }
        out.length += s.step;
        // The walls face each other: each counts half the material between.
        out.area += 0.5 * s.width * s.step;
        if out.at.is_none() || s.width < out.width {
            out.width = s.width;
            out.at = Some(s.at);
        }
    }
    let mut roots: Vec<usize> = (0..count)
        .filter(|&k| kept(k))
        .map(|k| find(&mut root, k))
        .collect();
    roots.sort_unstable();
    roots.dedup();
    out.features = roots.len();
    if out.features > 0 {
        out.parts.extend(part);
    }
    out
}

#[cfg(test)]
#[path = "narrow_tests.rs"]
mod tests;
