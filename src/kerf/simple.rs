//! The kerf offset's short way, for the loops that need none of
//! cavalier_contours' self-intersection machinery: most parts of a sheet
//! (a rectangle, a round hole).
//!
//! cavalier_contours 0.9 offsets a closed loop in four steps
//! (`parallel_offset` → `parallel_offset_for_source`): the raw offset (every
//! segment moved, arcs' radii changed, joins by arcs or trimmed), the raw
//! offset's self-intersections (local: each segment with the next; global:
//! the other pairs whose boxes in a spatial index meet), slicing at them with
//! a distance check of each slice against the source, and stitching. When
//! the raw offset has no invalid (reversed, collapsed) segment and no
//! self-intersection, the slicing keeps the whole raw offset if its first
//! vertex is far enough from the source, and the stitching copies it.
//!
//! [`offset_closed`] takes the same steps in the same order with the same
//! functions (the raw offset, the local search, the distance predicate and
//! the copy are cavalier_contours' own), but replaces the two spatial
//! indexes by a direct test of the same boxes (`seg_fast_approx_bounding_box`,
//! as `create_approx_aabb_index` stores them, with the same inclusive
//! overlap and the same `pos_equal_eps` margin): when no two non-adjacent
//! segments' boxes meet, the index would have offered the global search no
//! pair to test, so it finds nothing, and the answer is the one the library
//! gives, bit for bit. (Where every meeting of the loop is smooth or an
//! outer corner, the raw offset itself is built from the geometry by
//! `raw.rs`, which allocates nothing and takes no angle: the library's
//! up to rounding, and the programs the same.) Any other loop (boxes that meet, an invalid segment,
//! a local intersection, more than [`MAX_SEGMENTS`] segments) goes the
//! library's whole way. `crossings` does the same for the drawn loop's own
//! self-crossing check (exact boxes there, as `create_aabb_index` stores).

use cavalier_contours::polyline::internal::raw_pline_offset::{create_raw_offset, RawOffsetResult};
use cavalier_contours::polyline::{
    seg_bounding_box, seg_distance_is_greater_than, seg_fast_approx_bounding_box, PlineIntersect,
    PlineOffsetOptions, PlineSelfIntersectOptions, PlineSource, PlineSourceMut, PlineVertex,
    PlineViewData, Polyline, SelfIntersectsInclude,
};

use super::raw;
use crate::geom::Point;

/// Above this many segments the pairwise box test (n²/2 pairs) gives way
/// to the library's spatial index.
const MAX_SEGMENTS: usize = 48;

/// The box of a segment, as one of cavalier_contours' indexes stores it.
type BoxOf = fn(PlineVertex<f64>, PlineVertex<f64>) -> [f64; 4];

fn approx_box(v1: PlineVertex<f64>, v2: PlineVertex<f64>) -> [f64; 4] {
    let b = seg_fast_approx_bounding_box(v1, v2);
    [b.min_x, b.min_y, b.max_x, b.max_y]
}

fn exact_box(v1: PlineVertex<f64>, v2: PlineVertex<f64>) -> [f64; 4] {
    let b = seg_bounding_box(v1, v2);
    [b.min_x, b.min_y, b.max_x, b.max_y]
}

/// True when the library's global self-intersection search
/// (`visit_global_self_intersects`) would test no pair of `pl`'s segments:
/// no segment's box, grown by `eps`, meets the box of a later segment that
/// is not its neighbour (the index's query and its two filters, written
/// out). None when `pl` is too long to test pair by pair.
fn no_global_pairs(pl: &Polyline<f64>, eps: f64, box_of: BoxOf) -> Option<bool> {
    let n = pl.vertex_count();
    if n < 3 {
        // The library's global search skips these loops altogether.
        return Some(true);
    }
    // A rectangle's offset has 8 segments: its boxes in a small array (the
    // large one's zeroing was most of this test's time).
    if n <= 8 {
        return Some(no_pairs_in::<8>(pl, eps, box_of));
    }
    if n > MAX_SEGMENTS {
        return None;
    }
    Some(no_pairs_in::<MAX_SEGMENTS>(pl, eps, box_of))
}

/// [`no_global_pairs`] for a loop of 3 to `N` segments.
fn no_pairs_in<const N: usize>(pl: &Polyline<f64>, eps: f64, box_of: BoxOf) -> bool {
    let n = pl.vertex_count();
    let mut boxes = [[0.0f64; 4]; N];
    for (i, b) in boxes.iter_mut().enumerate().take(n) {
        *b = box_of(pl.at(i), pl.at((i + 1) % n));
    }
    for i in 0..n {
        let q = boxes[i];
        let (x0, y0, x1, y1) = (q[0] - eps, q[1] - eps, q[2] + eps, q[3] + eps);
        // Later segments only (the library tests each pair from its lower
        // index), not the next one, and not the last when i is the first.
        let last = if i == 0 { n - 1 } else { n };
        for b in boxes.iter().take(last).skip(i + 2) {
            // static_aabb2d_index's `AABB::overlaps`: inclusive.
            if !(b[2] < x0 || b[3] < y0 || b[0] > x1 || b[1] > y1) {
                return false;
            }
        }
    }
    true
}

/// Where a closed polyline crosses or runs along itself: what
/// `visit_self_intersects_opt` reports with an index of exact boxes and
/// `SelfIntersectsInclude::All` (an overlap counts its two ends).
pub(crate) fn crossings(pl: &Polyline<f64>, eps: f64) -> Vec<Point> {
    let mut at = Vec::new();
    let mut visit = |x: PlineIntersect<f64>| match x {
        PlineIntersect::Basic(b) => at.push(Point::new(b.point.x, b.point.y)),
        PlineIntersect::Overlapping(o) => {
            at.push(Point::new(o.point1.x, o.point1.y));
            at.push(Point::new(o.point2.x, o.point2.y));
        }
    };
    if no_global_pairs(pl, eps, exact_box) == Some(true) {
        if lines_meet_at_corners(pl, eps) {
            // Nor would the local search (a rectangle's four corners).
            return at;
        }
        // Local pairs only: the global search would find nothing.
        pl.visit_self_intersects_opt(
            &mut visit,
            &PlineSelfIntersectOptions {
                aabb_index: None,
                pos_equal_eps: eps,
                include: SelfIntersectsInclude::Local,
            },
        );
        return at;
    }
    let index = pl.create_aabb_index();
    pl.visit_self_intersects_opt(
        &mut visit,
        &PlineSelfIntersectOptions {
            aabb_index: Some(&index),
            pos_equal_eps: eps,
            include: SelfIntersectsInclude::All,
        },
    );
    at
}

/// True when the library's local self-intersection search reports nothing
/// on `pl`: a closed loop of three or more lines, no vertex fuzzy equal to
/// the next, each corner turning by a cross product of at least `eps`.
///
/// Why. The search tests each line v1→v2 against the next, v2→v3
/// (`line_line_intr(v1, v2, v2, v3)`), after reporting a vertex equal to
/// the next. With v = v2 − v1, u = v3 − v2 and w = v1 − v2 = −v exactly
/// (a difference's rounding is symmetric), the line parameters are
/// u×w / v×u and v×w / v×u, the library's own products: u×w rounds the
/// very products of v×u, negated, so the first is exactly 1, and v×w is
/// v.x(−v.y) − v.y(−v.x), exactly 0. When |v×u| is not below `eps` (the
/// test this function makes with the same arithmetic) the library takes
/// that branch, finds the point at t = 1, v1 + (v2 − v1), within a few
/// ulps of v2, and reports only points farther than `eps` from v2: none,
/// for coordinates below 1e12 `eps` (their ulps far below `eps`).
fn lines_meet_at_corners(pl: &Polyline<f64>, eps: f64) -> bool {
    let n = pl.vertex_count();
    if n < 3 || !pl.is_closed() {
        return false;
    }
    (0..n).all(|i| {
        let (v1, v2, v3) = (pl.at(i), pl.at((i + 1) % n), pl.at((i + 2) % n));
        let (v, u) = (v2.pos() - v1.pos(), v3.pos() - v2.pos());
        v1.bulge_is_zero()
            && v1.x.abs().max(v1.y.abs()) < 1e12 * eps
            && !v1.pos().fuzzy_eq_eps(v2.pos(), eps)
            && v.perp_dot(u).abs() >= eps
    })
}

/// `pl.parallel_offset_opt(d, options)` for a closed loop, the short way
/// when it gives the same answer (see the module's note): what `kerf::offset`
/// does with [`short_way_into`].
#[cfg(test)]
pub(crate) fn offset_closed(
    pl: &Polyline<f64>,
    d: f64,
    options: &PlineOffsetOptions<f64>,
) -> Vec<Polyline<f64>> {
    short_way(pl, d, options).unwrap_or_else(|| pl.parallel_offset_opt(d, options))
}

/// The offset when the raw offset needs no slicing; None otherwise.
#[cfg(test)]
pub(crate) fn short_way(
    pl: &Polyline<f64>,
    d: f64,
    options: &PlineOffsetOptions<f64>,
) -> Option<Vec<Polyline<f64>>> {
    let mut scratch = Scratch::default();
    let one = short_way_into(pl, d, options, false, &mut scratch)?;
    Some(if one {
        vec![scratch.offset().clone()]
    } else {
        Vec::new()
    })
}

/// Buffers kept from loop to loop: the raw offset's segments and polyline,
/// and the offset.
pub(crate) struct Scratch {
    raw: raw::RawOffset,
    rp: Polyline<f64>,
    out: Polyline<f64>,
    /// The offset is the raw offset itself (`rp`), not a copy in `out`.
    in_raw: bool,
}

impl Scratch {
    /// The offset [`short_way_into`] found.
    pub(crate) fn offset(&self) -> &Polyline<f64> {
        if self.in_raw {
            &self.rp
        } else {
            &self.out
        }
    }
}

impl Default for Scratch {
    fn default() -> Self {
        Scratch {
            raw: raw::RawOffset::default(),
            rp: Polyline::new(),
            out: Polyline::new(),
            in_raw: false,
        }
    }
}

/// [`short_way`] written into `scratch.out` (buffers reused from loop to
/// loop, where [`short_way`] allocates them and grows them vertex by
/// vertex; the raw offset by [`raw::RawOffset`] where it can):
/// Some(true) when the offset is the one loop left in `scratch.out`,
/// Some(false) when it is nothing, None when the library must go its way.
/// `clean`: the caller knows that `pl` has no repeated position at
/// `options.pos_equal_eps` (`remove_repeat_pos` at a tolerance at least
/// as wide found none: a pair within the narrower is within the wider).
pub(crate) fn short_way_into(
    pl: &Polyline<f64>,
    d: f64,
    options: &PlineOffsetOptions<f64>,
    clean: bool,
    scratch: &mut Scratch,
) -> Option<bool> {
    let Scratch {
        raw,
        rp: raw_buf,
        out,
        in_raw,
    } = scratch;
    out.clear();
    *in_raw = false;
    let eps = options.pos_equal_eps;
    // The library's own cases first: nothing to offset, a copy, a source
    // it cleans (and indexes anew), a caller's index, the dual offsets.
    if pl.vertex_count() < 2
        || d == 0.0
        || !pl.is_closed()
        || options.aabb_index.is_some()
        || options.handle_self_intersects
        || (!clean && pl.remove_repeat_pos(eps).is_some())
    {
        return None;
    }
    let library;
    let written_out = raw.closed_into(pl, d, eps, raw_buf);
    let rp: &Polyline<f64> = if written_out {
        raw_buf
    } else {
        let r: RawOffsetResult<Polyline<f64>> = create_raw_offset(pl, d, eps);
        if !r.invalid_segment_indexes.is_empty() {
            return None;
        }
        library = r.polyline;
        &library
    };
    if rp.vertex_count() < 2 {
        return None;
    }
    if no_global_pairs(rp, eps, approx_box) != Some(true) {
        return None;
    }
    // A raw offset of lines and rounded corners has no local
    // self-intersection the search could report (the proof is at
    // `no_local_crossing`): a rectangle's eight pairs of line and arc.
    let mut local = false;
    let tangent = written_out && raw.no_local_crossing();
    if !tangent {
        rp.visit_self_intersects_opt(
            &mut |_: PlineIntersect<f64>| local = true,
            &PlineSelfIntersectOptions {
                aabb_index: None,
                pos_equal_eps: eps,
                include: SelfIntersectsInclude::Local,
            },
        );
    }
    if local {
        return None;
    }
    // No slice boundary: the whole raw offset, if its first vertex is
    // farther from the source than the offset (`point_valid_for_offset`,
    // its index query written out over the source's approximate boxes).
    let p = rp.at(0).pos();
    let reach = d.abs() - options.offset_dist_eps;
    let n = pl.vertex_count();
    let valid = (0..n).all(|i| {
        let (v1, v2) = (pl.at(i), pl.at((i + 1) % n));
        let b = approx_box(v1, v2);
        let (x0, y0, x1, y1) = (p.x - reach, p.y - reach, p.x + reach, p.y + reach);
        b[2] < x0
            || b[3] < y0
            || b[0] > x1
            || b[1] > y1
            || seg_distance_is_greater_than(v1, v2, p, reach, eps)
    });
    if !valid {
        return Some(false);
    }
    // `stitch_slices_together` with one slice: the raw offset copied
    // without repeated positions, closed. Where no two neighbours (the
    // last and the first too) are fuzzy equal, the copy is the raw offset
    // vertex for vertex (its closing point, the first again, is dropped):
    // the raw offset itself is the answer, with no copy.
    if written_out && !repeats(rp, eps) {
        *in_raw = true;
        return Some(true);
    }
    out.set_is_closed(false);
    out.extend_remove_repeat(&PlineViewData::from_entire_pline(rp).view(rp), eps);
    if out.vertex_count() > 1 {
        let last = out.last().map(|v| v.pos());
        if last.is_some_and(|q| out.at(0).pos().fuzzy_eq_eps(q, eps)) {
            out.remove_last();
            if out.vertex_count() > 1 {
                out.set_is_closed(true);
            }
        }
    }
    Some(out.vertex_count() > 1)
}

/// True when two neighbouring vertices of a closed polyline are fuzzy
/// equal (the last and the first among them).
fn repeats(pl: &Polyline<f64>, eps: f64) -> bool {
    let n = pl.vertex_count();
    (0..n).any(|i| pl.at(i).pos().fuzzy_eq_eps(pl.at((i + 1) % n).pos(), eps))
}

#[cfg(test)]
#[path = "simple_tests.rs"]
mod tests;
