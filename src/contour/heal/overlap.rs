//! Segments drawn twice or overlapping (paper 001 §11): kept once, or
//! merged into one line or arc over their union. Run by [`super::heal_open`]
//! on what did not close in the first chaining.

use std::f64::consts::TAU;

use super::{snap, HealKind, Healing, Piece, Pieces, Seg};

use crate::fx::FxMap;
use crate::geom::{arc_pieces, Segment};

/// A segment's identity whichever way it runs, snapped to the tolerance.
pub(super) fn segment_key(s: &Segment, t: f64) -> Key {
    let (a, b) = (
        (snap(s.a.x, t), snap(s.a.y, t)),
        (snap(s.b.x, t), snap(s.b.y, t)),
    );
    let (lo, hi, bulge) = if a <= b {
        (a, b, s.bulge)
    } else {
        (b, a, -s.bulge)
    };
    (lo.0, lo.1, hi.0, hi.1, (bulge * 1e9).round() as i64)
}

/// A segment's key, as [`segment_key`] gives it.
type Key = (i64, i64, i64, i64, i64);

/// Keeps one of each segment drawn twice (either direction); `earlier`
/// holds the keys of segments already kept elsewhere.
///
/// A segment is a copy when an earlier one (in `earlier`, then in `segs`)
/// has its key. Found by sorting the keys' hashes (a linear radix sort)
/// and comparing keys within runs of equal hashes, rather than through a
/// hash map: at a million segments the map outgrew the caches and every
/// insert waited on memory (issue 17, chaining at scale).
pub(super) fn drop_duplicate_segments(
    segs: Vec<Seg>,
    t: f64,
    earlier: Vec<Key>,
    healing: &mut Healing,
) -> Vec<Seg> {
    let first_seg = earlier.len();
    let copy = super::copies(first_seg + segs.len(), |k| {
        if k < first_seg {
            earlier[k]
        } else {
            segment_key(&segs[k - first_seg].s, t)
        }
    });
    // In place: a million segments copied was a fresh 50 MB to page in.
    let mut segs = segs;
    let mut k = first_seg;
    segs.retain(|g| {
        let keep = !copy[k];
        k += 1;
        if !keep {
            healing.add(HealKind::Duplicate, g.s.point_at(0.5));
        }
        keep
    });
    segs
}

/// Merges collinear lines that overlap (share more than the tolerance); the
/// merged lines become pieces of their own.
pub(super) fn merge_overlapping_lines(
    segs: Vec<Seg>,
    t: f64,
    healing: &mut Healing,
    merged: &mut Pieces,
) -> Vec<Seg> {
    let mut segs = segs;
    // The lines, by their place in `segs` (not copied out: a million lines
    // were a fresh 50 MB to page in).
    let lines: Vec<usize> = (0..segs.len()).filter(|&k| segs[k].s.is_line()).collect();
    // A line's direction mod π.
    let dir = |s: &Segment| {
        let d = s.b.sub(s.a).unit();
        if d.y < 0.0 || (d.y == 0.0 && d.x < 0.0) {
            d.scale(-1.0)
        } else {
            d
        }
    };
    // Each line as (direction mod π, offset from the origin, interval along the direction).
    #[derive(Clone, Copy)]
    struct L {
        angle: f64,
        offset: f64,
        t0: f64,
        t1: f64,
        line: usize,
    }
    let mut ls: Vec<L> = lines
        .iter()
        .enumerate()
        .map(|(k, &at)| {
            let s = segs[at].s;
            let d = dir(&s);
            let (ta, tb) = (s.a.dot(d), s.b.dot(d));
            L {
                angle: d.y.atan2(d.x),
                offset: d.cross(s.a),
                t0: ta.min(tb),
                t1: ta.max(tb),
                line: k,
            }
        })
        .collect();
    crate::sort::sort_by_number_then(
        &mut ls,
        |x| x.angle,
        |x, y| x.offset.total_cmp(&y.offset).then(x.t0.total_cmp(&y.t0)),
    );
    let mut used = vec![false; lines.len()];
    let mut i = 0;
    while i < ls.len() {
        // A run of lines on (nearly) the same infinite line.
        let mut j = i + 1;
        while j < ls.len() {
            let len = (ls[j].t1 - ls[j].t0).max(ls[i].t1 - ls[i].t0).max(1.0);
            let same_dir = (ls[j].angle - ls[i].angle).abs() * len <= t;
            if !same_dir || (ls[j].offset - ls[i].offset).abs() > t {
                break;
            }
            j += 1;
        }
        if j - i > 1 {
            let mut run: Vec<usize> = (i..j).collect();
            crate::sort::sort_by(&mut run, |&x, &y| ls[x].t0.total_cmp(&ls[y].t0));
            let mut k = 0;
            while k < run.len() {
                let line = &segs[lines[ls[run[k]].line]].s;
                let (dir, offset) = (dir(line), ls[run[k]].offset);
                let (lo, mut hi) = (ls[run[k]].t0, ls[run[k]].t1);
                let mut members = vec![run[k]];
                let mut m = k + 1;
                while m < run.len() && ls[run[m]].t0 < hi - t {
                    hi = hi.max(ls[run[m]].t1);
                    members.push(run[m]);
                    m += 1;
                }
                if members.len() > 1 {
                    // The point at parameter t is t·dir + offset·perp(dir), since cross(dir, p) = offset.
                    let base = dir.perp().scale(offset);
                    for &mi in &members[1..] {
                        healing.add(HealKind::Overlap, segs[lines[ls[mi].line]].s.point_at(0.5));
                    }
                    for &mi in &members {
                        used[ls[mi].line] = true;
                    }
                    let mut entities: Vec<usize> = members
                        .iter()
                        .map(|&mi| segs[lines[ls[mi].line]].entity as usize)
                        .collect();
                    entities.dedup();
                    merged.push(Piece {
                        segments: vec![Segment::line(
                            base.add(dir.scale(lo)),
                            base.add(dir.scale(hi)),
                        )],
                        closed: false,
                        entities,
                        measure: None,
                    });
                }
                k = m;
            }
        }
        i = j;
    }
    // The lines merged taken out, in place (what is left is in input order;
    // the caller reads it back by place).
    let mut gone = vec![false; segs.len()];
    for (k, &at) in lines.iter().enumerate() {
        gone[at] = used[k];
    }
    let mut k = 0;
    segs.retain(|_| {
        k += 1;
        !gone[k - 1]
    });
    segs
}

/// Merges arcs on the same circle whose angular ranges overlap; the merged
/// arcs become pieces of their own.
pub(super) fn merge_overlapping_arcs(
    segs: Vec<Seg>,
    t: f64,
    healing: &mut Healing,
    merged: &mut Pieces,
) -> Vec<Seg> {
    // The lines stay in place; the arcs go to their circles and what is
    // not merged comes back after them (the caller reads it back by place).
    let mut out = segs;
    // Circle (centre, radius snapped) → its arcs as (start angle, sweep, segment).
    type Arcs = Vec<(f64, f64, Seg)>;
    let mut groups: FxMap<(i64, i64, i64), Arcs> = FxMap::default();
    out.retain(|&g| match g.s.arc_center() {
        Some((c, r)) => {
            // As a counter-clockwise range [start, start + sweep).
            let ccw = if g.s.is_ccw() { g.s } else { g.s.reversed() };
            let v = ccw.a.sub(c);
            let start = v.y.atan2(v.x).rem_euclid(TAU);
            groups
                .entry((snap(c.x, t), snap(c.y, t), snap(r, t)))
                .or_default()
                .push((start, ccw.sweep(), g));
            false
        }
        None => true,
    });
    let mut keys: Vec<_> = groups.keys().copied().collect();
    crate::sort::sort_by(&mut keys, |a, b| a.cmp(b));
    for key in keys {
        let Some(mut arcs) = groups.remove(&key) else {
            continue;
        };
        if arcs.len() == 1 {
            out.extend(arcs.into_iter().map(|a| a.2));
            continue;
        }
        crate::sort::sort_by(&mut arcs, |x, y| x.0.total_cmp(&y.0));
        let Some((c, r)) = arcs[0].2.s.arc_center() else {
            continue;
        };
        let eps = t / r.max(t);
        let mut k = 0;
        while k < arcs.len() {
            let (lo, mut hi) = (arcs[k].0, arcs[k].0 + arcs[k].1);
            let mut m = k + 1;
            while m < arcs.len() && arcs[m].0 < hi - eps {
                hi = hi.max(arcs[m].0 + arcs[m].1);
                healing.add(HealKind::Overlap, arcs[m].2.s.point_at(0.5));
                m += 1;
            }
            if m == k + 1 {
                out.push(arcs[k].2);
            } else {
                let sweep = (hi - lo).min(TAU);
                let closed = sweep >= TAU - eps;
                let mut entities: Vec<usize> =
                    arcs[k..m].iter().map(|a| a.2.entity as usize).collect();
                entities.dedup();
                merged.push(Piece {
                    segments: arc_pieces(c, r, lo, sweep),
                    closed,
                    entities,
                    measure: None,
                });
            }
            k = m;
        }
    }
    out
}
