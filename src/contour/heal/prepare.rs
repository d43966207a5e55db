//! The first healing step, before chaining ([`prepare`]): each entity's
//! pieces, zero-length ones dropped, closed entities drawn twice kept
//! once; ranges of entities on the threads (issue 17).

use super::{copies, loop_key, spans, HealKind, Healing};
use crate::contour::chain::{Measure, Pieces};
use crate::dxf::Entity;
use crate::geom::{Point, Segment, Tolerance};
use crate::par::Threads;

/// An entity's layer and whether it carries a stamp ([`Entity::source`]),
/// as [`prepare`] lists them: `layer | STAMPED`.
pub const STAMPED: u32 = 1 << 31;

/// First step, before chaining: zero-length entities and segments dropped,
/// closed entities drawn twice kept once; everything else is left whole, so
/// that parts sharing an edge (each drawn with its own copy of it) still close.
///
/// `marks` gets each entity's layer and stamp flag, read here while the
/// entity is in cache: the contours need them for their first entity, and
/// reading them there went back to the 27 MB of entities of a sheet, one
/// cache miss per contour (issue 17).
pub fn prepare(
    entities: &[Entity],
    tol: Tolerance,
    threads: Threads,
    healing: &mut Healing,
    marks: &mut Vec<u32>,
) -> Pieces {
    let t = tol.mm().max(1e-9);
    // Each entity becomes its pieces on its own: ranges of entities on the
    // threads, joined in entity order (what one thread gives).
    let mut parts = crate::par::map_ranges(entities.len(), threads, 4096, |r| {
        let mut part = Prepared::with_capacity(r.len());
        part.add(entities, r, t);
        part
    });
    let mut all = if parts.len() == 1 {
        parts.pop().unwrap_or_else(|| Prepared::with_capacity(0))
    } else {
        let mut all = Prepared::with_capacity(entities.len());
        for p in parts {
            all.marks.extend_from_slice(&p.marks);
            all.pieces.append(p.pieces);
            all.zero.extend_from_slice(&p.zero);
            all.keys.extend_from_slice(&p.keys);
            all.firsts.extend_from_slice(&p.firsts);
        }
        all
    };
    std::mem::swap(marks, &mut all.marks);
    let Prepared {
        mut pieces,
        zero,
        keys,
        firsts,
        ..
    } = all;
    // Closed entities drawn twice kept once (the first).
    let copy = copies(keys.len(), |k| keys[k]);
    pieces.drop_closed(&copy);
    let mut dups = firsts
        .iter()
        .zip(&copy)
        .filter(|(_, &c)| c)
        .map(|(f, _)| *f);
    let mut dup = dups.next();
    for (i, at) in zero {
        while let Some((_, p)) = dup.filter(|&(j, _)| j < i) {
            healing.add(HealKind::Duplicate, p);
            dup = dups.next();
        }
        healing.add(HealKind::ZeroLength, at);
    }
    for (_, p) in dup.into_iter().chain(dups) {
        healing.add(HealKind::Duplicate, p);
    }
    pieces
}

/// One range of entities prepared ([`prepare`]): its layer marks, pieces,
/// zero-length fixes, and its closed pieces' keys and first points.
struct Prepared {
    /// Each entity's layer, and STAMPED for a nested sheet's.
    marks: Vec<u32>,
    pieces: Pieces,
    /// Fixes in entity order, each with its entity: the copies among the
    /// closed entities are known only at the end, and each goes after its
    /// entity's zero-length pieces.
    zero: Vec<(usize, Point)>,
    /// Each closed piece kept so far: its key, entity and first point.
    keys: Vec<[i64; 6]>,
    firsts: Vec<(usize, Point)>,
}

impl Prepared {
    fn with_capacity(n: usize) -> Prepared {
        Prepared {
            marks: Vec::with_capacity(n),
            pieces: Pieces::with_capacity(n),
            zero: Vec::new(),
            keys: Vec::new(),
            firsts: Vec::new(),
        }
    }

    /// Adds the entities of `range`, in order.
    fn add(&mut self, entities: &[Entity], range: std::ops::Range<usize>, t: f64) {
        let mut lengths: Vec<f64> = Vec::new();
        for i in range {
            let e = &entities[i];
            // Layer indices stay far below 2^31 (one layer per entity at most).
            self.marks
                .push(e.layer | if e.source.is_some() { STAMPED } else { 0 });
            let first = e.segments.first().map_or(Point::default(), |s| s.a);
            // Each segment's length once (as `path_length` sums them, from
            // -0.0), unless a line spans `t` along an axis: its length is then
            // at least `t` (`hypot` is at least either side), and so is the
            // sum (lengths are never negative). Only the lines that do not are
            // measured below: no `hypot` per line of a sheet (issue 17).
            lengths.clear();
            if !e.segments.iter().any(|s| spans(s, t)) {
                lengths.extend(e.segments.iter().map(Segment::length));
                if lengths.iter().fold(-0.0, |sum, l| sum + l) < t {
                    self.zero.push((i, first));
                    continue;
                }
            }
            // An open entity's segments go straight to the pieces' flat store;
            // a closed one's into the vector its contour will keep.
            let mut own = Vec::new();
            let segs = if e.closed {
                own.reserve_exact(e.segments.len());
                &mut own
            } else {
                self.pieces.open_segments()
            };
            let from = segs.len();
            for (k, s) in e.segments.iter().enumerate() {
                let short = match lengths.get(k) {
                    Some(&length) => length < t,
                    None => !spans(s, t) && s.length() < t,
                };
                if short {
                    self.zero.push((i, s.a));
                } else {
                    segs.push(*s);
                }
            }
            let segs = &mut segs[from..];
            // Re-join where a tiny segment was dropped (around the loop for a closed entity).
            for k in 1..segs.len() {
                segs[k].a = segs[k - 1].b;
            }
            if !e.closed {
                self.pieces.close_open(&[i]);
                continue;
            }
            if let (Some(first), Some(last)) = (segs.first().map(|s| s.a), segs.last_mut()) {
                last.b = first;
            }
            let measure = Measure::of(&own);
            self.keys.push(loop_key(&measure, t));
            self.firsts.push((i, first));
            self.pieces.push_closed(own, vec![i], Some(measure));
        }
    }
}
