//! cavalier_contours' raw offset of a closed loop (`create_raw_offset`,
//! 0.9.0), the same arithmetic written out for the loops a sheet is full of:
//! every join of the offset either coincident (a circle's two halves) or an
//! outer round (a rectangle's corners, outwards). Any other join (an inner
//! one, to be trimmed by intersection; a reversal; a degenerate tangent) or
//! an arc offset past zero radius gives None, and the library builds it.
//!
//! Why: the library builds a vector of raw segments (each arc's start angle
//! an `atan2`, its sweep an `atan`), a polyline and two index lists a loop;
//! here the raw segments go into a buffer kept from loop to loop, the
//! polyline into another, no angle is taken, and the span bulge
//! `tan(4·atan(b) / 4)` of an arc is remembered for its bulge (a sheet's
//! circles all have bulge 1). Every operation is the library's own, in its
//! order (its `Vector2` methods, its fuzzy comparisons, its
//! `seg_arc_radius_and_center`, `angle_from_bulge`, `bulge_from_angle`), so
//! the polyline is the library's bit for bit: `kerf_simple_tests.rs`
//! compares them on random loops.

use cavalier_contours::core::math::{angle_from_bulge, bulge_from_angle, Vector2};
use cavalier_contours::core::traits::{FuzzyEq, FuzzyOrd};
use cavalier_contours::polyline::{
    seg_arc_radius_and_center, PlineSource, PlineSourceMut, PlineVertex, Polyline,
};

/// One raw offset segment: the library's `RawOffsetSeg`, less what the
/// joins written out here never read.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Raw {
    start: Vector2<f64>,
    end: Vector2<f64>,
    /// The arc's centre, None for a line.
    center: Option<Vector2<f64>>,
    /// The arc sweeps clockwise (its `sweep < 0`).
    clockwise: bool,
    /// The bulge of the whole segment (`span_bulge(0, 1)`).
    bulge: f64,
}

impl Raw {
    /// `RawOffsetSeg::start_tangent` / `end_tangent` at `p` (start or end).
    fn tangent(&self, p: Vector2<f64>) -> Vector2<f64> {
        match self.center {
            None => self.end - self.start,
            Some(c) => {
                let t = (p - c).perp();
                if self.clockwise {
                    -t
                } else {
                    t
                }
            }
        }
    }
}

/// Buffers kept from loop to loop, and the last arc bulge's span bulge.
#[derive(Default)]
pub(crate) struct RawOffset {
    segs: Vec<Raw>,
    /// The last arc's bulge (bits), its sweep and its span bulge.
    memo: Option<(u64, f64, f64)>,
}

/// A join the library would classify as coincident or outer round.
#[derive(Clone, Copy)]
struct Join {
    current_end: Vector2<f64>,
    next_start: Vector2<f64>,
    bulge: f64,
}

impl RawOffset {
    /// An arc's sweep (`angle_from_bulge(b)`) and its whole span's bulge
    /// (`span_bulge(0, 1)`: `bulge_from_angle(sweep · (1 − 0))`),
    /// remembered for the last `b`.
    fn sweep_and_bulge(&mut self, b: f64) -> (f64, f64) {
        match self.memo {
            Some((bits, sweep, out)) if bits == b.to_bits() => (sweep, out),
            _ => {
                let sweep = angle_from_bulge(b);
                let out = bulge_from_angle(sweep * (1.0 - 0.0));
                self.memo = Some((b.to_bits(), sweep, out));
                (sweep, out)
            }
        }
    }

    /// `create_untrimmed_raw_offset_segs` into the buffer; false when an
    /// arc collapses (the library keeps it as a scaffold: its way).
    fn segments(&mut self, pl: &Polyline<f64>, offset: f64) -> bool {
        let n = pl.vertex_count();
        self.segs.clear();
        for i in 0..n {
            let (v1, v2) = (pl.at(i), pl.at((i + 1) % n));
            let seg = if v1.bulge_is_zero() {
                let line = v2.pos() - v1.pos();
                let offset_vector = line.unit_perp().scale(offset);
                Raw {
                    start: v1.pos() + offset_vector,
                    end: v2.pos() + offset_vector,
                    center: None,
                    clockwise: false,
                    bulge: 0.0,
                }
            } else {
                let (arc_radius, arc_center) = seg_arc_radius_and_center(v1, v2);
                let is_clockwise = v1.bulge_is_neg();
                let offset_direction = if is_clockwise { offset } else { -offset };
                let radius_after_offset = arc_radius + offset_direction;
                let radial_scale = radius_after_offset / arc_radius;
                let start_radial = v1.pos() - arc_center;
                let end_radial = v2.pos() - arc_center;
                if radius_after_offset.fuzzy_lt(0.0) {
                    return false;
                }
                let (sweep, bulge) = self.sweep_and_bulge(v1.bulge);
                Raw {
                    start: arc_center + start_radial.scale(radial_scale),
                    end: arc_center + end_radial.scale(radial_scale),
                    center: Some(arc_center),
                    clockwise: sweep < 0.0,
                    bulge,
                }
            };
            self.segs.push(seg);
        }
        true
    }

    /// `RawOffsetBuilder::analyze_join` when it ends in a coincident or an
    /// outer round join; None otherwise.
    fn join(
        &self,
        i: usize,
        j: usize,
        shared: Vector2<f64>,
        offset: f64,
        eps: f64,
    ) -> Option<Join> {
        let (current, next) = (&self.segs[i], &self.segs[j]);
        if current.end.fuzzy_eq_eps(next.start, eps) {
            return Some(Join {
                current_end: current.end,
                next_start: current.end,
                bulge: 0.0,
            });
        }
        let incoming = current.tangent(current.end);
        let outgoing = next.tangent(next.start);
        let incoming_len_sq = incoming.length_squared();
        let outgoing_len_sq = outgoing.length_squared();
        let position_eps_sq = eps * eps;
        if incoming_len_sq <= position_eps_sq || outgoing_len_sq <= position_eps_sq {
            return None;
        }
        let turn = incoming.perp_dot(outgoing);
        let angle_eps = f64::fuzzy_epsilon();
        if turn * turn <= angle_eps * angle_eps * incoming_len_sq * outgoing_len_sq
            || offset * turn > 0.0
        {
            // A reversal, a same-way gap, or an inner join.
            return None;
        }
        // `arc_connection_boundary`.
        let current_direction = (current.end - shared).normalize();
        let next_direction = (next.start - shared).normalize();
        // The library's two comparisons: a NaN stays NaN, as with clamp.
        let cos_sweep = current_direction.dot(next_direction).clamp(-1.0, 1.0);
        let mut sin_sweep = current_direction.perp_dot(next_direction).abs();
        if sin_sweep > 1.0 {
            sin_sweep = 1.0;
        }
        let magnitude = if cos_sweep >= 0.0 {
            sin_sweep / (1.0 + cos_sweep + (2.0 * (1.0 + cos_sweep)).sqrt())
        } else {
            (1.0 - cos_sweep) / (sin_sweep + (2.0 * (1.0 - cos_sweep)).sqrt())
        };
        Some(Join {
            current_end: current.end,
            next_start: next.start,
            bulge: if offset >= 0.0 { -magnitude } else { magnitude },
        })
    }

    /// `create_raw_offset(pl, offset, eps).polyline` of a closed loop of at
    /// least two vertices and a non-zero offset, written into `out`, when
    /// every join is coincident or an outer round (no segment is then
    /// locally invalid); false (and `out` unspecified) otherwise.
    pub(crate) fn closed_into(
        &mut self,
        pl: &Polyline<f64>,
        offset: f64,
        eps: f64,
        out: &mut Polyline<f64>,
    ) -> bool {
        debug_assert!(pl.is_closed() && pl.vertex_count() >= 2 && offset != 0.0);
        if !self.segments(pl, offset) {
            return false;
        }
        let last = self.segs.len() - 1;
        out.clear();
        out.set_is_closed(false);
        let Some(closing) = self.join(last, 0, pl.at(0).pos(), offset, eps) else {
            return false;
        };
        out.add_vertex(PlineVertex::from_vector2(closing.next_start, 0.0));
        for i in 0..last {
            let Some(b) = self.join(i, i + 1, pl.at(i + 1).pos(), offset, eps) else {
                return false;
            };
            emit(out, b.current_end, self.segs[i].bulge, eps);
            emit(out, b.next_start, b.bulge, eps);
        }
        let closing_bulge = if closing.current_end.fuzzy_eq_eps(closing.next_start, eps) {
            self.segs[last].bulge
        } else {
            emit(out, closing.current_end, self.segs[last].bulge, eps);
            closing.bulge
        };
        // `close_segment`, then `finish(true)`.
        let first = out.at(0).pos();
        if let Some(v) = out.last() {
            if !v.pos().fuzzy_eq_eps(first, eps) {
                out.set_last(v.with_bulge(closing_bulge));
            }
        }
        if out.vertex_count() > 1 {
            let first = out.at(0).pos();
            if out.last().is_some_and(|v| v.pos().fuzzy_eq_eps(first, eps)) {
                out.remove_last();
            }
            out.set_is_closed(true);
        }
        if out.vertex_count() == 1 {
            out.clear();
        }
        true
    }
}

/// `RawOffsetBuilder::emit_segment` (never locally invalid here).
fn emit(out: &mut Polyline<f64>, end: Vector2<f64>, bulge: f64, eps: f64) {
    let Some(last) = out.last() else {
        return;
    };
    if last.pos().fuzzy_eq_eps(end, eps) {
        return;
    }
    out.set_last(last.with_bulge(bulge));
    out.add_vertex(PlineVertex::from_vector2(end, 0.0));
}
