//! Crossing a tab (issue 20 §6, [`crate::plan::tabs`]): the plan says where
//! (a [`Role::Tab`](crate::plan::Role::Tab) step over the contour); the
//! post says how.
//!
//! - A post with `tab_off`/`tab_on` templates (a controller that can switch
//!   the torch off and on again while moving) writes them around a feed
//!   move over the tab.
//! - Any other post turns the torch off as at a cut's end (`thc_off`,
//!   `torch_off`; a Z post's `torch_off` lifts the torch, a knife's lifts
//!   the knife), rapids to the tab's far end and pierces again there as at
//!   a cut's start (`probe`, `torch_on`, `dwell`, `after_pierce`, `thc_on`):
//!   a new pierce, counted as one by the plan's statistics. In depth passes
//!   the tool also comes up out of the cut (`pass_retract`) and goes back
//!   down to the pass's depth (`pass_z`) after.

use super::motion::{feed, motion, scaled, State};
use super::number::Grid;
use super::{JobInfo, Writer};
use crate::plan::Step;

/// Writes the crossing of one tab step. `locked`: the torch height is
/// locked (it stays so over the restart).
pub(super) fn cross(
    w: &mut Writer,
    grid: &Grid,
    st: &mut State,
    step: &Step,
    k: f64,
    job: &JobInfo,
    locked: bool,
) {
    let post = w.post;
    let s = scaled(&step.segment, k);
    let bridge = (w.pass_depth && super::router_time::is_router(post))
        .then(|| job.process.tool.tab_top(job.process.passes.depth))
        .flatten();
    if let Some(top) = bridge {
        // A router's bridge at the bottom (issue 43 §3): a pass above its
        // top cuts through; a deeper one goes up to the top at rapid
        // (out of material), across at the feed, and down again at the
        // plunge feed (`pass_z`).
        let z = w.pass_mm;
        if z >= top - 1e-9 {
            feed(w, post, grid, st, &s);
            return;
        }
        w.comment("tab");
        w.set_pass_z(top);
        let up = format!("{} Z{{pass_z}}", post.rapid);
        w.templates(std::slice::from_ref(&up));
        w.reset_feed();
        feed(w, post, grid, st, &s);
        w.set_pass_z(z);
        w.templates(&post.pass_z);
        w.reset_feed();
        return;
    }
    w.comment("tab");
    if !post.tab_off.is_empty() {
        w.templates(&post.tab_off);
        feed(w, post, grid, st, &s);
        w.templates(&post.tab_on);
        return;
    }
    w.templates(&post.thc_off);
    w.templates(&post.torch_off);
    if w.pass_depth {
        w.templates(&post.pass_retract);
    }
    let q = grid.snap(s.b);
    motion(w, grid, st, &post.rapid, q, &[]);
    if !post.probe.is_empty() {
        w.templates(&post.probe);
        w.reset_feed();
    }
    w.templates(&post.torch_on);
    if job.process.pierce_delay > 0.0 {
        w.templates(&post.dwell);
    }
    w.templates(&post.after_pierce);
    if !locked {
        w.templates(&post.thc_on);
    }
    if w.pass_depth {
        w.templates(&post.pass_z);
    }
}
