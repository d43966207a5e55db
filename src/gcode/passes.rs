//! Depth passes (issue 20 §8, paper 004: n = ceil(H / d_max), d = H / n):
//! one cut's feed moves written n times at decreasing Z. Moved out of
//! `emit.rs`, which calls it at the pierce.

use super::motion::State;
use super::number::Grid;
use super::step::feed_step;
use super::thc::Height;
use super::{JobInfo, Writer};
use crate::geom::Segment;
use crate::plan::Role;

/// The feed moves of cut `c` in depth passes (issue 20 §8, paper 004):
/// the lead-in once at the first depth, the contour part (first to last
/// contour or repeat step, with the links between) n times at Z = -d, -2d,
/// … -H, the lead-out once at full depth. The tool plunges at the pierce
/// and at the end of each pass, and comes up once after the last.
///
/// A closed contour ends where it began, so the next pass plunges right
/// there and goes round again: no retract, no second pierce or plunge
/// elsewhere (a re-pierce is a crater on a torch and a lost second on a
/// knife or router, and its lead-in would be cut again deeper for
/// nothing). An open path does not return to its start: the next pass
/// runs back along it from its end (a zig-zag, still one plunge per pass
/// and no travel with the tool up); when that leaves the tool at the
/// path's start (an even count), its lead-out, which leaves from the end,
/// is not cut.
pub(super) fn depth_passes(
    w: &mut Writer,
    grid: &Grid,
    st: &mut State,
    c: &crate::plan::Cut,
    job: &JobInfo,
    k: f64,
    locked: &mut Height,
) {
    let post = w.post;
    let passes = job.process.passes;
    let n = passes.count();
    let in_section =
        |s: &crate::plan::Step| matches!(s.role, Role::Contour | Role::Repeat | Role::Tab);
    let (first, last) = match (
        c.steps.iter().position(in_section),
        c.steps.iter().rposition(in_section),
    ) {
        (Some(a), Some(b)) => (a, b),
        _ => (0, c.steps.len().saturating_sub(1)),
    };
    if c.steps.is_empty() {
        return;
    }
    let section = &c.steps[first..=last];
    let closed = grid.snap(section[0].segment.a.scale(k))
        == grid.snap(section[section.len() - 1].segment.b.scale(k));
    w.pass_depth = true;
    let mut forward = true;
    for pass in 1..=n {
        w.set_pass_z(passes.z(pass));
        w.comment(&format!("pass {pass} of {n}"));
        w.templates(&post.pass_z);
        if pass == 1 {
            for s in &c.steps[..first] {
                feed_step(w, grid, st, s, k, false, locked, job);
            }
        }
        if forward {
            for s in section {
                feed_step(w, grid, st, s, k, false, locked, job);
            }
        } else {
            for s in section.iter().rev() {
                let back = crate::plan::Step {
                    segment: Segment {
                        a: s.segment.b,
                        b: s.segment.a,
                        bulge: -s.segment.bulge,
                    },
                    ..*s
                };
                feed_step(w, grid, st, &back, k, false, locked, job);
            }
        }
        if !closed {
            forward = !forward;
        }
    }
    if forward || closed {
        for s in &c.steps[last + 1..] {
            feed_step(w, grid, st, s, k, false, locked, job);
        }
    }
}
