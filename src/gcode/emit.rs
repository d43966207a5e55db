//! The one G-code emitter: a [`CutPlan`] written the way a [`Post`] says.
//!
//! - Every coordinate is rounded to the post's decimal grid and the machine
//!   position is tracked on that grid, so what the program says is where the
//!   machine is. Each arc's centre is a grid point whose distances to the
//!   rounded start and end differ by at most one grid step: LinuxCNC never
//!   reports "radius to end of arc differs", and GRBL's rule (error 33 when
//!   the radii differ by more than 0.005 mm and 0.1 %) holds from 3 decimals.
//! - Arcs are cut into pieces of at most `max_arc_sweep_deg`, never written
//!   as full circles, and written as lines when the post says so (chord
//!   formula of paper 004) or when no grid centre fits both ends.
//! - Only the post's own templates and our numbers reach the program;
//!   comments go through [`super::comment_as`].

use crate::contour::ContourKind;
use crate::geom::{flatten_count, Point, Segment};
use crate::plan::{CutPlan, Move, Role};

use super::number::{push_u64, Grid};
use super::post::{ArcMode, Post};
use super::thc::Height;
use super::{JobInfo, Writer};

/// The machine state the emitter tracks.
pub(super) struct State {
    pos: (i64, i64),
    motion: Option<String>,
    x: Option<i64>,
    y: Option<i64>,
    /// Knife heading, grid units of a degree, unwrapped.
    heading: Option<i64>,
}

pub(super) fn scaled(s: &Segment, k: f64) -> Segment {
    Segment {
        a: s.a.scale(k),
        b: s.b.scale(k),
        bulge: s.bulge,
    }
}

/// Writes a G-code program (the post is already validated).
pub(crate) fn gcode(plan: &CutPlan, post: &Post, job: &JobInfo) -> String {
    let k = post.unit_scale();
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let mut w = Writer::new(post, plan, job);
    w.raws(&post.program_start);
    // Contours cut, by kind: a chain or an Eulerian circuit cuts many on one
    // pierce, so counting cuts said "holes 0" for a plate full of them. Holes
    // are cut on pierces of their own in every order (a cut's kind is its
    // first contour's).
    let (outers, holes, marks) = plan.cuts.iter().fold((0, 0, 0), |(o, h, m), c| {
        let n = c.contours.len().max(1);
        match c.kind {
            _ if c.is_mark() => (o, h, m + 1),
            ContourKind::Hole => (o, h + n, m),
            _ => (o + n, h, m),
        }
    });
    w.comment(&format!(
        "kerfcam {} - {}",
        env!("CARGO_PKG_VERSION"),
        post.name
    ));
    // Marks (issue 20) are named only when there are some: programs without
    // them read as before.
    let marks = if marks > 0 {
        format!(", marks {marks}")
    } else {
        String::new()
    };
    w.comment(&format!(
        "cuts {}: outer {}, holes {}{marks}, kerf {} mm, feed {} mm/min",
        plan.cuts.len(),
        outers,
        holes,
        grid.fmt_mm(job.kerf),
        grid.fmt_mm(job.feed)
    ));
    if let Some(t) = job.torches {
        w.comment(&t.comment());
    }
    w.templates(&post.header);
    let passes = job.passes;
    if passes.on() {
        // The first rapid must not find the tool below the surface.
        w.templates(&post.pass_retract);
    }
    // The cut being written is cut in depth passes (its feed moves were
    // written at its pierce).
    let mut in_passes = false;
    let mut st = State {
        pos: grid.snap(plan.origin.scale(k)),
        motion: None,
        x: None,
        y: None,
        heading: None,
    };
    if let Some(park) = job.torches.and_then(|t| t.park) {
        // Paper 001 §6.5 (L2825–L2828): the gantry parks and the program
        // stops for the operator to set the torches, before the first cut.
        let q = grid.snap(park.scale(k));
        motion(&mut w, &grid, &mut st, &post.rapid, q, &[]);
        w.comment("operator stop: set the torches, then cycle start");
        w.templates(&["M0".to_string()]);
    }
    let delay = job.pierce_delay > 0.0;
    // The cut being written: a mark (its own tool codes), a small hole (its
    // own speed, the height locked); whether the height is locked now.
    let (mut mark, mut small, mut comp) = (false, false, false);
    let mut height = super::thc::Height::default();
    // Corner and end locks in one-pass cuts (depth passes are for knives
    // and routers, which have no height control), on posts that can lock
    // (the others' moves are not split for nothing).
    let lock_rule = if passes.on() || post.thc_lock.is_empty() {
        crate::process::ThcLock::OFF
    } else {
        job.thc_lock
    };
    let either = |own: &'_ [String], fallback: &'_ [String]| -> Vec<String> {
        if own.is_empty() { fallback } else { own }.to_vec()
    };
    let mut line = String::new();
    for m in plan.moves() {
        match m {
            Move::Rapid(p) => {
                let q = grid.snap(p.scale(k));
                motion(&mut w, &grid, &mut st, &post.rapid, q, &[]);
            }
            Move::Pierce(i) => {
                let c = plan.cuts.get(i);
                mark = c.is_some_and(|c| c.is_mark());
                small = c.is_some_and(|c| c.small_hole);
                if let Some(c) = c {
                    let what = match c.kind {
                        _ if mark => "mark",
                        ContourKind::Hole if small => "small hole",
                        ContourKind::Hole => "hole",
                        ContourKind::Open => "open",
                        ContourKind::Outer => "outer",
                    };
                    // One a cut: built in a reused buffer (no `format!`).
                    line.clear();
                    line.push_str("cut ");
                    push_u64(&mut line, i as u64 + 1);
                    line.push_str(" part ");
                    push_or_dash(&mut line, c.part.map(|p| p as u64));
                    line.push(' ');
                    line.push_str(what);
                    line.push_str(" contour ");
                    push_or_dash(&mut line, c.contours.first().map(|&k| k as u64 + 1));
                    w.comment(&line);
                    if post.knife.is_some() {
                        // Turn the knife to the first direction while it is up.
                        if let Some(s) = c.steps.first() {
                            let t = s.segment.tangent_at(0.0);
                            let h = turn_to(&grid, &mut st, t.y.atan2(t.x).to_degrees());
                            knife_word(&mut w, post, &grid, &post.rapid, h);
                        }
                    }
                }
                if mark {
                    // A scribe marks on the surface: no probe, no pierce, no height control.
                    w.templates(&either(&post.mark_on, &post.torch_on));
                    if !post.probe.is_empty() {
                        w.reset_feed();
                    }
                    continue;
                }
                if !post.probe.is_empty() {
                    w.templates(&post.probe);
                    w.reset_feed();
                }
                w.templates(&post.torch_on);
                if delay {
                    w.templates(&post.dwell);
                }
                w.templates(&post.after_pierce);
                if let Some(left) = c.and_then(|c| c.comp) {
                    // On the lead-in line that follows (issue 20 §7).
                    w.templates(if left {
                        &post.comp_left
                    } else {
                        &post.comp_right
                    });
                    comp = true;
                }
                if small {
                    w.templates(&post.thc_lock);
                    height.locked = !post.thc_lock.is_empty();
                    w.templates(&post.small_hole_on);
                } else {
                    w.templates(&post.thc_on);
                }
                if let Some(c) = c {
                    height.start(c, &lock_rule);
                }
                if let (true, Some(c)) = (passes.on(), c) {
                    super::passes::depth_passes(&mut w, &grid, &mut st, c, job, k, &mut height);
                    in_passes = true;
                }
            }
            Move::Feed(step) => {
                if in_passes {
                    // Written with the passes at the pierce.
                    continue;
                }
                feed_step(&mut w, &grid, &mut st, &step, k, mark, &mut height, job);
            }
            Move::TorchOff => {
                if mark {
                    w.templates(&either(&post.mark_off, &post.torch_off));
                    mark = false;
                    continue;
                }
                if std::mem::take(&mut in_passes) {
                    // Up out of the cut once, after the last pass.
                    w.templates(&post.pass_retract);
                    w.pass_depth = false;
                }
                if std::mem::take(&mut small) {
                    w.templates(&post.small_hole_off);
                }
                if std::mem::take(&mut comp) {
                    w.templates(&post.comp_off);
                }
                w.templates(&post.thc_off);
                w.templates(&post.torch_off);
                if std::mem::take(&mut height.locked) {
                    w.templates(&post.thc_unlock);
                }
            }
            Move::Spot(_) => {
                if post.spot.is_empty() {
                    w.templates(&post.torch_on);
                    if delay {
                        w.templates(&post.dwell);
                    }
                    w.templates(&post.torch_off);
                } else {
                    w.templates(&post.spot);
                }
                if !post.probe.is_empty() {
                    // A probing spot left its own feed modal.
                    w.reset_feed();
                }
            }
        }
    }
    w.templates(&post.footer);
    w.raws(&post.program_end);
    w.finish()
}

/// `n` in decimal, or "-" for none.
fn push_or_dash(out: &mut String, n: Option<u64>) {
    match n {
        Some(n) => push_u64(out, n),
        None => out.push('-'),
    }
}

/// One feed step of a cut, holding the torch height over a lead-out; a
/// tab crossed as the post says ([`super::tabs`]).
#[allow(clippy::too_many_arguments)] // the emitter's state, passed down as is
pub(super) fn feed_step(
    w: &mut Writer,
    grid: &Grid,
    st: &mut State,
    step: &crate::plan::Step,
    k: f64,
    mark: bool,
    height: &mut Height,
    job: &JobInfo,
) {
    let post = w.post;
    if step.role == Role::Tab {
        height.skip(step.segment.length());
        super::tabs::cross(w, grid, st, step, k, job, height.locked);
        // A lock window that opened or closed over the tab.
        if let Some(lock) = height.due() {
            super::thc::set(w, height, lock);
        }
        return;
    }
    if step.role == Role::LeadOut && !mark {
        // The overcut at a contour's end: the kerf crosses its own
        // start and the arc voltage jumps; hold the height.
        super::thc::set(w, height, true);
    }
    if height.idle() {
        // The common case: no split, no length, no allocation.
        return feed(w, post, grid, st, &scaled(&step.segment, k));
    }
    // In pieces where the height is locked or released (corners, the
    // contour's end: [`super::thc`]).
    for (piece, change) in height.pieces(&step.segment) {
        feed(w, post, grid, st, &scaled(&piece, k));
        if let Some(lock) = change {
            super::thc::set(w, height, lock);
        }
    }
}

/// One motion block to the grid point `q`, with the extra words (I, J, R,
/// a knife's axis), each a letter and a grid number.
pub(super) fn motion(
    w: &mut Writer,
    grid: &Grid,
    st: &mut State,
    word: &str,
    q: (i64, i64),
    extra: &[(&str, i64)],
) {
    let post = w.post;
    if w.take_templated() {
        st.motion = None;
    }
    let new_motion = !post.modal || st.motion.as_deref() != Some(word);
    let (new_x, new_y) = (
        !post.modal || st.x != Some(q.0),
        !post.modal || st.y != Some(q.1),
    );
    if !new_x && !new_y && extra.is_empty() {
        return;
    }
    let feed = if word != post.rapid || post.rapid == post.line {
        w.feed_word()
    } else {
        None
    };
    w.block_of(|b| {
        if new_motion {
            b.text(word);
        }
        if new_x {
            b.num("X", grid, q.0);
        }
        if new_y {
            b.num("Y", grid, q.1);
        }
        for &(letter, v) in extra {
            b.num(letter, grid, v);
        }
        if let Some(f) = &feed {
            b.text(f);
        }
    });
    if st.motion.as_deref() != Some(word) {
        // Reuses the string: G1 and G2/G3 alternate on every rounded corner.
        let m = st.motion.get_or_insert_with(String::new);
        m.clear();
        m.push_str(word);
    }
    st.x = Some(q.0);
    st.y = Some(q.1);
    st.pos = q;
}

/// Blocks for one feed segment (in program units).
pub(super) fn feed(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, s: &Segment) {
    let end = grid.snap(s.b);
    if end == st.pos {
        // Shorter than the grid: nothing the machine can do.
        return;
    }
    let Some((c, r)) = s.arc_center() else {
        return line_to(w, post, grid, st, end);
    };
    // No trigonometry for most arcs (a quarter of the writer's time was
    // atan, cos and tan): the sagitta is r·2b²/(1 + b²) (1 − cos 2·atan b),
    // and the exact formula below decides only when that lands within
    // rounding of half a grid step, so the same arcs become lines as before.
    let b = s.bulge.abs();
    let near = r * 2.0 * b * b / (1.0 + b * b);
    let half = grid.step() / 2.0;
    let flat = if (near - half).abs() > 1e-9 * half {
        near < half
    } else {
        r * (1.0 - (s.sweep().abs() / 2.0).cos()) <= half
    };
    if flat {
        return line_to(w, post, grid, st, end);
    }
    if post.arcs == ArcMode::Lines || post.knife.is_some() {
        let chord = (post.chord * post.unit_scale()).max(grid.step() / 2.0);
        return linearise(w, post, grid, st, s, r, chord);
    }
    let max = post.max_arc_sweep_deg.to_radians();
    // |sweep| = 4·atan|b| ≤ max: one piece (the count below has 1e-9 of
    // the sweep to spare, so a bulge a rounding above the limit still gives
    // one). The posts' 180° needs no tan: tan 45° = 1.
    let limit = if post.max_arc_sweep_deg == 180.0 {
        1.0
    } else {
        (max / 4.0).tan()
    };
    if b <= limit * (1.0 + 1e-12) {
        // Most arcs: written whole, from the centre already at hand.
        return arc_to(w, post, grid, st, end, c, s.is_ccw(), s, r);
    }
    let sweep = s.sweep();
    let n = ((sweep.abs() / max) - 1e-9).ceil().clamp(1.0, 64.0) as usize;
    let bulge = (sweep / n as f64 / 4.0).tan();
    for i in 0..n {
        let piece = Segment {
            a: s.point_at(i as f64 / n as f64),
            b: if i + 1 == n {
                s.b
            } else {
                s.point_at((i + 1) as f64 / n as f64)
            },
            bulge,
        };
        arc(w, post, grid, st, &piece);
    }
}

fn arc(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, s: &Segment) {
    let end = grid.snap(s.b);
    let Some((c, r)) = s.arc_center() else {
        return line_to(w, post, grid, st, end);
    };
    arc_to(w, post, grid, st, end, c, s.is_ccw(), s, r)
}

/// One arc block to the grid point `end` about the centre `c` (of `s`,
/// radius `r`, for the lines it falls back to).
#[allow(clippy::too_many_arguments)] // the arc's geometry, computed once by the caller
fn arc_to(
    w: &mut Writer,
    post: &Post,
    grid: &Grid,
    st: &mut State,
    end: (i64, i64),
    c: Point,
    ccw: bool,
    s: &Segment,
    r: f64,
) {
    if end == st.pos {
        return;
    }
    let Some((i, j)) = grid.arc_center(st.pos, end, c) else {
        // No grid centre fits both ends: lines within half a grid step.
        return linearise(w, post, grid, st, s, r, grid.step() / 2.0);
    };
    let ij;
    let r_word;
    let extra: &[(&str, i64)] = match post.arcs {
        ArcMode::IjIncremental | ArcMode::Lines => {
            ij = [("I", i), ("J", j)];
            &ij
        }
        ArcMode::IjAbsolute => {
            ij = [("I", st.pos.0 + i), ("J", st.pos.1 + j)];
            &ij
        }
        ArcMode::R => {
            // At least half the chord, rounded up: the control must reach the end.
            let half = (((end.0 - st.pos.0) as f64).hypot((end.1 - st.pos.1) as f64) / 2.0).ceil();
            let rr = ((i as f64).hypot(j as f64).round()).max(half) as i64;
            r_word = [("R", rr)];
            &r_word
        }
    };
    let word = if ccw { &post.ccw } else { &post.cw };
    motion(w, grid, st, word, end, extra);
}

fn line_to(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, q: (i64, i64)) {
    let mut axis: Option<(&str, i64)> = None;
    if post.knife.is_some() {
        let d = ((q.0 - st.pos.0) as f64, (q.1 - st.pos.1) as f64);
        if d != (0.0, 0.0) {
            let before = st.heading;
            let h = turn_to(grid, st, d.1.atan2(d.0).to_degrees());
            let lift = post.knife.as_ref().map_or(180.0, |k| k.lift_angle_deg);
            let turn = before.map_or(0.0, |b| (h - b).abs() as f64 / grid.scale());
            if turn > lift {
                // Too sharp to drag the knife round: lift, turn, plunge (paper 003).
                w.templates(&post.torch_off);
                knife_word(w, post, grid, &post.rapid, h);
                w.templates(&post.torch_on);
                if w.pass_depth {
                    // Back down to this pass's depth, not the first cut's.
                    w.templates(&post.pass_z);
                }
            } else if before != Some(h) {
                if let Some(k) = &post.knife {
                    axis = Some((k.axis.as_str(), h));
                }
            }
        }
    }
    motion(w, grid, st, &post.line, q, axis.as_slice());
}

/// The unwrapped heading (grid units) nearest the last one for `deg`.
fn turn_to(grid: &Grid, st: &mut State, deg: f64) -> i64 {
    let full = (360.0 * grid.scale()).round() as i64;
    let want = (deg * grid.scale()).round() as i64;
    let h = match st.heading {
        None => want,
        Some(prev) => {
            let d = (want - prev).rem_euclid(full);
            let d = if d > full / 2 { d - full } else { d };
            prev + d
        }
    };
    st.heading = Some(h);
    h
}

fn knife_word(w: &mut Writer, post: &Post, grid: &Grid, word: &str, h: i64) {
    if let Some(k) = &post.knife {
        w.block(&[word.to_string(), format!("{}{}", k.axis, grid.fmt(h))]);
    }
}

fn linearise(
    w: &mut Writer,
    post: &Post,
    grid: &Grid,
    st: &mut State,
    s: &Segment,
    r: f64,
    chord: f64,
) {
    let n = flatten_count(r, s.sweep().abs(), chord);
    for i in 1..=n {
        let p: Point = if i == n {
            s.b
        } else {
            s.point_at(i as f64 / n as f64)
        };
        let q = grid.snap(p);
        if q != st.pos {
            line_to(w, post, grid, st, q);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{Cut, Step};

    fn half_circle_plan() -> CutPlan {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        CutPlan {
            common_line: Vec::new(),
            cuts: vec![Cut {
                pierce: s.a,
                steps: vec![Step {
                    segment: s,
                    role: Role::Contour,
                    contour: Some(0),
                }],
                contours: vec![0],
                part: Some(1),
                kind: ContourKind::Outer,
                spot: false,
                small_hole: false,
                comp: None,
            }],
            ..CutPlan::default()
        }
    }

    fn body(post: &Post) -> Vec<String> {
        let job = JobInfo {
            feed: 1000.0,
            kerf: 0.0,
            pierce_delay: 0.0,
            ..JobInfo::from_options(&crate::gcode::GcodeOptions::DEFAULT)
        };
        gcode(&half_circle_plan(), post, &job)
            .lines()
            .filter(|l| ["G1 ", "G2 ", "G3 ", "X"].iter().any(|w| l.starts_with(w)))
            .map(String::from)
            .collect()
    }

    #[test]
    fn a_half_circle_is_one_g3_with_a_consistent_centre() {
        assert_eq!(body(&Post::default()), ["G3 X-10 Y0 I-10 J0"]);
    }

    #[test]
    fn arcs_split_at_the_posts_sweep_and_written_as_r_or_absolute_centres() {
        let r = Post {
            arcs: ArcMode::R,
            max_arc_sweep_deg: 90.0,
            ..Post::default()
        };
        assert_eq!(body(&r), ["G3 X0 Y10 R10", "G3 X-10 Y0 R10"]);
        let abs = Post {
            arcs: ArcMode::IjAbsolute,
            modal: true,
            max_arc_sweep_deg: 90.0,
            ..Post::default()
        };
        assert_eq!(body(&abs), ["G3 X0 Y10 I0 J0", "X-10 Y0 I0 J0"]);
    }
}
