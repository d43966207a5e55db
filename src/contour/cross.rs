//! Loops that cross themselves, repaired into the outline of the region
//! they enclose (issue 45 §2).
//!
//! A loop that crosses or touches itself has no inside to offset from,
//! but the filled shape it draws has: the points of non-zero winding (the
//! rule PostScript, PDF and SVG fill by, and what the designer of a glyph
//! outline or a sloppy corner meant). The loop is split at its crossings;
//! between two crossings a run of the loop has one face on each side, so
//! the winding number on each side, taken once per run, decides it: a run
//! with winding 0 on one side and non-zero on the other is boundary, kept
//! with the filled side on its left; the rest is inside or outside. The
//! kept runs are chained at the crossings, at each one turning into the
//! next run met clockwise from the way back, which traces each face's
//! boundary on its own (de Berg et al., *Computational Geometry*, §2.2,
//! the doubly-connected edge list's "next" half-edge). Outers come out
//! counter-clockwise and holes clockwise; arcs stay arcs, split at the
//! crossings with the bulge of the swept fraction.
//!
//! Crossings are found by cavalier_contours' self-intersection search
//! (exact line–line, line–arc and arc–arc intersections over an index of
//! boxes), the one the kerf stage refuses such loops with. That search
//! also finds places where a loop only touches itself (at a vertex) or
//! runs back over itself (a zero-width spike, a doubled edge). A loop that
//! only does that can be drawn without crossing: all its winding numbers
//! are 0 or one sign's 1 (a perturbed simple curve's). Split at its
//! touches it would come apart into lobes, parts the designer drew as one
//! outline (lines of a garment's internal marks drawn there and back,
//! graded sizes meeting at a point), so such a loop is repaired only when
//! its region stays one part (a spike dropped, a pinched hole made a
//! hole), and otherwise left as drawn and said.

use std::collections::HashMap;

use cavalier_contours::core::Control;
use cavalier_contours::polyline::{
    PlineBasicIntersect, PlineIntersect, PlineSelfIntersectOptions, PlineSource, PlineSourceMut,
    Polyline, SelfIntersectsInclude,
};

use super::chain::{Chain, Measure};
use super::heal::{HealKind, Healing};
use crate::geom::{loop_area, path_bbox, Point, Segment, Tolerance};
use crate::par::Threads;
use crate::text;
use crate::warning::{dec, Warning};

/// More crossings than this in one loop: not a sloppy corner but a
/// scribble, left as it is (the kerf stage names it).
const MAX_CROSSINGS: usize = 20_000;

/// What became of one loop.
#[derive(Debug)]
pub(super) enum Outcome {
    /// It neither crosses nor touches itself.
    Simple,
    /// The outline(s) of its non-zero region.
    Repaired(Repair),
    /// It crosses itself and encloses nothing (or only slivers): left out.
    Empty {
        /// The first crossing.
        at: Point,
        /// How many places it crosses or touches itself.
        crossings: usize,
    },
    /// It crosses itself but could not be taken apart with confidence
    /// (too many crossings, or a face too thin to tell its sides): left
    /// as it is, for the kerf stage to refuse and name.
    Unresolved,
    /// It touches or runs back over itself without crossing, and its
    /// region would come apart into several parts there: left as drawn
    /// (the kerf stage refuses it, as without the repair), said.
    Touching {
        /// The first place.
        at: Point,
        /// How many places it touches itself.
        places: usize,
        /// The parts it would have become.
        lobes: usize,
    },
}

/// A repaired loop.
#[derive(Debug)]
pub(super) struct Repair {
    /// The region's boundary loops: outers counter-clockwise, holes clockwise.
    pub loops: Vec<Vec<Segment>>,
    /// How many places it crossed or touched itself.
    pub crossings: usize,
    /// The first of them.
    pub at: Point,
    /// A point filled by the non-zero rule that the even-odd rule would
    /// leave empty (winding ±2 or more: a pentagram's centre), if any.
    pub even_odd_differs: Option<Point>,
    /// Pieces enclosing no area, dropped.
    pub slivers: usize,
    /// It only touches or runs back over itself (no winding number but 0
    /// and one sign's 1): nothing crosses.
    pub touch_only: bool,
}

/// Loops that cross themselves among `chains` replaced by the loops of
/// their region (in their place, with their entities: the layer and
/// references follow), each repair recorded in `healing` and warned;
/// loops enclosing nothing dropped and named. Chains without a crossing
/// are returned untouched.
pub(super) fn repair_chains(
    mut chains: Vec<Chain>,
    tol: Tolerance,
    threads: Threads,
    healing: &mut Healing,
    warnings: &mut Vec<Warning>,
) -> Vec<Chain> {
    // The kerf stage's point equality, so a loop it would refuse is one found here.
    let eps = tol.mm().min(1e-5);
    let is_loop = |c: &Chain| c.closed && c.measure.area.abs() > tol.mm() * c.measure.length;
    // A closed chain whose signed area cancels (a symmetric bow tie) may
    // still enclose a region; one that encloses nothing stays as it was
    // (open, "closed-no-area").
    let found: Vec<(usize, Outcome)> = crate::par::map_ranges(chains.len(), threads, 256, |r| {
        r.filter(|&i| chains[i].closed)
            .filter_map(|i| match repair(&chains[i].segments, eps, tol.mm()) {
                Outcome::Simple => None,
                Outcome::Empty { .. } | Outcome::Unresolved | Outcome::Touching { .. }
                    if !is_loop(&chains[i]) =>
                {
                    None
                }
                o => Some((i, o)),
            })
            .collect::<Vec<_>>()
    })
    .into_iter()
    .flatten()
    .collect();
    if found.is_empty() {
        return chains;
    }
    let mut out = Vec::with_capacity(chains.len() + found.len());
    let mut next = 0;
    let mut rest = chains.drain(..);
    for (i, outcome) in found {
        out.extend(rest.by_ref().take(i - next));
        next = i + 1;
        let Some(c) = rest.next() else { break };
        match outcome {
            Outcome::Simple | Outcome::Unresolved => out.push(c),
            Outcome::Touching { at, places, lobes } => {
                warnings.push(
                    Warning::at(
                        "self-touching-kept",
                        text!("outline touches or runs back over itself at {places} place(s) without crossing: left as drawn, not repaired (it would come apart into {lobes} parts)";
                              "contorno toca ou volta sobre si mesmo em {places} lugar(es) sem se cruzar: deixado como desenhado, sem reparo (ele se partiria em {lobes} peças)"),
                        at,
                    )
                    .of_kind(
                        text!("outline touches or runs back over itself without crossing: left as drawn, not repaired";
                              "contorno toca ou volta sobre si mesmo sem se cruzar: deixado como desenhado, sem reparo"),
                        text!("({:.3}, {:.3})", at.x, at.y; "({:.3}; {:.3})", dec(at.x), dec(at.y)),
                    ),
                );
                out.push(c);
            }
            Outcome::Empty { at, crossings: n } => warnings.push(
                Warning::at(
                    "self-crossing-empty",
                    text!("outline crosses itself ({n} place(s)) and encloses no area: left out";
                          "contorno cruza a si mesmo ({n} lugar(es)) e não encerra área: deixado de fora"),
                    at,
                )
                .of_kind(
                    text!("outline crosses itself and encloses no area: left out";
                          "contorno cruza a si mesmo e não encerra área: deixado de fora"),
                    text!("({:.3}, {:.3})", at.x, at.y; "({:.3}; {:.3})", dec(at.x), dec(at.y)),
                ),
            ),
            Outcome::Repaired(r) => {
                healing.add(HealKind::SelfCrossing, r.at);
                warnings.push(repaired(&r));
                for segments in r.loops {
                    out.push(Chain {
                        measure: Measure::of(&segments),
                        segments,
                        closed: true,
                        entities: c.entities.clone(),
                        shares_edges: c.shares_edges,
                    });
                }
            }
        }
    }
    out.extend(rest);
    out
}

/// The warning of one repair: where, into what, and where the even-odd
/// rule would have filled less.
fn repaired(r: &Repair) -> Warning {
    let (n, k, at) = (r.crossings, r.loops.len(), r.at);
    let mut w = Warning::at(
        "self-crossing-repaired",
        if r.touch_only {
            text!("outline touched or ran back over itself at {n} place(s), first at ({:.3}, {:.3}): cut as the {k} outline(s) of the one part it encloses, the lines drawn there and back not cut",
                  at.x, at.y;
                  "contorno tocava ou voltava sobre si mesmo em {n} lugar(es), o primeiro em ({:.3}; {:.3}): cortado como o(s) {k} contorno(s) da peça que encerra, sem as linhas desenhadas de ida e volta",
                  dec(at.x), dec(at.y))
        } else {
            text!("outline crossed itself at {n} place(s), first at ({:.3}, {:.3}): cut as the {k} outline(s) of the region it encloses (non-zero rule)",
                  at.x, at.y;
                  "contorno cruzava a si mesmo em {n} lugar(es), o primeiro em ({:.3}; {:.3}): cortado como o(s) {k} contorno(s) da região que encerra (regra do enrolamento não nulo)",
                  dec(at.x), dec(at.y))
        },
        at,
    );
    if r.slivers > 0 {
        let s = r.slivers;
        w.text.en += &format!("; {s} piece(s) enclosing no area left out");
        w.text.pt += &format!("; {s} trecho(s) sem área deixado(s) de fora");
    }
    if let Some(p) = r.even_odd_differs {
        w.text.en += &format!(
            "; the even-odd rule would leave a region around ({:.3}, {:.3}) empty",
            p.x, p.y
        );
        w.text.pt += &format!(
            "; a regra par-ímpar deixaria vazia uma região em torno de ({:.3}; {:.3})",
            dec(p.x),
            dec(p.y)
        );
    }
    let kind = if r.touch_only {
        text!("outline touching or running back over itself repaired (one part)";
              "contorno que toca ou volta sobre si mesmo reparado (uma peça)")
    } else if r.even_odd_differs.is_some() {
        text!("self-crossing outline repaired by the non-zero rule (the even-odd rule would fill less)";
              "contorno que cruza a si mesmo reparado pela regra do enrolamento não nulo (a regra par-ímpar preencheria menos)")
    } else {
        text!("self-crossing outline repaired"; "contorno que cruza a si mesmo reparado")
    };
    w.of_kind(
        kind,
        text!("({:.3}, {:.3})", at.x, at.y; "({:.3}; {:.3})", dec(at.x), dec(at.y)),
    )
}

/// The winding number of `segs` (a closed loop) around `p`: the angle each
/// segment subtends at `p`, summed, in turns. An arc subtends its chord's
/// angle plus a full turn, signed by its direction, when `p` lies between
/// chord and arc (the loop arc + chord back encloses just that segment of
/// the disc).
pub(super) fn winding(segs: &[Segment], p: Point) -> i64 {
    let mut total = 0.0;
    for s in segs {
        let (u, v) = (s.a.sub(p), s.b.sub(p));
        total += u.cross(v).atan2(u.dot(v));
        if let Some((c, r)) = s.arc_center() {
            let chord = s.b.sub(s.a);
            // A counter-clockwise arc bulges to the right of its chord.
            let right = chord.cross(p.sub(s.a)) < 0.0;
            if p.dist(c) < r && right == s.is_ccw() {
                total += std::f64::consts::TAU.copysign(s.bulge);
            }
        }
    }
    (total / std::f64::consts::TAU).round() as i64
}

/// Where `p` (on `s`, or within a crossing's snap of it) lies along `s`, 0 to 1.
fn param(s: &Segment, p: Point) -> f64 {
    let t = match s.arc_angles() {
        Some((c, _, start, sweep)) => {
            let v = p.sub(c);
            let mut d = v.y.atan2(v.x) - start;
            // Into the sweep's direction, within one turn.
            let tau = std::f64::consts::TAU;
            if sweep > 0.0 {
                d = d.rem_euclid(tau);
                if d > sweep + 0.5 * (tau - sweep) {
                    d -= tau;
                }
            } else {
                d = -((-d).rem_euclid(tau));
                if d < sweep - 0.5 * (tau + sweep) {
                    d += tau;
                }
            }
            d / sweep
        }
        None => {
            let d = s.b.sub(s.a);
            let l2 = d.dot(d);
            if l2 > 0.0 {
                p.sub(s.a).dot(d) / l2
            } else {
                0.0
            }
        }
    };
    t.clamp(0.0, 1.0)
}

/// The part of `s` from parameter `t0` (at `a`) to `t1` (at `b`).
fn piece(s: &Segment, t0: f64, a: Point, t1: f64, b: Point) -> Segment {
    let bulge = if s.is_line() {
        0.0
    } else {
        (s.sweep() * (t1 - t0) / 4.0).tan()
    };
    Segment { a, b, bulge }
}

/// Crossing points merged within `snap`: each hit's vertex number.
struct Nodes {
    at: Vec<Point>,
    cells: HashMap<(i64, i64), Vec<usize>>,
    snap: f64,
}

impl Nodes {
    fn id(&mut self, p: Point) -> usize {
        let cell = |v: f64| (v / (2.0 * self.snap)).floor() as i64;
        let (cx, cy) = (cell(p.x), cell(p.y));
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(ids) = self.cells.get(&(cx + dx, cy + dy)) {
                    if let Some(&i) = ids.iter().find(|&&i| self.at[i].dist(p) <= self.snap) {
                        return i;
                    }
                }
            }
        }
        self.at.push(p);
        self.cells
            .entry((cx, cy))
            .or_default()
            .push(self.at.len() - 1);
        self.at.len() - 1
    }
}

/// Where the closed loop `segs` crosses, touches or runs along itself,
/// as (segment, segment, point); empty for a simple loop. `eps` is the
/// library's point equality.
fn hits(segs: &[Segment], eps: f64) -> Vec<(usize, usize, Point)> {
    let n = segs.len();
    // Two segments between the same two points meet only there (two
    // circles, or a circle and a line, meet in at most two points).
    if n < 3 || !segs.iter().all(Segment::is_finite) {
        return Vec::new();
    }
    if n <= 8 && no_box_pairs(segs, eps) {
        return Vec::new();
    }
    let mut pl = Polyline::<f64>::new();
    pl.set_is_closed(true);
    pl.reserve(n);
    for s in segs {
        pl.add(s.a.x, s.a.y, s.bulge);
    }
    let index = pl.create_aabb_index();
    let mut out = Vec::new();
    let pt = |v: cavalier_contours::core::math::Vector2<f64>| Point::new(v.x, v.y);
    pl.visit_self_intersects_opt(
        &mut |x: PlineIntersect<f64>| {
            match x {
                PlineIntersect::Basic(PlineBasicIntersect {
                    start_index1: i,
                    start_index2: j,
                    point,
                }) => out.push((i, j, pt(point))),
                PlineIntersect::Overlapping(o) => {
                    out.push((o.start_index1, o.start_index2, pt(o.point1)));
                    out.push((o.start_index1, o.start_index2, pt(o.point2)));
                }
            }
            // Stop past the cap: the loop is left as it is then.
            if out.len() > MAX_CROSSINGS {
                Control::Break(())
            } else {
                Control::Continue
            }
        },
        &PlineSelfIntersectOptions {
            aabb_index: Some(&index),
            pos_equal_eps: eps,
            include: SelfIntersectsInclude::All,
        },
    );
    out
}

/// True when no two segments of a small loop, other than neighbours, have
/// overlapping boxes: nothing to search (a rectangle, a slot).
fn no_box_pairs(segs: &[Segment], eps: f64) -> bool {
    let n = segs.len();
    let boxes: Vec<_> = segs.iter().map(|s| s.bbox().grown(eps)).collect();
    (0..n).all(|i| {
        let last = if i == 0 { n - 1 } else { n };
        (i + 2..last).all(|j| !boxes[i].overlaps(&boxes[j], 0.0))
    })
}

/// The loop `segs` (closed, each start the previous end) repaired, or
/// [`Outcome::Simple`] when it does not cross itself. `eps` is the point
/// equality of the crossing search, `tol` the drawing's tolerance:
/// crossings closer than it are one, and a piece must enclose more than
/// `tol` times its length to be a loop (the contour stage's rule).
pub(super) fn repair(segs: &[Segment], eps: f64, tol: f64) -> Outcome {
    let found = hits(segs, eps);
    if found.is_empty() {
        return Outcome::Simple;
    }
    if found.len() > MAX_CROSSINGS {
        return Outcome::Unresolved;
    }
    match split(segs, &found, tol) {
        Some(r) if r.loops.is_empty() => Outcome::Empty {
            at: r.at,
            crossings: r.crossings,
        },
        // Outers come out counter-clockwise: more than one is more parts
        // than the one outline drawn, which only a crossing may make.
        Some(r) if r.touch_only && outers(&r.loops) > 1 => Outcome::Touching {
            at: r.at,
            places: r.crossings,
            lobes: outers(&r.loops),
        },
        Some(r) => Outcome::Repaired(r),
        None => Outcome::Unresolved,
    }
}

/// How many of `loops` are outers (counter-clockwise).
fn outers(loops: &[Vec<Segment>]) -> usize {
    loops.iter().filter(|l| loop_area(l) > 0.0).count()
}

/// A run of the loop from one crossing to the next.
struct Run {
    segs: Vec<Segment>,
    from: usize,
    to: usize,
}

/// The non-zero region's boundary of `segs`, crossing it at `found`; None
/// when its faces cannot be told apart with confidence.
fn split(segs: &[Segment], found: &[(usize, usize, Point)], tol: f64) -> Option<Repair> {
    let n = segs.len();
    let mut nodes = Nodes {
        at: Vec::new(),
        cells: HashMap::new(),
        snap: tol,
    };
    // Each segment's crossings inside it, and the crossing (if any) at
    // each vertex (vertex k starts segment k).
    let mut inner: Vec<Vec<(f64, usize)>> = vec![Vec::new(); n];
    let mut corner: Vec<Option<usize>> = vec![None; n];
    for &(i, j, p) in found {
        let v = nodes.id(p);
        for k in [i, j] {
            let s = segs.get(k)?;
            let q = nodes.at[v];
            if q.dist(s.a) <= tol {
                corner[k] = Some(v);
            } else if q.dist(s.b) <= tol {
                corner[(k + 1) % n] = Some(v);
            } else {
                inner[k].push((param(s, q), v));
            }
        }
    }
    let crossings = nodes.at.len();
    let first = nodes.at[0];
    // The loop as pieces, each with the crossing it ends at.
    let mut pieces: Vec<(Segment, Option<usize>)> = Vec::with_capacity(n + 2 * found.len());
    for k in 0..n {
        let s = &segs[k];
        let mut stops = std::mem::take(&mut inner[k]);
        stops.sort_by(|a, b| a.0.total_cmp(&b.0));
        stops.dedup_by_key(|x| x.1);
        let mut from = (0.0, corner[k].map_or(s.a, |v| nodes.at[v]));
        for (t, v) in stops {
            let p = nodes.at[v];
            if p != from.1 {
                pieces.push((piece(s, from.0, from.1, t, p), Some(v)));
            } else if let Some(last) = pieces.last_mut() {
                // Snapped onto the vertex it starts at: that is where it ends.
                last.1 = Some(v);
            }
            from = (t, p);
        }
        let end = corner[(k + 1) % n];
        let b = end.map_or(s.b, |v| nodes.at[v]);
        if b != from.1 {
            pieces.push((piece(s, from.0, from.1, 1.0, b), end));
        } else if let (Some(last), Some(_)) = (pieces.last_mut(), end) {
            last.1 = end;
        }
    }
    // Runs from crossing to crossing, starting after the first.
    let start = pieces.iter().position(|p| p.1.is_some())? + 1;
    let m = pieces.len();
    let mut runs: Vec<Run> = Vec::new();
    let mut cur: Vec<Segment> = Vec::new();
    let mut from = pieces[start - 1].1?;
    for k in 0..m {
        let (s, end) = pieces[(start + k) % m];
        cur.push(s);
        if let Some(v) = end {
            runs.push(Run {
                segs: std::mem::take(&mut cur),
                from,
                to: v,
            });
            from = v;
        }
    }
    let scale = {
        let bb = path_bbox(segs);
        (bb.max.x - bb.min.x)
            .abs()
            .max((bb.max.y - bb.min.y).abs())
            .max(bb.max.x.abs().max(bb.max.y.abs()))
    };
    let all: Vec<Segment> = runs.iter().flat_map(|r| r.segs.iter().copied()).collect();
    let mut kept: Vec<Run> = Vec::new();
    let mut even_odd_differs = None;
    // The signs of the winding numbers met. Around a crossing the four
    // corners wind w, w + 1, w + 1, w + 2 (each strand changes it by one):
    // three values, so a 2 or both signs met is a crossing, and a loop
    // meeting only 0 and one sign's 1 merely touches or retraces itself.
    // Every corner at a crossing is met: it lies beside a run's side.
    let (mut positive, mut negative) = (false, false);
    for run in runs {
        // The run's longest piece, sampled at its middle, each side at
        // half the distance to the nearest other piece.
        let s = *run
            .segs
            .iter()
            .max_by(|a, b| a.length().total_cmp(&b.length()))?;
        let m = s.point_at(0.5);
        let left = s.tangent_at(0.5).perp();
        let near = all
            .iter()
            .filter(|o| **o != s)
            .map(|o| crate::geom::dist_to_segment(m, o))
            // Pieces through m run along this one (an overlap): both sides
            // are off them too.
            .filter(|&d| d > 1e-9 * scale)
            .fold(f64::INFINITY, f64::min);
        let d = (0.5 * near).min(0.25 * s.length());
        // Too close to tell the sides apart in floating point (or NaN).
        if d.is_nan() || d <= 1e-9 * scale.max(1.0) {
            return None;
        }
        let wl = winding(segs, m.add(left.scale(d)));
        let wr = winding(segs, m.sub(left.scale(d)));
        for (w, side) in [(wl, d), (wr, -d)] {
            positive |= w > 0;
            negative |= w < 0;
            if w.abs() >= 2 && even_odd_differs.is_none() {
                even_odd_differs = Some(m.add(left.scale(side)));
            }
        }
        match (wl != 0, wr != 0) {
            (true, false) => kept.push(run),
            (false, true) => kept.push(Run {
                segs: run.segs.iter().rev().map(Segment::reversed).collect(),
                from: run.to,
                to: run.from,
            }),
            _ => {}
        }
    }
    dedup_overlaps(&mut kept);
    let loops = chain(&kept)?;
    let (mut out, mut slivers) = (Vec::new(), 0);
    for l in loops {
        let len: f64 = l.iter().map(Segment::length).sum();
        if loop_area(&l).abs() > tol * len {
            out.push(l);
        } else {
            slivers += 1;
        }
    }
    let touch_only = !(positive && negative) && even_odd_differs.is_none();
    Some(Repair {
        loops: out,
        crossings,
        at: first,
        even_odd_differs,
        slivers,
        touch_only,
    })
}

/// Drops all but one of kept runs drawn over one another (a loop that
/// runs back along itself keeps the shared edge once).
fn dedup_overlaps(kept: &mut Vec<Run>) {
    let key = |r: &Run| {
        let mid = r.segs[r.segs.len() / 2].point_at(0.5);
        (r.from, r.to, mid)
    };
    let mut i = 0;
    while i < kept.len() {
        let (f, t, m) = key(&kept[i]);
        let same = kept[..i].iter().any(|o| {
            let (g, u, p) = key(o);
            g == f && u == t && p.dist(m) < 1e-9 * (1.0 + m.norm())
        });
        if same {
            kept.remove(i);
        } else {
            i += 1;
        }
    }
}

/// The kept runs chained into loops at the crossings: arriving at one,
/// the next run is the first met turning clockwise from the way back,
/// so each face's boundary closes on itself. None if a run leads nowhere.
fn chain(kept: &[Run]) -> Option<Vec<Vec<Segment>>> {
    let mut leaving: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, r) in kept.iter().enumerate() {
        leaving.entry(r.from).or_default().push(i);
    }
    let mut used = vec![false; kept.len()];
    let mut loops = Vec::new();
    for first in 0..kept.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let mut segs = kept[first].segs.clone();
        let mut at = first;
        // Each step uses a run: at most as many steps as runs. The first
        // run is a candidate again where it starts: chosen, the face closes.
        for _ in 0..=kept.len() {
            let here = kept[at].to;
            let back = segs.last()?.tangent_at(1.0).scale(-1.0);
            let cw = |k: usize| {
                let out = kept[k].segs[0].tangent_at(0.0);
                let a = (-back.cross(out).atan2(back.dot(out))).rem_euclid(std::f64::consts::TAU);
                if a == 0.0 {
                    std::f64::consts::TAU
                } else {
                    a
                }
            };
            let next = leaving
                .get(&here)?
                .iter()
                .copied()
                .filter(|&i| !used[i] || i == first)
                .min_by(|&i, &j| cw(i).total_cmp(&cw(j)))?;
            if next == first {
                break;
            }
            used[next] = true;
            segs.extend_from_slice(&kept[next].segs);
            at = next;
        }
        if kept[at].to != kept[first].from {
            return None;
        }
        loops.push(segs);
    }
    Some(loops)
}

#[cfg(test)]
#[path = "cross_tests.rs"]
mod tests;
