//! The raw offset of the loops a sheet is full of, from their geometry:
//! a rectangle or a convex part offset outwards, a round hole or a round
//! part either way.
//!
//! The raw offset of a closed loop moves every segment by `d` to its left
//! (a line along its normal; an arc about its own centre, its radius
//! shrunk by `d` when it turns left, grown when it turns right; its sweep,
//! so its bulge, unchanged) and joins the moved segments. Where two
//! segments meet smoothly (a circle's two halves, a line running into a
//! tangent arc) the moved ends meet too. Where the loop turns away from
//! the offset side (an outer corner) the moved ends are joined by an arc
//! of radius |d| about the corner, turning the way the loop turns. Any
//! other meeting — an inner corner, whose moved segments cross and must be
//! trimmed; a reversal; a segment too short to have a direction — and any
//! arc whose radius would reach zero give None: cavalier_contours builds
//! that raw offset (`create_raw_offset`).
//!
//! Why not always the library's: it builds a vector of raw segments with
//! an `atan2` per arc, a polyline and index lists per loop; a 137k-contour
//! sheet spends a quarter of its kerf there. Here nothing is allocated per
//! loop and no angle is taken: a corner arc's bulge `tan(θ/4)` comes from
//! the cosine and sine of its sweep by two half-angle steps.
//!
//! The result is the library's raw offset up to rounding (the same
//! vertices in the same order: each segment's moved start, then the
//! corner arc's start where a corner is rounded; `raw_tests.rs`
//! compares them on random loops within 1e-9 mm), and it goes through the
//! library's own self-intersection and distance checks afterwards.

use cavalier_contours::core::math::Vector2;
use cavalier_contours::polyline::{
    seg_arc_radius_and_center, PlineSource, PlineSourceMut, PlineVertex, Polyline,
};

/// One segment moved by the offset.
#[derive(Clone, Copy, Debug)]
struct Moved {
    start: Vector2<f64>,
    end: Vector2<f64>,
    /// The source segment's bulge (a moved arc sweeps the same angle).
    bulge: f64,
    /// Unit directions of travel at the source segment's start and end.
    dir_in: Vector2<f64>,
    dir_out: Vector2<f64>,
}

/// How two moved segments meet.
#[derive(Clone, Copy, Debug)]
enum Meet {
    /// At one point (the first segment's moved end).
    Smooth,
    /// By an arc about the corner with this bulge.
    Round(f64),
}

/// Buffers kept from loop to loop.
#[derive(Default)]
pub(crate) struct RawOffset {
    moved: Vec<Moved>,
    meets: Vec<Meet>,
    /// The last [`RawOffset::closed_into`]: the loop was lines only, the
    /// shortest this long (squared).
    lines_only: bool,
    shortest2: f64,
    /// The last raw offset written has no local self-intersection the
    /// library's search could report ([`RawOffset::no_local_crossing`]).
    tangent_joins: bool,
}

/// Unit vector along `v`; None when `v` is too short to have a direction.
fn unit(v: Vector2<f64>, eps: f64) -> Option<Vector2<f64>> {
    let len = v.length();
    (len > eps).then(|| v.scale(1.0 / len))
}

/// The left normal of a direction (a quarter turn counter-clockwise).
fn left(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// `tan(θ/4)` of the angle θ in [0, π) between two unit vectors, from its
/// cosine `c` and sine `s ≥ 0`: `tan(θ/2)` as `s/(1+c)` (or `(1−c)/s`
/// where `c < 0`, no cancellation either way), then halved again by
/// `tan(φ/2) = t / (1 + √(1+t²))`.
fn quarter_tan(c: f64, s: f64) -> f64 {
    let half = if c >= 0.0 {
        s / (1.0 + c)
    } else {
        (1.0 - c) / s
    };
    half / (1.0 + (1.0 + half * half).sqrt())
}

impl RawOffset {
    /// Every segment of `pl` moved by `d`; false where an arc's radius
    /// would reach zero or a segment has no direction.
    fn move_segments(&mut self, pl: &Polyline<f64>, d: f64, eps: f64) -> bool {
        let n = pl.vertex_count();
        self.moved.clear();
        (self.lines_only, self.shortest2) = (true, f64::INFINITY);
        for i in 0..n {
            let (v1, v2) = (pl.at(i), pl.at((i + 1) % n));
            let (a, b) = (v1.pos(), v2.pos());
            let moved = if v1.bulge_is_zero() {
                let Some(dir) = unit(b - a, eps) else {
                    return false;
                };
                self.shortest2 = self.shortest2.min((b - a).length_squared());
                let shift = left(dir).scale(d);
                Moved {
                    start: a + shift,
                    end: b + shift,
                    bulge: 0.0,
                    dir_in: dir,
                    dir_out: dir,
                }
            } else {
                self.lines_only = false;
                let (r, c) = seg_arc_radius_and_center(v1, v2);
                // Left of a counter-clockwise arc is its centre.
                let ccw = v1.bulge > 0.0;
                let r2 = if ccw { r - d } else { r + d };
                if r2 <= eps || r <= eps {
                    return false;
                }
                let k = r2 / r;
                // Travel on a counter-clockwise arc is a quarter turn left
                // of the radius.
                let turn = |p: Vector2<f64>| {
                    let t = left((p - c).scale(1.0 / r));
                    if ccw {
                        t
                    } else {
                        -t
                    }
                };
                Moved {
                    start: c + (a - c).scale(k),
                    end: c + (b - c).scale(k),
                    bulge: v1.bulge,
                    dir_in: turn(a),
                    dir_out: turn(b),
                }
            };
            self.moved.push(moved);
        }
        true
    }

    /// How moved segment `i` meets the next, `j`, at source vertex
    /// `corner`; None for an inner corner or a reversal.
    fn meet(&self, i: usize, j: usize, corner: Vector2<f64>, d: f64, eps: f64) -> Option<Meet> {
        let (m1, m2) = (&self.moved[i], &self.moved[j]);
        if m1.end.fuzzy_eq_eps(m2.start, eps) {
            return Some(Meet::Smooth);
        }
        // Sine of the loop's turn at the corner: > 0 turning left.
        let turn = m1.dir_out.perp_dot(m2.dir_in);
        // Nearly straight on (the moved ends should then have met) or
        // turning back: not a corner to round.
        if turn.abs() <= 1e-5 || d * turn > 0.0 {
            return None;
        }
        let u = unit(m1.end - corner, eps)?;
        let w = unit(m2.start - corner, eps)?;
        let c = u.dot(w).clamp(-1.0, 1.0);
        let s = u.perp_dot(w).abs().min(1.0);
        if s <= 1e-12 && c < 0.0 {
            return None;
        }
        let b = quarter_tan(c, s);
        Some(Meet::Round(if turn > 0.0 { b } else { -b }))
    }

    /// The raw offset of the closed loop `pl` by `d` (not 0), into `out`,
    /// when it has two vertices or more and every meeting is smooth or an
    /// outer corner; false (and `out` unspecified) otherwise.
    pub(crate) fn closed_into(
        &mut self,
        pl: &Polyline<f64>,
        d: f64,
        eps: f64,
        out: &mut Polyline<f64>,
    ) -> bool {
        debug_assert!(pl.is_closed() && d != 0.0);
        self.tangent_joins = false;
        let n = pl.vertex_count();
        if n < 2 || !self.move_segments(pl, d, eps) {
            return false;
        }
        self.meets.clear();
        for i in 0..n {
            let j = (i + 1) % n;
            match self.meet(i, j, pl.at(j).pos(), d, eps) {
                Some(m) => self.meets.push(m),
                None => return false,
            }
        }
        out.clear();
        for i in 0..n {
            let m = &self.moved[i];
            // A segment after a smooth meeting starts where the one before
            // ended.
            let start = match self.meets[(i + n - 1) % n] {
                Meet::Smooth => self.moved[(i + n - 1) % n].end,
                Meet::Round(_) => m.start,
            };
            if !push(out, start, m.bulge, eps) {
                return false;
            }
            if let Meet::Round(b) = self.meets[i] {
                if !push(out, m.end, b, eps) {
                    return false;
                }
            }
        }
        // At least one vertex a segment (n >= 2), and no two neighbours alike.
        let (first, last) = (out.at(0).pos(), out.at(out.vertex_count() - 1).pos());
        if first.fuzzy_eq_eps(last, eps) {
            return false;
        }
        out.set_is_closed(true);
        // Lines only, every meeting a rounded corner: lines and corner arcs
        // alternate (see `no_local_crossing`), no line shorter than
        // sqrt(8 (|d| eps + eps²)).
        self.tangent_joins = self.lines_only
            && self.meets.iter().all(|m| matches!(m, Meet::Round(_)))
            && self.shortest2 > 8.0 * (d.abs() * eps + eps * eps);
        true
    }

    /// True when the library's local self-intersection search
    /// (`visit_local_self_intersects`, each segment against the next) would
    /// report nothing on the raw offset the last [`RawOffset::closed_into`]
    /// wrote: a loop of lines offset outwards, each corner rounded.
    ///
    /// Why. Lines and corner arcs alternate, so every pair the search
    /// tests is a line and the arc at one of its ends (the shared vertex
    /// q), and the search reports only points not within `eps` of q. The
    /// arc is centred on the source corner c with radius r = |d| and starts
    /// (or ends) at the line's moved end, r from c along the line's normal:
    /// the line is tangent to the arc's circle at q, so it meets the circle
    /// nowhere else, and the library's line-circle solution, whatever its
    /// rounding, gives points on the line near q only (one tangent point,
    /// or two spread either side of q). Each case of `pline_seg_intr`'s
    /// line-arc branch then gives q or nothing:
    /// - a tangent point becomes a line end lying on the arc: q lies on
    ///   it (it is the arc's own end); the line's other end p is
    ///   √(L² + r²) from c, beyond r + eps when L² > 2 r eps + eps², which
    ///   the shortest-line bound holds with room for the centre's rounding
    ///   (the library finds c again from the arc's chord and bulge);
    /// - of two points, one beyond q's end of the line is kept only within
    ///   eps of it (the fuzzy range on the line); one on the line's side is
    ///   off the arc's sweep (past the arc's ray through q by its distance
    ///   to q, the sweep's fuzzy margin being eps) unless within eps of q; a point kept is swapped for the line end on the
    ///   arc, q, when there is one (the "sticky" ends), and any other is
    ///   within eps of q.
    ///
    /// Nothing is reported either way. Two neighbours alike (the search's
    /// "singularity") `push` already refuses. `raw_tests.rs` runs
    /// the library's search on every raw offset this accepts of random
    /// convex polygons, large and small, with corners nearly straight.
    pub(crate) fn no_local_crossing(&self) -> bool {
        self.tangent_joins
    }
}

/// Appends a vertex; false when it would repeat the one before (a segment
/// with no length: the library's way then).
fn push(out: &mut Polyline<f64>, p: Vector2<f64>, bulge: f64, eps: f64) -> bool {
    // Not `out.last()`: on an empty polyline it computes `0 - 1` (cavalier
    // 0.9), which wraps to "none" in a release build and panics in a debug
    // one (every closed offset's first vertex, in the wasm tests built for
    // debugging).
    let n = out.vertex_count();
    if n > 0 && out.at(n - 1).pos().fuzzy_eq_eps(p, eps) {
        return false;
    }
    out.add_vertex(PlineVertex::from_vector2(p, bulge));
    true
}
