//! Parts that touch (issue 14, item 3): drawn with a common edge, as paper
//! 003's fabric grid or a nest exported with no gap. Their kerf paths run
//! inside each other; cutting both would take a whole kerf from each part
//! along the common edge and leave a sliver between. What such a drawing
//! asks for is one cut along the common edge: it is cut on the drawn line
//! (each part loses half the kerf there, as the spacing warning says), and
//! round the outside the parts' kerf paths are kept where they cut into no
//! part, joined to the common edges' ends by the shortest straight connector.
//!
//! - Common edges: pieces of drawn outlines that two parts drew ([`graph`]
//!   merges them).
//! - Kerf paths of the touching parts are split where they cross one another
//!   and a piece is kept only if its middle is in scrap, half a kerf from
//!   every part ([`Scrap::point_ok`]).
//! - Each end of a common edge where the contact ends (one common edge
//!   there) is joined to the nearest point of a kept piece.

use super::graph::{self, param};
use crate::contour::ContourKind;
use crate::fx::FxSet;
use crate::geom::{angle_in_sweep, dist_to_segment, BBox, Point, Segment};
use crate::plan::clearance::crossings;
use crate::plan::scrap::Scrap;
use crate::plan::PlanInput;

/// What replaces the kerf paths of touching parts.
pub struct Touching {
    /// Contours whose kerf paths are replaced.
    pub replaced: FxSet<usize>,
    /// Kept path pieces, common edges and connectors, each with a contour.
    pub segments: Vec<(Segment, usize)>,
}

/// The cut of touching parts, or None when no two parts share an edge.
/// Only the contours `cut` takes are looked at.
pub fn common_edges(
    input: &PlanInput,
    scrap: &Scrap,
    kerf: f64,
    tol: f64,
    cut: &dyn Fn(usize) -> bool,
) -> Option<Touching> {
    let contours = &input.contours.contours;
    let drawn: Vec<(Segment, usize)> = contours
        .iter()
        .enumerate()
        .filter(|&(i, c)| c.kind == ContourKind::Outer && cut(i))
        .flat_map(|(i, c)| c.segments.iter().map(move |s| (*s, i)))
        .collect();
    let g = graph::build(&drawn, tol);
    let shared: Vec<&graph::Edge> = g.edges.iter().filter(|e| e.also.is_some()).collect();
    if shared.is_empty() {
        return None;
    }
    let mut replaced = FxSet::default();
    let mut pairs = FxSet::default();
    for e in &shared {
        let (a, b) = (e.contour, e.also.unwrap_or(e.contour));
        replaced.insert(a);
        replaced.insert(b);
        pairs.insert((a.min(b), a.max(b)));
    }
    // The touching parts' kerf paths, with the points where they cross.
    let paths: Vec<(Segment, usize)> = input
        .kerf
        .paths
        .iter()
        .filter(|p| replaced.contains(&p.contour))
        .flat_map(|p| p.segments.iter().map(move |s| (*s, p.contour)))
        .filter(|(s, _)| s.is_finite())
        .collect();
    // Pairs of pieces whose boxes meet, by a sweep along x: testing every
    // pair was most of a graded garment pattern's plan (thousands of
    // touching pieces). Each piece's crossings are sorted by `split`, so the
    // order pairs are met in does not matter.
    let boxes: Vec<BBox> = paths.iter().map(|(s, _)| s.bbox()).collect();
    let mut by_x: Vec<usize> = (0..paths.len()).collect();
    crate::sort::sort_by(&mut by_x, |&a, &b| boxes[a].min.x.total_cmp(&boxes[b].min.x));
    let mut cuts: Vec<Vec<Point>> = vec![Vec::new(); paths.len()];
    for (k, &i) in by_x.iter().enumerate() {
        for &j in &by_x[k + 1..] {
            if boxes[j].min.x > boxes[i].max.x + tol {
                break;
            }
            let (ci, cj) = (paths[i].1, paths[j].1);
            if ci == cj || !boxes[i].overlaps(&boxes[j], tol) || !pairs.contains(&(ci.min(cj), ci.max(cj))) {
                continue;
            }
            for x in meet(&paths[i].0, &paths[j].0) {
                cuts[i].push(x);
                cuts[j].push(x);
            }
        }
    }
    let mut segments = Vec::new();
    let mut kept: Vec<Segment> = Vec::new();
    for ((s, c), at) in paths.iter().zip(cuts) {
        for piece in split(s, &at, tol) {
            if scrap.point_ok(piece.point_at(0.5)) {
                kept.push(piece);
                segments.push((piece, *c));
            }
        }
    }
    let mut degree = vec![0usize; g.vertices.len()];
    for e in &shared {
        degree[e.u] += 1;
        degree[e.v] += 1;
        // Once for each part: the graph merges them into one edge of both.
        segments.push((e.seg, e.contour));
        segments.push((e.seg, e.also.unwrap_or(e.contour)));
    }
    for e in &shared {
        for v in [e.u, e.v] {
            if degree[v] != 1 {
                continue;
            }
            let p = g.vertices[v];
            let near = kept
                .iter()
                .map(|s| nearest_on(s, p))
                .min_by(|a, b| a.dist(p).total_cmp(&b.dist(p)));
            // The kept path round the contact's end is half a kerf or so away.
            if let Some(q) = near.filter(|q| q.dist(p) <= 2.0 * kerf && q.dist(p) > tol) {
                segments.push((Segment::line(p, q), e.contour));
            }
        }
    }
    Some(Touching { replaced, segments })
}

/// `s` cut at the points `at` (those on its inside).
fn split(s: &Segment, at: &[Point], tol: f64) -> Vec<Segment> {
    let mut ts: Vec<f64> = at
        .iter()
        .filter(|p| p.dist(s.a) > tol && p.dist(s.b) > tol)
        .map(|p| param(s, *p))
        .filter(|t| *t > 0.0 && *t < 1.0)
        .collect();
    crate::sort::sort_floats(&mut ts);
    ts.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let mut out = Vec::with_capacity(ts.len() + 1);
    let mut from = 0.0;
    for t in ts.into_iter().chain([1.0]) {
        let (a, b) = (s.point_at(from), if t >= 1.0 { s.b } else { s.point_at(t) });
        let a = if from <= 0.0 { s.a } else { a };
        let bulge = if s.is_line() {
            0.0
        } else {
            (s.sweep() * (t - from) / 4.0).tan()
        };
        if a.dist(b) > tol {
            out.push(Segment { a, b, bulge });
        }
        from = t;
    }
    out
}

/// Where two segments (lines or arcs) meet.
fn meet(a: &Segment, b: &Segment) -> Vec<Point> {
    if a.is_line() {
        return crossings(a, b).iter().collect();
    }
    if b.is_line() {
        return crossings(b, a).iter().collect();
    }
    let (Some((c1, r1)), Some((c2, r2))) = (a.arc_center(), b.arc_center()) else {
        return Vec::new();
    };
    let d = c1.dist(c2);
    if d <= 1e-12 || d > r1 + r2 || d < (r1 - r2).abs() {
        return Vec::new();
    }
    let x = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
    let h = (r1 * r1 - x * x).max(0.0).sqrt();
    let u = c2.sub(c1).scale(1.0 / d);
    let m = c1.add(u.scale(x));
    [m.add(u.perp().scale(h)), m.sub(u.perp().scale(h))]
        .into_iter()
        .filter(|p| on_arc(a, *p) && on_arc(b, *p))
        .collect()
}

fn on_arc(s: &Segment, p: Point) -> bool {
    match s.arc_center() {
        Some((c, _)) => {
            let (a0, v) = (s.a.sub(c), p.sub(c));
            angle_in_sweep(a0.y.atan2(a0.x), s.sweep(), v.y.atan2(v.x))
        }
        None => dist_to_segment(p, s) <= 1e-9,
    }
}

/// The point of `s` nearest `p`.
fn nearest_on(s: &Segment, p: Point) -> Point {
    match s.arc_center() {
        Some((c, r)) if on_arc(s, p) && p.dist(c) > 0.0 => c.add(p.sub(c).scale(r / p.dist(c))),
        Some(_) => {
            if p.dist(s.a) <= p.dist(s.b) {
                s.a
            } else {
                s.b
            }
        }
        None => {
            let d = s.b.sub(s.a);
            let len2 = d.dot(d);
            if len2 <= 0.0 {
                return s.a;
            }
            let t = (p.sub(s.a).dot(d) / len2).clamp(0.0, 1.0);
            s.a.add(d.scale(t))
        }
    }
}
