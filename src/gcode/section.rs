//! Which part of a cut is cut on every depth pass, and whether its leads
//! are too: read by the passes that write it (`passes`) and by the time
//! that counts it (`router_time`), from the plan alone.

use crate::plan::{Cut, Role, Step};

/// Cut `c`'s contour section, cut on every pass: its first and last
/// step (a contour, a repeat or a tab; the whole cut when it has none),
/// and whether it ends where it starts (within a micrometre: the post's
/// grid decides it for the program). None for a cut with no steps.
pub(crate) fn section(c: &Cut) -> Option<(usize, usize, bool)> {
    if c.steps.is_empty() {
        return None;
    }
    let in_section =
        |s: &Step| matches!(s.role, Role::Contour | Role::Repeat | Role::Tab);
    let (first, last) = match (
        c.steps.iter().position(in_section),
        c.steps.iter().rposition(in_section),
    ) {
        (Some(a), Some(b)) => (a, b),
        _ => (0, c.steps.len() - 1),
    };
    let closed = c.steps[first].segment.a.dist(c.steps[last].segment.b) < 1e-3;
    Some((first, last, closed))
}

/// True when cut `c` (its contour section from step `first` to `last`)
/// is cut with its leads on every depth pass: a `router`'s `closed`
/// contour with leads ([`super::passes::depth_passes`]; the time estimate,
/// the page's Play list and the plan SVG follow it). An end mill going
/// down onto the finished wall leaves a mark there, at every pass: it
/// goes down in the waste, at the lead-in's start, whether the lead is
/// an arc (`plan::router_lead`) or straight, and leaves by the lead-out
/// when there is one. Other machines cut the lead-in once, at the first
/// depth (a knife's, a plasma's second pass goes round without a pierce).
pub fn releads(c: &Cut, first: usize, last: usize, closed: bool, router: bool) -> bool {
    let mut leads = c.steps[..first].iter().chain(&c.steps[last + 1..]);
    router && closed && leads.next().is_some()
}
