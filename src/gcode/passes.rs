//! Depth passes (issue 20 §8, paper 004: n = ceil(H / d_max), d = H / n):
//! one cut's feed moves written n times at decreasing Z. Moved out of
//! `emit.rs`, which calls it at the pierce.

use super::motion::{motion, State};
use super::number::Grid;
use super::section::{releads, section};
use super::step::feed_step;
use super::thc::Height;
use super::{JobInfo, Writer};
use crate::geom::Segment;

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
///
/// A router is the exception for a closed contour with lead arcs (issue
/// 43 §3): its end mill would otherwise go down on the finished wall at
/// every pass after the first, and leave a mark there. Each pass is cut
/// whole — lead-in, contour, lead-out — and between passes the tool comes
/// up where the lead-out left it, in the waste (`pass_retract`), and goes
/// across to the lead-in's start at rapid ([`releads`]).
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
    let Some((first, last, _)) = section(c) else {
        return;
    };
    let section = &c.steps[first..=last];
    let closed = grid.snap(section[0].segment.a.scale(k))
        == grid.snap(section[section.len() - 1].segment.b.scale(k));
    w.pass_depth = true;
    let again = releads(c, first, last, closed, super::router_time::is_router(post));
    let mut forward = true;
    for pass in 1..=n {
        if again && pass > 1 {
            w.templates(&post.pass_retract);
            let q = grid.snap(c.steps[0].segment.a.scale(k));
            motion(w, grid, st, &post.rapid, q, &[]);
        }
        w.set_pass_z(passes.z(pass));
        w.comment(&format!("pass {pass} of {n}"));
        w.templates(&post.pass_z);
        if pass == 1 || again {
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
        if again {
            for s in &c.steps[last + 1..] {
                feed_step(w, grid, st, s, k, false, locked, job);
            }
        }
    }
    if !again && (forward || closed) {
        for s in &c.steps[last + 1..] {
            feed_step(w, grid, st, s, k, false, locked, job);
        }
    }
}
