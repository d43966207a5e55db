//! The contour cuts of a tour built on the threads (issue 17). A cut
//! depends on its kerf path and its entry point alone, not on the cut
//! before ([`cuts::Builder::contour_cut`]), so cuts may be built in any
//! order on any thread; what their leads gave way to (the builder's
//! warnings) is joined in visit order, and the plan and its warnings are
//! the same with any number of threads.
//! Ranges of the tour's visits, a builder each ([`in_ranges`]).
//!
//! Tried and dropped: every cut built ahead on a second thread from the
//! free search's entries while the tour was repaired and polished, only
//! those whose entry the tour then changed built again: on the 25 MB nest
//! the polish re-chose half the entries (68k of 137k cuts built twice).

use super::clearance::Obstacles;
use super::cuts::Builder;
use super::tsp::Tour;
use super::{Cut, PlanInput, PlanOptions};
use crate::geom::Point;

/// Cuts built a batch at a time, the batch's kerf paths read first
/// ([`Builder::warm`]): ~64 paths' records and loops (~20 KB) stay
/// in the core's cache until their cuts are built.
const WARM: usize = 64;

/// Fewest visits a thread builds the cuts of (a cut takes ~1 us on the
/// 25 MB nest: a chunk a few ms, well above a thread's start).
const CUTS_CHUNK: usize = 4096;

/// The cuts of `visits` entered at `points` (the tour's), in order. The
/// entry points from the tour itself (read through the sites in the
/// tour's order they were a cache miss a contour on big sheets). The
/// paths read a batch ahead ([`Builder::warm`]).
fn contour_cuts(b: &mut Builder, visits: &[(usize, usize)], points: &[Point]) -> Vec<Cut> {
    let mut out = Vec::with_capacity(visits.len());
    for (visits, points) in visits.chunks(WARM).zip(points.chunks(WARM)) {
        b.warm(visits.iter().map(|&(k, _)| k));
        for (&(k, _), &near) in visits.iter().zip(points) {
            if let Some(cut) = b.contour_cut(k, near) {
                out.push(cut);
            }
        }
    }
    out
}

/// The tour's cuts after `open`, on ranges of its visits, a builder each,
/// what they gave way to taken on by `builder` in visit order.
pub fn in_ranges(
    builder: &mut Builder,
    input: &PlanInput,
    options: &PlanOptions,
    starts: &[(usize, Point)],
    obstacles: &Obstacles,
    tour: &Tour,
    open: Vec<Cut>,
) -> Vec<Cut> {
    let n = tour.visits.len();
    let ranges = crate::par::map_ranges(n, options.threads, CUTS_CHUNK, |r| {
        let mut b = Builder::new(input, options, starts, obstacles);
        let cuts = contour_cuts(&mut b, &tour.visits[r.clone()], &tour.points[r]);
        (cuts, b.into_gave_way())
    });
    let mut cuts = open;
    for (mut part, gave_way) in ranges {
        if cuts.is_empty() {
            cuts = part;
        } else {
            cuts.append(&mut part);
        }
        builder.absorb(gave_way);
    }
    cuts
}
