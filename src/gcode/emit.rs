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
use crate::plan::{CutPlan, Move};

use super::motion::{knife_word, motion, turn_to, State};
use super::number::Grid;
use super::post::Post;
use super::step::feed_step;
use super::{JobInfo, Writer};

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
    let mut st = State::at(grid.snap(plan.origin.scale(k)));
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
    // `plan.moves()` taken apart: a loop over the cuts and their steps (the
    // chained iterator's state was a tenth of the emitter's own time).
    let mut write = |m: Move| {
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
                    w.cut_comment(
                        i as u64 + 1,
                        c.part.map(|p| p as u64),
                        what,
                        c.contours.first().map(|&k| k as u64 + 1),
                    );
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
                    return;
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
                    return;
                }
                feed_step(&mut w, &grid, &mut st, &step, k, mark, &mut height, job);
            }
            Move::TorchOff => {
                if mark {
                    w.templates(&either(&post.mark_off, &post.torch_off));
                    mark = false;
                    return;
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
    };
    for (i, c) in plan.cuts.iter().enumerate() {
        write(Move::Rapid(c.pierce));
        if c.spot {
            write(Move::Spot(i));
            for s in &c.steps {
                write(Move::Feed(*s));
            }
        } else {
            write(Move::Pierce(i));
            for s in &c.steps {
                write(Move::Feed(*s));
            }
            write(Move::TorchOff);
        }
    }
    w.templates(&post.footer);
    w.raws(&post.program_end);
    w.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gcode::ArcMode;
    use crate::geom::{Point, Segment};
    use crate::plan::{Cut, Role, Step};

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
    fn the_stats_variables_are_filled_in_when_a_template_asks() {
        // The writer computes the plan's stats only for these two.
        let post = Post {
            header: vec!["(time {est_time_s} s, {pierces} pierces, again {pierces})".into()],
            ..Post::default()
        };
        let job = JobInfo::from_options(&crate::gcode::GcodeOptions::DEFAULT);
        let plan = half_circle_plan();
        let time = Grid::new(post.decimals).fmt_mm(super::super::est_time_s(&plan, &post, &job));
        assert_ne!(time, "0");
        let want = format!("(time {time} s, 1 pierces, again 1)");
        assert!(
            gcode(&plan, &post, &job).lines().any(|l| l == want),
            "{want}"
        );
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
