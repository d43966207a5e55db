//! Tabs (micro-joints; paper 001's "travas", notes-001 §10.3/§14): short
//! stretches of a part's outline left uncut so the part stays in the sheet
//! until it is knocked out (thin parts that would tip up under the torch,
//! small parts that would fall through the slats).
//!
//! A tab is data on the plan: the stretch of a cut's contour steps it spans
//! (an arc-length interval of the kerf path) becomes a [`Role::Tab`] step,
//! crossed with the torch off (or the knife up). Every consumer reads it
//! from there: the post writes it as its templates say, the preview draws
//! it, the time estimate counts it, the verification sees the part held.
//!
//! **Width.** `width` is the material left: the narrowest width of the
//! bridge, measured along the kerf's centre line. The kerf disc reaches
//! w/2 past the torch's stop and restart points, so the torch is off for
//! `width + kerf` of its path (paper 001's 10–12 mm bridges are what is left
//! of the plate, not where the torch was).
//!
//! **Placement.** Tabs go on the contour's longest straight edges (arcs only
//! when no straight edge has room), spread over them by the room each has:
//! a long edge gets two before a short one gets one. Each keeps clear of
//! the edge's corners (the kerf turning there) and of the cut's start,
//! where the lead-in arrives and the lead-out or overcut leaves (a tab
//! there would be cut by the overcut).

pub use super::options::Tabs;
use super::{Cut, CutPlan, Role, Step};
use crate::contour::{ContourKind, Contours};
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::{dec, Warning};

/// A tab's place on one contour step run: arc-length from the run's start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TabGap {
    /// Where the torch goes off, mm from the run's start.
    pub from: f64,
    /// Where it comes back on.
    pub to: f64,
}

/// Puts `tabs` on every qualifying contour of `plan` (marks, spots, small
/// holes and open paths get none), and a tab where each point of `at`
/// (contour index, point near it) falls on its contour's kerf path.
/// `kerf` is the kerf width, mm. Returns, for each of `at`, whether it has
/// its tab (none on a loop too short for one, or not cut as a loop).
pub fn apply(
    plan: &mut CutPlan,
    contours: &Contours,
    tabs: &Tabs,
    at: &[(usize, Point)],
    kerf: f64,
) -> Vec<bool> {
    let mut held = vec![false; at.len()];
    if !tabs.on() && (at.is_empty() || tabs.width <= 0.0) {
        return held;
    }
    let gap = tabs.width + kerf.max(0.0);
    // Clear of a corner by a kerf and half a tab, at least 1 mm: the kerf
    // turning a corner widens the slot there.
    let clear = (kerf + tabs.width / 2.0).max(1.0);
    let mut short: Vec<usize> = Vec::new();
    for cut in plan.cuts.iter_mut() {
        if cut.spot || cut.small_hole || cut.is_mark() {
            continue;
        }
        // After the contour: how far the lead-out runs back over it.
        let out_len: f64 = cut
            .steps
            .iter()
            .filter(|s| s.role == Role::LeadOut)
            .map(|s| s.segment.length())
            .sum();
        let mut i = 0;
        while i < cut.steps.len() {
            let s = cut.steps[i];
            let kind = s
                .contour
                .and_then(|k| contours.contours.get(k))
                .map(|c| c.kind);
            let auto = tabs.on()
                && match kind {
                    Some(ContourKind::Outer) => true,
                    Some(ContourKind::Hole) => tabs.holes,
                    _ => false,
                };
            let asked: Vec<usize> = (0..at.len())
                .filter(|&t| Some(at[t].0) == s.contour && kind.is_some())
                .collect();
            let clicked: Vec<Point> = asked.iter().map(|&t| at[t].1).collect();
            if s.role != Role::Contour || (!auto && clicked.is_empty()) {
                i += 1;
                continue;
            }
            // The run of this contour's steps.
            let mut j = i;
            while j < cut.steps.len()
                && cut.steps[j].role == Role::Contour
                && cut.steps[j].contour == s.contour
            {
                j += 1;
            }
            let run: Vec<Segment> = cut.steps[i..j].iter().map(|s| s.segment).collect();
            let start_clear = clear + out_len;
            let placed = at_points(&run, &clicked, gap, start_clear, clear);
            // A second click on a placed tab is that tab: all are held, or
            // none when the run has no room for one.
            for &t in &asked {
                held[t] = !placed.is_empty();
            }
            let mut gaps = if auto {
                let g = place(&run, tabs.count, gap, clear, start_clear);
                if g.len() < tabs.count {
                    short.extend(cut.part);
                }
                g
            } else {
                Vec::new()
            };
            // The user's tabs win where an automatic one would overlap.
            gaps.retain(|g| !placed.iter().any(|p| g.from < p.to && p.from < g.to));
            gaps.extend(placed);
            crate::sort::sort_by(&mut gaps, |a, b| a.from.total_cmp(&b.from));
            let gaps = joined(gaps);
            let n = split(cut, i, j, &gaps);
            i = j + n;
        }
    }
    if !short.is_empty() {
        crate::sort::sort_indices(&mut short);
        short.dedup();
        let (n, w, parts) = (
            tabs.count,
            tabs.width,
            short
                .iter()
                .map(|p| p.to_string())
                .collect::<Vec<_>>()
                .join(", "),
        );
        plan.warnings.push(Warning::new(
            "tabs-short",
            text!("tabs: part(s) {parts} have no room for {n} tab(s) of {w} mm clear of corners and leads; fewer placed";
                  "pontes: peça(s) {parts} sem espaço para {n} ponte(s) de {} mm longe de cantos e entradas; menos colocadas", dec(w)),
        ));
    }
    held
}

/// Shortest stretch of contour cut between two tabs, mm: a shorter one is
/// joined into the tabs around it (the torch would fire and stop on the
/// spot: a pierce and nothing cut).
const MIN_CUT_BETWEEN: f64 = 0.01;

/// `gaps` (sorted by start) with those less than [`MIN_CUT_BETWEEN`]
/// apart made one.
fn joined(gaps: Vec<TabGap>) -> Vec<TabGap> {
    let mut out: Vec<TabGap> = Vec::with_capacity(gaps.len());
    for g in gaps {
        match out.last_mut() {
            Some(last) if g.from - last.to < MIN_CUT_BETWEEN => last.to = last.to.max(g.to),
            _ => out.push(g),
        }
    }
    out
}

/// Tab gaps on a run of contour segments: up to `n` gaps of length `gap`,
/// each at least `clear` from its edge's ends, `start_clear` from the run's
/// start and `clear` from its end.
pub fn place(run: &[Segment], n: usize, gap: f64, clear: f64, start_clear: f64) -> Vec<TabGap> {
    let total: f64 = run.iter().map(Segment::length).sum();
    // Each edge's usable interval of arc length.
    let mut at = 0.0;
    let mut edges: Vec<(bool, f64, f64)> = Vec::new();
    for s in run {
        let len = s.length();
        let lo = (at + clear).max(start_clear);
        let hi = (at + len - clear).min(total - clear);
        if hi - lo >= gap {
            edges.push((s.is_line(), lo, hi));
        }
        at += len;
    }
    let lines = edges.iter().any(|e| e.0);
    edges.retain(|e| e.0 == lines);
    // Tabs dealt one at a time to the edge with the most room per tab.
    let mut dealt = vec![0usize; edges.len()];
    for _ in 0..n {
        let fits = |e: &(bool, f64, f64), k: usize| {
            let room = e.2 - e.1;
            room >= (k + 1) as f64 * gap + k as f64 * clear
        };
        let best = (0..edges.len())
            .filter(|&e| fits(&edges[e], dealt[e]))
            .max_by(|&a, &b| {
                let per = |e: usize| (edges[e].2 - edges[e].1) / (dealt[e] + 1) as f64;
                per(a).total_cmp(&per(b)).then(b.cmp(&a))
            });
        match best {
            Some(e) => dealt[e] += 1,
            None => break,
        }
    }
    let mut gaps = Vec::new();
    for (e, &k) in edges.iter().zip(&dealt) {
        // k gaps spread evenly: centres at (i + 1) / (k + 1) of the room.
        for i in 0..k {
            let c = e.1 + (e.2 - e.1) * (i + 1) as f64 / (k + 1) as f64;
            let from = (c - gap / 2.0).max(e.1);
            gaps.push(TabGap {
                from,
                to: from + gap,
            });
        }
    }
    crate::sort::sort_by(&mut gaps, |a, b| a.from.total_cmp(&b.from));
    gaps
}

/// Gaps of length `gap` centred where each of `points` is nearest the run,
/// moved along it to keep `start_clear` from its start and `end_clear`
/// from its end (where the lead-in arrives and the lead-out leaves);
/// a gap overlapping one placed before is left out (a second click on the
/// same tab), and so are all when the run is too short to hold one.
pub fn at_points(
    run: &[Segment],
    points: &[Point],
    gap: f64,
    start_clear: f64,
    end_clear: f64,
) -> Vec<TabGap> {
    let total: f64 = run.iter().map(Segment::length).sum();
    let (lo, hi) = (start_clear, total - end_clear - gap);
    if hi.is_nan() || hi < lo {
        return Vec::new();
    }
    let mut gaps: Vec<TabGap> = Vec::new();
    for &p in points {
        // Arc length of the run's point nearest `p`.
        let mut best = (f64::INFINITY, 0.0);
        let mut at = 0.0;
        for s in run {
            let len = s.length();
            let t = crate::geom::nearest_param(s, p);
            let d = s.point_at(t).dist(p);
            if d < best.0 {
                best = (d, at + t * len);
            }
            at += len;
        }
        let from = (best.1 - gap / 2.0).clamp(lo, hi);
        let g = TabGap {
            from,
            to: from + gap,
        };
        if !gaps.iter().any(|o| g.from < o.to && o.from < g.to) {
            gaps.push(g);
        }
    }
    gaps
}

/// Splits the steps `i..j` of `cut` at `gaps` (arc lengths from step `i`'s
/// start); the pieces inside a gap become [`Role::Tab`] steps. Returns how
/// many steps were added.
fn split(cut: &mut Cut, i: usize, j: usize, gaps: &[TabGap]) -> usize {
    if gaps.is_empty() {
        return 0;
    }
    let mut out: Vec<Step> = Vec::with_capacity(j - i + 2 * gaps.len());
    let mut at = 0.0;
    for s in &cut.steps[i..j] {
        let len = s.segment.length();
        // Cut points inside this step, as fractions, and whether each
        // piece after a point is a tab.
        let mut cuts: Vec<(f64, bool)> = Vec::new();
        for g in gaps {
            for (x, tab) in [(g.from, true), (g.to, false)] {
                if x > at && x < at + len && len > 0.0 {
                    cuts.push(((x - at) / len, tab));
                }
            }
        }
        let starts_in_tab = gaps.iter().any(|g| g.from <= at && at < g.to);
        let mut t0 = 0.0;
        let mut tab = starts_in_tab;
        for (t, next) in cuts.iter().copied().chain([(1.0, false)]) {
            if t > t0 {
                out.push(Step {
                    segment: piece(&s.segment, t0, t),
                    role: if tab { Role::Tab } else { Role::Contour },
                    contour: s.contour,
                });
            }
            t0 = t;
            tab = next;
        }
        at += len;
    }
    let out = one_step_a_tab(out);
    let added = out.len() - (j - i);
    cut.steps.splice(i..j, out);
    added
}

/// `steps` with each run of tab pieces (a tab over a corner spans two or
/// more segments) made one step, the straight move from its start to its
/// end: the tool crosses a tab in one move with the torch off, so the
/// program never fires and stops the torch between the pieces, and the
/// preview draws the move the machine makes.
fn one_step_a_tab(steps: Vec<Step>) -> Vec<Step> {
    let mut out: Vec<Step> = Vec::with_capacity(steps.len());
    for s in steps {
        match out.last_mut() {
            Some(last) if last.role == Role::Tab && s.role == Role::Tab => {
                last.segment = Segment::line(last.segment.a, s.segment.b);
            }
            _ => out.push(s),
        }
    }
    out
}

/// The piece of `s` between the fractions `t0` and `t1` of its length.
pub fn piece(s: &Segment, t0: f64, t1: f64) -> Segment {
    if t0 <= 0.0 && t1 >= 1.0 {
        // Whole: the same numbers (no bulge recomputed through tan/atan).
        return *s;
    }
    let a = if t0 <= 0.0 { s.a } else { s.point_at(t0) };
    let b = if t1 >= 1.0 { s.b } else { s.point_at(t1) };
    let bulge = if s.is_line() {
        0.0
    } else {
        (s.sweep() * (t1 - t0) / 4.0).tan()
    };
    Segment { a, b, bulge }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;

    fn rect(w: f64, h: f64) -> Vec<Segment> {
        let p = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h), (0.0, 0.0)];
        p.windows(2)
            .map(|q| Segment::line(Point::new(q[0].0, q[0].1), Point::new(q[1].0, q[1].1)))
            .collect()
    }

    #[test]
    fn tabs_go_to_the_longest_edges_clear_of_corners() {
        // 100 × 20: two tabs, one on each long edge, centred.
        let g = place(&rect(100.0, 20.0), 2, 4.0, 2.0, 2.0);
        assert_eq!(g.len(), 2);
        assert!((g[0].from - 48.0).abs() < 1e-9, "{g:?}");
        assert!((g[1].from - (120.0 + 48.0)).abs() < 1e-9, "{g:?}");
        // Four tabs on 100 × 20: the long edges take two each before a
        // 20 mm edge (16 mm of room) takes one.
        let g = place(&rect(100.0, 20.0), 4, 4.0, 2.0, 2.0);
        assert!(g
            .iter()
            .all(|t| t.from < 100.0 || (120.0..220.0).contains(&t.from)));
        assert_eq!(g.len(), 4);
    }

    #[test]
    fn a_circle_gets_tabs_on_its_arcs_and_no_room_means_fewer() {
        let a = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let other = Segment {
            a: Point::new(-10.0, 0.0),
            b: Point::new(10.0, 0.0),
            bulge: 1.0,
        };
        let run = [a, other];
        let g = place(&run, 2, 3.0, 1.0, 1.0);
        assert_eq!(g.len(), 2);
        let p = piece(&a, 0.25, 0.75);
        assert!((p.length() - a.length() / 2.0).abs() < 1e-9);
        // A 5 mm square has no room for a 4 mm gap 2 mm from each corner.
        assert!(place(&rect(5.0, 5.0), 3, 4.0, 2.0, 2.0).is_empty());
    }
}
