//! Motion blocks on the post's decimal grid: lines, arcs (each centre a
//! grid point, cut into pieces of at most the post's sweep, or written as
//! lines) and a knife's heading, with the machine state they move
//! (see [`super::emit`] for the rules the numbers keep).

use crate::geom::{flatten_count, Point, Segment};

use super::number::Grid;
use super::post::{ArcMode, Post};
use super::Writer;

/// The machine state the emitter tracks.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct State {
    pos: (i64, i64),
    motion: Option<String>,
    x: Option<i64>,
    y: Option<i64>,
    /// Knife heading, grid units of a degree, unwrapped.
    heading: Option<i64>,
}

pub(super) fn scaled(s: &Segment, k: f64) -> Segment {
    Segment {
        a: s.a.scale(k),
        b: s.b.scale(k),
        bulge: s.bulge,
    }
}

impl State {
    /// The machine at grid point `pos`, no motion mode or axis written yet.
    pub(super) fn at(pos: (i64, i64)) -> State {
        State {
            pos,
            motion: None,
            x: None,
            y: None,
            heading: None,
        }
    }
}
/// One motion block to the grid point `q`, with the extra words (I, J, R,
/// a knife's axis), each a letter and a grid number.
pub(super) fn motion(
    w: &mut Writer,
    grid: &Grid,
    st: &mut State,
    word: &str,
    q: (i64, i64),
    extra: &[(&str, i64)],
) {
    let post = w.post;
    if w.take_templated() {
        st.motion = None;
    }
    let new_motion = !post.modal || !st.motion.as_deref().is_some_and(|m| same(m, word));
    let (new_x, new_y) = (
        !post.modal || st.x != Some(q.0),
        !post.modal || st.y != Some(q.1),
    );
    // G91: the rounded target less the rounded position (both on the
    // grid, exact integers), so no rounding accumulates over the moves.
    let rel = post.incremental;
    let (x, y) = if rel {
        (q.0 - st.pos.0, q.1 - st.pos.1)
    } else {
        q
    };
    let to_g91 = rel && !w.g91;
    if !new_x && !new_y && extra.is_empty() {
        return;
    }
    let feed = if !same(word, &post.rapid) || same(&post.rapid, &post.line) {
        w.feed_word()
    } else {
        None
    };
    w.block_of(|b| {
        if to_g91 {
            b.text("G91");
        }
        if new_motion {
            b.text(word);
        }
        if new_x {
            b.num("X", grid, x);
        }
        if new_y {
            b.num("Y", grid, y);
        }
        for &(letter, v) in extra {
            b.num(letter, grid, v);
        }
        if let Some(f) = &feed {
            b.text(f);
        }
    });
    if !st.motion.as_deref().is_some_and(|m| same(m, word)) {
        // Reuses the string: G1 and G2/G3 alternate on every rounded corner.
        let m = st.motion.get_or_insert_with(String::new);
        m.clear();
        m.push_str(word);
    }
    w.g91 |= rel;
    st.x = Some(q.0);
    st.y = Some(q.1);
    st.pos = q;
}

/// `a == b` for a motion word (`G0`, `G1`, …): compared a byte at a time
/// in line, where `==` calls `memcmp` (twice a block, for two bytes).
#[inline]
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len() && a.bytes().zip(b.bytes()).all(|(x, y)| x == y)
}

/// Blocks for one feed segment (in program units).
pub(super) fn feed(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, s: &Segment) {
    let end = grid.snap(s.b);
    if end == st.pos {
        // Shorter than the grid: nothing the machine can do.
        return;
    }
    let Some((c, r)) = s.arc_center() else {
        return line_to(w, post, grid, st, end);
    };
    // No trigonometry for most arcs (a quarter of the writer's time was
    // atan, cos and tan): the sagitta is r·2b²/(1 + b²) (1 − cos 2·atan b),
    // and the exact formula below decides only when that lands within
    // rounding of half a grid step, so the same arcs become lines as before.
    let b = s.bulge.abs();
    let near = r * 2.0 * b * b / (1.0 + b * b);
    let half = grid.step() / 2.0;
    let flat = if (near - half).abs() > 1e-9 * half {
        near < half
    } else {
        r * (1.0 - (s.sweep().abs() / 2.0).cos()) <= half
    };
    if flat {
        return line_to(w, post, grid, st, end);
    }
    if post.arcs == ArcMode::Lines || post.knife.is_some() {
        let chord = (post.chord * post.unit_scale()).max(grid.step() / 2.0);
        return linearise(w, post, grid, st, s, r, chord);
    }
    let max = post.max_arc_sweep_deg.to_radians();
    // |sweep| = 4·atan|b| ≤ max: one piece (the count below has 1e-9 of
    // the sweep to spare, so a bulge a rounding above the limit still gives
    // one). The posts' 180° needs no tan: tan 45° = 1.
    let limit = if post.max_arc_sweep_deg == 180.0 {
        1.0
    } else {
        (max / 4.0).tan()
    };
    if b <= limit * (1.0 + 1e-12) {
        // Most arcs: written whole, from the centre already at hand.
        return arc_to(w, post, grid, st, end, c, s.is_ccw(), s, r);
    }
    let sweep = s.sweep();
    let n = ((sweep.abs() / max) - 1e-9).ceil().clamp(1.0, 64.0) as usize;
    let bulge = (sweep / n as f64 / 4.0).tan();
    for i in 0..n {
        let piece = Segment {
            a: s.point_at(i as f64 / n as f64),
            b: if i + 1 == n {
                s.b
            } else {
                s.point_at((i + 1) as f64 / n as f64)
            },
            bulge,
        };
        arc(w, post, grid, st, &piece);
    }
}

fn arc(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, s: &Segment) {
    let end = grid.snap(s.b);
    let Some((c, r)) = s.arc_center() else {
        return line_to(w, post, grid, st, end);
    };
    arc_to(w, post, grid, st, end, c, s.is_ccw(), s, r)
}

/// One arc block to the grid point `end` about the centre `c` (of `s`,
/// radius `r`, for the lines it falls back to).
#[allow(clippy::too_many_arguments)] // the arc's geometry, computed once by the caller
fn arc_to(
    w: &mut Writer,
    post: &Post,
    grid: &Grid,
    st: &mut State,
    end: (i64, i64),
    c: Point,
    ccw: bool,
    s: &Segment,
    r: f64,
) {
    if end == st.pos {
        return;
    }
    let Some((i, j)) = grid.arc_center(st.pos, end, c) else {
        // No grid centre fits both ends: lines within half a grid step.
        return linearise(w, post, grid, st, s, r, grid.step() / 2.0);
    };
    let ij;
    let r_word;
    let extra: &[(&str, i64)] = match post.arcs {
        ArcMode::IjIncremental | ArcMode::Lines => {
            ij = [("I", i), ("J", j)];
            &ij
        }
        ArcMode::IjAbsolute => {
            ij = [("I", st.pos.0 + i), ("J", st.pos.1 + j)];
            &ij
        }
        ArcMode::R => {
            // At least half the chord, rounded up: the control must reach the end.
            let half = (((end.0 - st.pos.0) as f64).hypot((end.1 - st.pos.1) as f64) / 2.0).ceil();
            let rr = ((i as f64).hypot(j as f64).round()).max(half) as i64;
            r_word = [("R", rr)];
            &r_word
        }
    };
    let word = if ccw { &post.ccw } else { &post.cw };
    motion(w, grid, st, word, end, extra);
}

fn line_to(w: &mut Writer, post: &Post, grid: &Grid, st: &mut State, q: (i64, i64)) {
    let mut axis: Option<(&str, i64)> = None;
    if post.knife.is_some() {
        let d = ((q.0 - st.pos.0) as f64, (q.1 - st.pos.1) as f64);
        if d != (0.0, 0.0) {
            let before = st.heading;
            let h = turn_to(grid, st, d.1.atan2(d.0).to_degrees());
            let lift = post.knife.as_ref().map_or(180.0, |k| k.lift_angle_deg);
            let turn = before.map_or(0.0, |b| (h - b).abs() as f64 / grid.scale());
            if turn > lift {
                // Too sharp to drag the knife round: lift, turn, plunge (paper 003).
                w.templates(&post.torch_off);
                knife_word(w, post, grid, &post.rapid, h);
                w.templates(&post.torch_on);
                if w.pass_depth {
                    // Back down to this pass's depth, not the first cut's.
                    w.templates(&post.pass_z);
                }
            } else if before != Some(h) {
                if let Some(k) = &post.knife {
                    axis = Some((k.axis.as_str(), h));
                }
            }
        }
    }
    motion(w, grid, st, &post.line, q, axis.as_slice());
}

/// The unwrapped heading (grid units) nearest the last one for `deg`.
pub(super) fn turn_to(grid: &Grid, st: &mut State, deg: f64) -> i64 {
    let full = (360.0 * grid.scale()).round() as i64;
    let want = (deg * grid.scale()).round() as i64;
    let h = match st.heading {
        None => want,
        Some(prev) => {
            let d = (want - prev).rem_euclid(full);
            let d = if d > full / 2 { d - full } else { d };
            prev + d
        }
    };
    st.heading = Some(h);
    h
}

pub(super) fn knife_word(w: &mut Writer, post: &Post, grid: &Grid, word: &str, h: i64) {
    if let Some(k) = &post.knife {
        w.block(&[word.to_string(), format!("{}{}", k.axis, grid.fmt(h))]);
    }
}

fn linearise(
    w: &mut Writer,
    post: &Post,
    grid: &Grid,
    st: &mut State,
    s: &Segment,
    r: f64,
    chord: f64,
) {
    let n = flatten_count(r, s.sweep().abs(), chord);
    for i in 1..=n {
        let p: Point = if i == n {
            s.b
        } else {
            s.point_at(i as f64 / n as f64)
        };
        let q = grid.snap(p);
        if q != st.pos {
            line_to(w, post, grid, st, q);
        }
    }
}
