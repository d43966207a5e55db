//! Which circuit is cut when, and where each is entered: nearest first
//! from where the torch stopped, every circuit after the circuits of what it
//! encloses (holes before the part's outline, islands before the hole
//! around them, as in every other order: paper 000 "Sequence", paper 001 §3).
//!
//! A circuit with paired rapids (mode "rapid") is cut in trails between its
//! rapids, entered just after one of them so that rapid is never made; a
//! circuit without is entered at one of its vertices.

use super::circuit::Link;
use super::graph::Graph;
use super::next::{Entry, Next};
use super::Kind;
use crate::contour::point_in_loop;
use crate::contour::ContourKind;
use crate::geom::Point;
use crate::plan::{CommonCut, Cut, PlanInput, Role, Step};

/// The trails of every circuit, in cutting order. `circuits[i]` belongs to
/// group `i`; `after[i]` lists the groups that must be cut before group `i`,
/// `depth[i]` is the deepest nesting of a contour in it.
pub fn order(
    circuits: &[Vec<(usize, bool)>],
    after: &[Vec<usize>],
    depth: &[usize],
    links: &[Link],
    kinds: &[Kind],
    origin: Point,
) -> Vec<Vec<(usize, bool)>> {
    let entries: Vec<Vec<Entry>> = circuits.iter().map(|c| entries(c, links, kinds)).collect();
    let mut next = Next::new(&entries, after, depth);
    let mut trails = Vec::new();
    let mut at = origin;
    while let Some((g, e)) = next.take(at) {
        let c = &circuits[g];
        let mut walk: Vec<(usize, bool)> = if e.reversed {
            c.iter().rev().map(|&(l, f)| (l, !f)).collect()
        } else {
            c.clone()
        };
        if e.drop {
            let n = walk.len();
            walk.rotate_left((e.k + 1).min(n));
            walk.pop();
        } else {
            let n = walk.len();
            walk.rotate_left(e.k.min(n));
        }
        let mut trail = Vec::new();
        for step in walk {
            if kinds[step.0] == Kind::Rapid {
                trails.push(std::mem::take(&mut trail));
            } else {
                trail.push(step);
            }
        }
        if let Some(&(l, f)) = trail.last() {
            at = links[l].oriented(f).b;
        }
        trails.push(trail);
    }
    trails
}

/// Most ways into a circuit without rapids that are weighed (evenly spaced
/// vertices): enough for a near start, few enough that sequencing a
/// thousand groups stays a matter of milliseconds.
const MAX_ENTRIES: usize = 64;

/// The ways into circuit `c`: with rapids, either direction starting just
/// after one of them (that rapid is then never made); without, from one of
/// its vertices.
fn entries(c: &[(usize, bool)], links: &[Link], kinds: &[Kind]) -> Vec<Entry> {
    let n = c.len();
    let rapids: Vec<usize> = (0..n).filter(|&k| kinds[c[k].0] == Kind::Rapid).collect();
    if rapids.is_empty() {
        let step = n.div_ceil(MAX_ENTRIES).max(1);
        return (0..n)
            .step_by(step)
            .map(|k| Entry {
                start: links[c[k].0].oriented(c[k].1).a,
                saved: 0.0,
                reversed: false,
                k,
                drop: false,
            })
            .collect();
    }
    let mut out = Vec::with_capacity(2 * rapids.len());
    for &k in &rapids {
        let (l, f) = c[k];
        let seg = links[l].oriented(f);
        let saved = seg.length();
        // Forward: the walk starts at the rapid's end. Reversed, the same
        // rapid sits at n-1-k and is walked the other way.
        out.push(Entry {
            start: seg.b,
            saved,
            reversed: false,
            k,
            drop: true,
        });
        out.push(Entry {
            start: seg.a,
            saved,
            reversed: true,
            k: n - 1 - k,
            drop: true,
        });
    }
    out
}

/// One trail as a cut. The first pass over a drawn edge (per `cut_once`)
/// is [`Role::Contour`], later ones [`Role::Repeat`].
pub fn to_cut(
    trail: &[(usize, bool)],
    links: &[Link],
    kinds: &[Kind],
    g: &Graph,
    input: &PlanInput,
    cut_once: &mut [bool],
    common: &mut Vec<CommonCut>,
) -> Cut {
    let mut steps = Vec::with_capacity(trail.len());
    let mut touched: Vec<usize> = Vec::new();
    for &(l, f) in trail {
        let segment = links[l].oriented(f);
        let (role, contour) = match kinds.get(l) {
            Some(&Kind::Edge(e)) => {
                let again = cut_once.get(e).copied().unwrap_or(true);
                if let Some(c) = cut_once.get_mut(e) {
                    *c = true;
                }
                let role = if again { Role::Repeat } else { Role::Contour };
                if let Some(edge) = g.edges.get(e).filter(|e| !again && e.also.is_some()) {
                    common.push(common_cut(edge, segment, input));
                }
                (role, g.edges.get(e).map(|e| e.contour))
            }
            _ => (Role::Link, None),
        };
        if let Some(c) = contour {
            if !touched.contains(&c) {
                touched.push(c);
            }
        }
        steps.push(Step {
            segment,
            role,
            contour,
        });
    }
    let first = touched
        .first()
        .and_then(|&c| input.contours.contours.get(c));
    Cut {
        pierce: steps.first().map_or(Point::default(), |s| s.segment.a),
        steps,
        contours: touched,
        part: first.and_then(|c| c.part),
        kind: first.map_or(ContourKind::Outer, |c| c.kind),
        spot: false,
        small_hole: false,
        comp: None,
    }
}

/// A shared path piece as cut: its two parts and the one on the right,
/// found by probing a kerf beyond the path on its right.
fn common_cut(
    edge: &super::graph::Edge,
    segment: crate::geom::Segment,
    input: &PlanInput,
) -> CommonCut {
    let contours = &input.contours.contours;
    let part = |c: Option<usize>| c.and_then(|c| contours.get(c)).and_then(|c| c.part);
    let t = segment.tangent_at(0.5).unit();
    let reach = input.process.kerf.max(0.0) / 2.0
        + (input.process.kerf.max(0.0) / 2.0).max(10.0 * input.tolerance);
    let probe = segment
        .point_at(0.5)
        .add(Point::new(t.y, -t.x).scale(reach));
    let inside = |c: Option<usize>| {
        c.and_then(|c| contours.get(c))
            .is_some_and(|c| probe.is_finite() && point_in_loop(probe, &c.segments))
    };
    let right = if inside(Some(edge.contour)) {
        part(Some(edge.contour))
    } else if inside(edge.also) {
        part(edge.also)
    } else {
        None
    };
    CommonCut {
        segment,
        parts: (part(Some(edge.contour)), part(edge.also)),
        right,
    }
}
