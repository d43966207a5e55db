//! The page's Play list (issue 43 §6, "what is previewed is what is
//! downloaded"): the program as flat moves, 7 numbers each, `[kind, x0,
//! y0, x1, y1, bulge, t_end]`, in the order the posts write them — a
//! router's milling [`Toolpath`] first (the very moves `gcode::emit_router`
//! writes), then the plan's cuts, each cut's contour once per depth pass
//! as `gcode`'s depth passes write it (back along an open path on every
//! other pass), with a router's Z moves between them. `t_end` is the
//! estimated seconds from the start when the move ends: the moves' times
//! add up to [`crate::gcode::job_time_s`] (the plan's, move by move as
//! [`crate::plan::PlanStats::est_time_s`] counts them; the milling's as
//! [`crate::mill::MillStats::time_s`]; a router profile's Z moves as
//! `gcode::router_time` counts them).

use crate::gcode::{dwell_s, is_router, Post};
use crate::geom::{Point, Segment};
use crate::mill::{MillMove, Toolpath};
use crate::plan::{Cut, Role, Step};
use crate::process::Process;
use crate::scene::Scene;

/// The kinds of move: one table, mirrored by `KIND` in `www/plan.js`
/// (`tests/browser/moves-wire.test.mjs` checks the two agree).
pub mod kind {
    pub const RAPID: f64 = 0.0;
    pub const LEAD_IN: f64 = 1.0;
    pub const CONTOUR: f64 = 2.0;
    pub const LEAD_OUT: f64 = 3.0;
    pub const LINK: f64 = 4.0;
    pub const REPEAT: f64 = 5.0;
    pub const PIERCE: f64 = 6.0;
    pub const SPOT: f64 = 7.0;
    /// A feed move with the torch off (only in programs re-read by the backplot).
    pub const DRY_FEED: f64 = 8.0;
    pub const MARK: f64 = 9.0;
    /// Over a tab, the torch off (issue 20 §6).
    pub const TAB: f64 = 10.0;
    /// A Z move in place (a router: up or down at rapid, or down at the
    /// plunge feed): `x0, y0` = `x1, y1`, where the tool is.
    pub const Z: f64 = 11.0;
    /// A milling cut at one depth (pocket, engraving) at the feed.
    pub const MILL: f64 = 12.0;
    /// A milling entry: along the path while Z goes down (a ramp, a
    /// helix), at the plunge feed.
    pub const MILL_ENTRY: f64 = 13.0;
    /// Numbers per move: `[kind, x0, y0, x1, y1, bulge, t_end]`.
    pub const STRIDE: usize = 7;
}

/// The list being written: where the tool is and the time so far; with
/// `only`, just the moves of that kind are kept (the rest still move the
/// tool and the clock).
struct List {
    v: Vec<f64>,
    at: Point,
    t: f64,
    only: Option<f64>,
}

impl List {
    fn push(&mut self, kind: f64, s: Segment, seconds: f64) {
        self.t += seconds;
        self.at = s.b;
        if self.only.is_none_or(|k| k == kind) {
            self.v
                .extend_from_slice(&[kind, s.a.x, s.a.y, s.b.x, s.b.y, s.bulge, self.t]);
        }
    }
    /// A move in Z where the tool is.
    fn z(&mut self, seconds: f64) {
        let at = self.at;
        self.push(kind::Z, Segment::line(at, at), seconds);
    }
}

/// The program of `scene` as the page's flat move list ([`kind`]);
/// `post` the job's (a router's Z moves are listed and timed).
pub fn moves(scene: &Scene, p: &Process, post: Option<&Post>) -> Vec<f64> {
    walk(scene, p, post, None)
}

/// The program's rapids in X and Y, in order, from the same walk as
/// [`moves`] (the plan SVG draws these: a router profile's lift and
/// rapid between depth passes with lead arcs too); rapids in place left
/// out.
pub fn rapids(scene: &Scene, p: &Process, post: Option<&Post>) -> Vec<Segment> {
    let v = walk(scene, p, post, Some(kind::RAPID));
    (v.chunks(kind::STRIDE))
        .map(|m| Segment::line(Point::new(m[1], m[2]), Point::new(m[3], m[4])))
        .filter(|s| s.a != s.b)
        .collect()
}

/// The rapids the preview draws ([`Scene::rapids`]): with a router's post
/// the program's ([`rapids`]: it lifts and crosses between a profile's
/// depth passes with lead arcs); none with another post, whose rapids
/// are the plan's, one per cut.
pub fn preview_rapids(scene: &Scene, p: &Process, post: Option<&Post>) -> Option<Vec<Segment>> {
    post.filter(|post| is_router(post))
        .map(|_| rapids(scene, p, post))
}

/// [`moves`], keeping only the moves of kind `only` when given.
fn walk(scene: &Scene, p: &Process, post: Option<&Post>, only: Option<f64>) -> Vec<f64> {
    let router = post.filter(|post| is_router(post));
    let plan = scene.plan;
    let n = p.passes.count().max(1);
    let count: usize = (plan.cuts.iter())
        .map(|c| 6 + c.steps.len() * if c.spot { 1 } else { n })
        .sum::<usize>()
        + scene.milling.map_or(0, |m| m.toolpath.moves.len());
    let cap = if only.is_some() { 0 } else { kind::STRIDE * count };
    let mut l = List {
        v: Vec::with_capacity(cap),
        at: plan.origin,
        t: 0.0,
        only,
    };
    let rapid = |d: f64| 60.0 * d / p.rapid.max(1e-9);
    if let Some(r) = router {
        // The header's dwell (`G4 P3`: the spindle spins up), in place.
        let t = dwell_s(&r.program_start, p.pierce_delay) + dwell_s(&r.header, p.pierce_delay);
        if t > 0.0 {
            l.z(t);
        }
        if p.passes.on() {
            // `pass_retract` after the header: down from the safe height.
            l.z(rapid((r.safe_height - r.retract_height).max(0.0)));
        }
    }
    if let Some(m) = scene.milling {
        l.at = m.toolpath.start;
        let change_s = router.map_or(0.0, |r| crate::gcode::tool_change_s(r, p));
        milling(&mut l, m.toolpath, p, router.map_or(0.0, |r| r.retract_height), change_s);
    }
    let mut profiles = 0;
    for c in &plan.cuts {
        let d = l.at.dist(c.pierce);
        l.push(kind::RAPID, Segment::line(l.at, c.pierce), rapid(d));
        let feed = c.feed(p);
        let in_passes = p.passes.on() && !c.spot && !c.is_mark();
        let router_z = router.filter(|_| in_passes);
        if let (Some(r), true) = (router_z, profiles > 0) {
            // `torch_on`: down from the safe height to the retract height.
            l.z(rapid((r.safe_height - r.retract_height).max(0.0)));
        }
        let at = c.pierce;
        let dot = Segment::line(at, at);
        if c.spot {
            l.push(kind::SPOT, dot, p.pierce_delay);
            continue;
        }
        l.push(kind::PIERCE, dot, p.pierce_delay);
        if !in_passes {
            for s in &c.steps {
                step(&mut l, s, feed, p, true);
            }
            continue;
        }
        profiles += 1;
        passes(&mut l, c, feed, p, router_z);
        if let Some(r) = router_z {
            // `pass_retract` up from the full depth, `torch_off` to the safe height.
            l.z(rapid(p.passes.depth + r.retract_height));
            l.z(rapid((r.safe_height - r.retract_height).max(0.0)));
        }
    }
    if let Some(r) = router {
        let t = dwell_s(&r.footer, p.pierce_delay) + dwell_s(&r.program_end, p.pierce_delay);
        if t > 0.0 {
            l.z(t);
        }
    }
    l.v
}

/// One plan step: its kind and time as the plan's estimate counts it
/// (`first`: the first time it is cut; a link or a tab written again in a
/// later depth pass is not in the estimate, so takes no time here).
fn step(l: &mut List, s: &Step, feed: f64, p: &Process, first: bool) {
    let seg = s.segment;
    let len = seg.length();
    let (k, t) = match s.role {
        // Crossed at the rapid speed, then a new pierce.
        Role::Tab => (kind::TAB, 60.0 * len / p.rapid.max(1e-9) + p.pierce_delay),
        Role::Contour => (kind::CONTOUR, 60.0 * len / feed.max(1e-9)),
        Role::Repeat => (kind::REPEAT, 60.0 * len / feed.max(1e-9)),
        Role::LeadIn => (kind::LEAD_IN, 60.0 * len / feed.max(1e-9)),
        Role::LeadOut => (kind::LEAD_OUT, 60.0 * len / feed.max(1e-9)),
        Role::Link => (kind::LINK, 60.0 * len / feed.max(1e-9)),
        Role::Mark => (kind::MARK, 60.0 * len / feed.max(1e-9)),
    };
    let counted = first || matches!(s.role, Role::Contour | Role::Repeat);
    l.push(k, seg, if counted { t } else { 0.0 });
}

/// Cut `c` in depth passes as `gcode`'s `depth_passes` writes it: the
/// lead-in once, the section from the first to the last contour step
/// (links and tabs between) once per pass, back along it on every other
/// pass of an open path, the lead-out once unless an even count of an
/// open path left the tool at its start. A router's plunge before each
/// pass (from the retract height to the first depth, then a depth each);
/// a router's closed profile with leads cut whole on every pass
/// ([`crate::gcode::releads`]).
fn passes(l: &mut List, c: &Cut, feed: f64, p: &Process, router: Option<&Post>) {
    if c.steps.is_empty() {
        return;
    }
    let in_section = |s: &Step| matches!(s.role, Role::Contour | Role::Repeat | Role::Tab);
    let (first, last) = match (
        c.steps.iter().position(in_section),
        c.steps.iter().rposition(in_section),
    ) {
        (Some(a), Some(b)) => (a, b),
        _ => (0, c.steps.len() - 1),
    };
    let section = &c.steps[first..=last];
    // As `depth_passes` decides it (on the post's grid there; a closed
    // contour's section ends on its start exactly).
    let closed = section[0].segment.a.dist(section[section.len() - 1].segment.b) < 1e-9;
    let n = p.passes.count();
    let plunge = |d: f64| 60.0 * d / p.tool.plunge_feed.max(1e-9);
    let rapid = |d: f64| 60.0 * d / p.rapid.max(1e-9);
    // A router's closed profile with leads: each pass cut whole, the tool
    // up and across to the lead-in between passes (`gcode::releads`).
    let again = crate::gcode::releads(c, first, last, closed, router.is_some());
    let mut forward = true;
    for pass in 1..=n {
        if let (Some(r), true) = (router, again && pass > 1) {
            l.z(rapid(r.retract_height - p.passes.z(pass - 1)));
            let d = l.at.dist(c.pierce);
            l.push(kind::RAPID, Segment::line(l.at, c.pierce), rapid(d));
        }
        if let Some(r) = router {
            let z0 = if pass == 1 || again {
                r.retract_height
            } else {
                p.passes.z(pass - 1)
            };
            l.z(plunge(z0 - p.passes.z(pass)));
        }
        if pass == 1 || again {
            for s in &c.steps[..first] {
                step(l, s, feed, p, true);
            }
        }
        let z = p.passes.z(pass);
        let cross = |l: &mut List, s: &Step| match router {
            Some(r) if s.role == Role::Tab => router_tab(l, s, p, r, z, feed),
            _ => step(l, s, feed, p, pass == 1),
        };
        if forward {
            for s in section {
                cross(l, s);
            }
        } else {
            for s in section.iter().rev() {
                let back = Step {
                    segment: s.segment.reversed(),
                    ..*s
                };
                cross(l, &back);
            }
        }
        if !closed {
            forward = !forward;
        }
        if again {
            for s in &c.steps[last + 1..] {
                step(l, s, feed, p, true);
            }
        }
    }
    if !again && (forward || closed) {
        for s in &c.steps[last + 1..] {
            step(l, s, feed, p, true);
        }
    }
}

/// A tab crossed by a router at depth `z` (`gcode::tabs::cross`, on every
/// pass), with a tab height as [`crate::process::Tool::tab_top`] says;
/// without one, up at rapid to the safe height (`torch_off`), down to the
/// retract height (`pass_retract`), across in a straight line at rapid,
/// the pierce's dwell, down to `z` at the plunge feed (`pass_z`).
fn router_tab(l: &mut List, s: &Step, p: &Process, r: &Post, z: f64, feed: f64) {
    let rapid = |d: f64| 60.0 * d / p.rapid.max(1e-9);
    if let Some(top) = p.tool.tab_top(p.passes.depth) {
        // A bridge at the bottom: cut through above its top; below it, up
        // to the top at rapid, across at the feed, down at the plunge feed.
        let across = 60.0 * s.segment.length() / feed.max(1e-9);
        if z >= top - 1e-9 {
            l.push(kind::CONTOUR, s.segment, across);
        } else {
            l.z(rapid(top - z));
            l.push(kind::TAB, s.segment, across);
            l.z(60.0 * (top - z) / p.tool.plunge_feed.max(1e-9));
        }
        return;
    }
    l.z(rapid(r.safe_height - z));
    l.z(rapid((r.safe_height - r.retract_height).max(0.0)));
    let chord = s.segment.a.dist(s.segment.b);
    l.push(kind::TAB, s.segment, rapid(chord) + p.pierce_delay);
    l.z(60.0 * (r.retract_height - z) / p.tool.plunge_feed.max(1e-9));
}

/// The milling toolpath's moves, timed as [`crate::mill::MillStats::time_s`]:
/// from `start_z` (the post's retract height) at the toolpath's start,
/// each tool's at its feeds; a tool change after the first `change_s`
/// long, in place.
fn milling(l: &mut List, t: &Toolpath, job: &Process, start_z: f64, change_s: f64) {
    let rapid = |d: f64| 60.0 * d / job.rapid.max(1e-9);
    let mut z = start_z;
    let mut tool = *job;
    for (i, m) in t.moves.iter().enumerate() {
        let p = &tool;
        match m {
            MillMove::ToolChange(tc) => {
                tool = Process {
                    feed: tc.feed,
                    tool: tc.tool,
                    ..*job
                };
                if i > 0 {
                    l.z(change_s);
                }
            }
            MillMove::Rapid(q) => {
                let d = l.at.dist(*q);
                l.push(kind::RAPID, Segment::line(l.at, *q), rapid(d));
            }
            MillMove::RapidZ(h) => {
                l.z(rapid((h - z).abs()));
                z = *h;
            }
            MillMove::Plunge(h) => {
                l.z(60.0 * (h - z).abs() / p.tool.plunge_feed.max(1e-9));
                z = *h;
            }
            MillMove::Cut { seg, z: h } => {
                let len = seg.length();
                if *h != z {
                    let t = 60.0 * len.hypot(h - z) / p.tool.plunge_feed.max(1e-9);
                    l.push(kind::MILL_ENTRY, *seg, t);
                } else {
                    l.push(kind::MILL, *seg, 60.0 * len / p.feed.max(1e-9));
                }
                z = *h;
            }
            MillMove::Note(_) => {}
        }
    }
}
