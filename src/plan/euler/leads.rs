//! Entries and exits of the Eulerian order's cuts (issue 14, item 5).
//!
//! A thermal torch leaves a blob where it pierces (paper 001 §2.1, L413): it
//! must pierce in scrap and come onto the path by a lead-in. Each cut's
//! pierce gets a straight lead-in square to the path, on whichever side of
//! it is scrap ([`Scrap::line_ok`], with the pierce a kerf clear of every
//! part). Between kerf-spaced parts neither side is scrap, so a closed
//! circuit is entered at another of its vertices, the nearest to where the
//! planner meant to start that takes a lead. A closed circuit ends with the
//! overcut asked for, past its start along what it cut first. With no kerf (a
//! knife, paper 003) cuts start on the line as before.

use super::circuit::Link;
use super::graph::Graph;
use super::Kind;
use crate::contour::{ContourKind, Contours};
use crate::geom::{Point, Segment};
use crate::plan::clearance::Obstacles;
use crate::plan::scrap::Scrap;
use crate::plan::{LeadKind, LeadOptions};

/// Most vertices of a circuit tried as its entry.
const MAX_TRIES: usize = 16;

/// What a trail needs to be entered and left.
pub struct Ends<'a> {
    /// The parts.
    pub scrap: &'a Scrap<'a>,
    /// The drawn contours, for the pierce clearance.
    pub obstacles: &'a Obstacles,
    /// Contour kinds (outer or hole) for the lead length.
    pub contours: &'a Contours,
    /// Lead settings.
    pub leads: LeadOptions,
    /// Kerf width, mm (no leads without a kerf).
    pub kerf: f64,
    /// The one tolerance, mm.
    pub tol: f64,
}

impl Ends<'_> {
    /// The trail entered where a lead-in fits (a closed trail may be turned
    /// to start at another vertex), and the lead-in's pierce point; the
    /// trail unchanged and None when no lead fits or none is asked.
    pub fn enter(
        &self,
        trail: Vec<(usize, bool)>,
        links: &[Link],
        kinds: &[Kind],
        g: &Graph,
    ) -> (Vec<(usize, bool)>, Option<Point>) {
        if self.kerf <= self.tol || self.leads.kind == LeadKind::None || trail.is_empty() {
            return (trail, None);
        }
        let seg = |k: usize| {
            let (l, f) = trail[k % trail.len()];
            links[l].oriented(f)
        };
        let n = trail.len();
        let closed = seg(0).a.dist(seg(n - 1).b) <= self.tol;
        let start = seg(0).a;
        let mut tries: Vec<usize> = if closed {
            let step = n.div_ceil(MAX_TRIES).max(1);
            (0..n).step_by(step).collect()
        } else {
            vec![0]
        };
        crate::sort::sort_by(&mut tries, |&a, &b| {
            seg(a).a.dist(start).total_cmp(&seg(b).a.dist(start))
        });
        for k in tries {
            let (l, _) = trail[k];
            let Some(&Kind::Edge(e)) = kinds.get(l) else {
                continue;
            };
            let kind = g
                .edges
                .get(e)
                .and_then(|e| self.contours.contours.get(e.contour))
                .map_or(ContourKind::Outer, |c| c.kind);
            let length = match kind {
                ContourKind::Hole => self.leads.hole_length,
                _ => self.leads.outer_length,
            };
            let into = seg(k);
            let from = if k == 0 && !closed {
                None
            } else {
                Some(seg(k + n - 1))
            };
            if let Some(q) = self.lead(&into, from.as_ref(), length) {
                let mut t = trail;
                t.rotate_left(k);
                return (t, Some(q));
            }
        }
        (trail, None)
    }

    /// A pierce point for a straight lead-in onto `into`'s start: square to
    /// it (or to `from`, the segment arriving there, or along their
    /// bisector) on a side that is scrap, `length` mm long or shorter.
    fn lead(&self, into: &Segment, from: Option<&Segment>, length: f64) -> Option<Point> {
        let v = into.a;
        let t_out = into.tangent_at(0.0).unit();
        let mut dirs = vec![t_out.perp(), t_out.perp().scale(-1.0)];
        if let Some(f) = from {
            let t_in = f.tangent_at(1.0).unit();
            dirs.extend([t_in.perp(), t_in.perp().scale(-1.0)]);
            let back = t_in.sub(t_out);
            if back.norm() > 1e-9 {
                dirs.push(back.unit().scale(-1.0));
                dirs.push(back.unit());
            }
        }
        let clearance = self.kerf;
        for len in [length, length / 2.0] {
            if len.is_nan() || len <= clearance {
                continue;
            }
            for d in &dirs {
                if !d.is_finite() {
                    continue;
                }
                let q = v.add(d.scale(len));
                if self.obstacles.distance(q, clearance) >= clearance && self.scrap.line_ok(q, v) {
                    return Some(q);
                }
            }
        }
        None
    }

    /// The overcut past the start of a closed trail: its first `overcut` mm again.
    pub fn overcut(&self, path: &[Segment]) -> Vec<Segment> {
        let closed = match (path.first(), path.last()) {
            (Some(a), Some(b)) => a.a.dist(b.b) <= self.tol,
            _ => false,
        };
        if !closed
            || self.leads.overcut.is_nan()
            || self.leads.overcut <= 0.0
            || self.kerf <= self.tol
        {
            return Vec::new();
        }
        crate::plan::lead::overcut(path, self.leads.overcut)
    }
}
