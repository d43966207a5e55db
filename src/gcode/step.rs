//! One feed step of a cut as the post writes it: split where the torch
//! height is locked or released ([`super::thc`]), a tab crossed with the
//! torch off ([`super::tabs`]).

use super::motion::{feed, scaled, State};
use super::number::Grid;
use super::thc::Height;
use super::{JobInfo, Writer};
use crate::plan::Role;

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
