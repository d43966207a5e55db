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
//! - The cuts are written by a [`Cutter`], one after the other; with
//!   several threads, in runs of cuts at once ([`super::runs`]).

use crate::contour::ContourKind;
use crate::plan::{CutPlan, Move};
use crate::process::{Passes, ThcLock};

use super::motion::{knife_word, motion, turn_to, State};
use super::number::Grid;
use super::post::Post;
use super::step::feed_step;
use super::thc::Height;
use super::{JobInfo, Writer};

/// The emitter between two cuts: the program so far and everything a cut
/// written next depends on (the machine's state, the writer's modal words,
/// the height lock).
#[derive(Clone)]
pub(super) struct Cutter<'a> {
    pub(super) w: Writer<'a>,
    pub(super) plan: &'a CutPlan,
    pub(super) post: &'a Post,
    job: JobInfo,
    grid: Grid,
    k: f64,
    delay: bool,
    passes: Passes,
    lock_rule: ThcLock,
    pub(super) st: State,
    /// The cut being written is cut in depth passes (its feed moves were
    /// written at its pierce).
    in_passes: bool,
    /// The cut being written: a mark (its own tool codes), a small hole (its
    /// own speed, the height locked); whether the radius compensation is on.
    mark: bool,
    small: bool,
    comp: bool,
    height: Height,
}

impl<'a> Cutter<'a> {
    /// The program's start and header written.
    pub(super) fn new(plan: &'a CutPlan, post: &'a Post, job: &JobInfo) -> Cutter<'a> {
        Cutter::with_milling(plan, None, post, job)
    }
    /// A router's: `milling` is cut before the plan (its time in the
    /// header's `{est_time_s}`).
    pub(super) fn with_milling(
        plan: &'a CutPlan,
        milling: Option<&'a crate::mill::Toolpath>,
        post: &'a Post,
        job: &JobInfo,
    ) -> Cutter<'a> {
        let k = post.unit_scale();
        let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
        let mut w = Writer::new(post, plan, job);
        w.milling = milling;
        // Several tools: the header's is the first to work.
        if let Some(crate::mill::MillMove::ToolChange(t)) = milling.and_then(|m| m.moves.first()) {
            w.set_tool(t);
        }
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
            grid.fmt_mm(job.process.kerf),
            grid.fmt_mm(job.process.feed)
        ));
        if let Some(t) = job.process.torches {
            w.comment(&t.comment());
        }
        // Several tools: the one to load first (the header's).
        if let Some(crate::mill::MillMove::ToolChange(t)) = milling.and_then(|m| m.moves.first()) {
            w.tool_comment("first tool", &t.tool);
        }
        w.templates(&post.header);
        let passes = job.process.passes;
        if passes.on() {
            // The first rapid must not find the tool below the surface.
            w.templates(&post.pass_retract);
        }
        let mut st = State::at(grid.snap(plan.origin.scale(k)));
        if let Some(park) = job.process.torches.and_then(|t| t.park) {
            // Paper 001 §6.5 (L2825–L2828): the gantry parks and the program
            // stops for the operator to set the torches, before the first cut.
            let q = grid.snap(park.scale(k));
            motion(&mut w, &grid, &mut st, &post.rapid, q, &[]);
            w.comment("operator stop: set the torches, then cycle start");
            w.templates(&["M0".to_string()]);
        }
        // Corner and end locks in one-pass cuts (depth passes are for knives
        // and routers, which have no height control), on posts that can lock
        // (the others' moves are not split for nothing).
        let lock_rule = if passes.on() || post.thc_lock.is_empty() {
            ThcLock::OFF
        } else {
            job.process.thc_lock
        };
        Cutter {
            w,
            plan,
            post,
            job: *job,
            grid,
            k,
            delay: job.process.pierce_delay > 0.0,
            passes,
            lock_rule,
            st,
            in_passes: false,
            mark: false,
            small: false,
            comp: false,
            height: Height::default(),
        }
    }

    /// Cut `i` written (`plan.moves()` taken apart: a loop over the cut's
    /// steps; the chained iterator's state was a tenth of the emitter's
    /// own time).
    pub(super) fn cut(&mut self, i: usize) {
        let c = &self.plan.cuts[i];
        self.write(Move::Rapid(c.pierce));
        if c.spot {
            self.write(Move::Spot(i));
            for s in &c.steps {
                self.write(Move::Feed(*s));
            }
        } else {
            self.write(Move::Pierce(i));
            for s in &c.steps {
                self.write(Move::Feed(*s));
            }
            self.write(Move::TorchOff);
        }
    }

    /// The footer and the program's end written: the program.
    pub(super) fn finish(mut self) -> String {
        self.w.templates(&self.post.footer);
        self.w.raws(&self.post.program_end);
        self.w.finish()
    }

    /// True when a cut written next from `self` and from `o` writes the
    /// same blocks and leaves the same state: everything but the program
    /// so far is the same (a lock's progress only while a change is due).
    pub(super) fn same_course(&self, o: &Cutter) -> bool {
        self.w.same_course(&o.w)
            && self.st == o.st
            && (self.in_passes, self.mark, self.small, self.comp)
                == (o.in_passes, o.mark, o.small, o.comp)
            && self.height.same_course(&o.height)
    }

    fn write(&mut self, m: Move) {
        let Cutter {
            w,
            plan,
            post,
            job,
            grid,
            k,
            delay,
            passes,
            lock_rule,
            st,
            in_passes,
            mark,
            small,
            comp,
            height,
        } = self;
        let (plan, post, grid, k, delay, passes) = (*plan, *post, &*grid, *k, *delay, *passes);
        let either = |own: &'a [String], fallback: &'a [String]| -> &'a [String] {
            if own.is_empty() {
                fallback
            } else {
                own
            }
        };
        match m {
            Move::Rapid(p) => {
                let q = grid.snap(p.scale(k));
                motion(w, grid, st, &post.rapid, q, &[]);
            }
            Move::Pierce(i) => {
                let c = plan.cuts.get(i);
                *mark = c.is_some_and(|c| c.is_mark());
                *small = c.is_some_and(|c| c.small_hole);
                if let Some(c) = c {
                    let what = match c.kind {
                        _ if *mark => "mark",
                        ContourKind::Hole if *small => "small hole",
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
                            let h = turn_to(grid, st, t.y.atan2(t.x).to_degrees());
                            knife_word(w, post, grid, &post.rapid, h);
                        }
                    }
                }
                if *mark {
                    // A scribe marks on the surface: no probe, no pierce, no height control.
                    w.templates(either(&post.mark_on, &post.torch_on));
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
                    *comp = true;
                }
                if *small {
                    w.templates(&post.thc_lock);
                    height.locked = !post.thc_lock.is_empty();
                    w.templates(&post.small_hole_on);
                } else {
                    w.templates(&post.thc_on);
                }
                if let Some(c) = c {
                    height.start(c, lock_rule);
                }
                if let (true, Some(c)) = (passes.on(), c) {
                    super::passes::depth_passes(w, grid, st, c, job, k, height);
                    *in_passes = true;
                }
            }
            Move::Feed(step) => {
                if *in_passes {
                    // Written with the passes at the pierce.
                    return;
                }
                feed_step(w, grid, st, &step, k, *mark, height, job);
            }
            Move::TorchOff => {
                if *mark {
                    w.templates(either(&post.mark_off, &post.torch_off));
                    *mark = false;
                    return;
                }
                if std::mem::take(in_passes) {
                    // Up out of the cut once, after the last pass.
                    w.templates(&post.pass_retract);
                    w.pass_depth = false;
                }
                if std::mem::take(small) {
                    w.templates(&post.small_hole_off);
                }
                if std::mem::take(comp) {
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
}

#[cfg(test)]
#[path = "emit_tests.rs"]
mod tests;
