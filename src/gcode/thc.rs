//! The torch-height lock within a cut ([`crate::process::ThcLock`]):
//! where along the cut the post's `thc_lock` and `thc_unlock` templates go.
//!
//! At the pierce the cut's feed steps are read once: every joint between
//! two contour steps (or links, repeats) whose included angle is below the
//! rule's, and every arc tighter than the lock distance that turns as
//! sharply (the kerf path's round of a convex corner), gets a locked window from `corner_distance` before it to
//! `corner_distance` after it (windows that touch are merged); the last
//! `end_distance` of the contour is locked to the end (released after the
//! torch is off, as in small holes). The steps are then written in pieces
//! split where a window opens or closes.

use super::Writer;
use crate::geom::Segment;
use crate::plan::{tabs::piece, Cut, Role};
use crate::process::ThcLock;

/// The lock's state while a cut is written.
#[derive(Clone, Debug, Default)]
pub(super) struct Height {
    /// Locked now (the post's `thc_lock` written, `thc_unlock` not yet).
    pub(super) locked: bool,
    /// Where the lock changes, mm from the cut's pierce: (at, lock).
    events: Vec<(f64, bool)>,
    next: usize,
    /// How far the cut has gone, mm.
    at: f64,
}

/// Steps whose joints may be corners to slow down for.
fn is_cutting(r: Role) -> bool {
    matches!(r, Role::Contour | Role::Link | Role::Repeat)
}

/// Writes a change of the lock (nothing when it is already so, or when
/// the post has no lock codes).
pub(super) fn set(w: &mut Writer, h: &mut Height, lock: bool) {
    if lock && !h.locked {
        w.templates(&w.post.thc_lock);
        h.locked = !w.post.thc_lock.is_empty();
    } else if !lock && h.locked {
        w.templates(&w.post.thc_unlock);
        h.locked = false;
    }
}

impl Height {
    /// Plans the locks of `cut` under `rule` (none for a mark or a small
    /// hole, locked throughout by its own rule).
    pub(super) fn start(&mut self, cut: &Cut, rule: &ThcLock) {
        self.events.clear();
        self.next = 0;
        self.at = 0.0;
        if !rule.on() || cut.small_hole || cut.is_mark() {
            return;
        }
        let mut windows: Vec<(f64, f64)> = Vec::new();
        let mut at = 0.0;
        let mut end_of_contour = None;
        let steps = &cut.steps;
        let sharp = |turn_deg: f64| 180.0 - turn_deg < rule.corner_angle_deg;
        for (i, s) in steps.iter().enumerate() {
            let len = s.segment.length();
            // A kerf path rounds a convex corner with an arc of half the
            // kerf: an arc tighter than the lock distance is a corner,
            // turning by its sweep.
            let tight = s
                .segment
                .arc_center()
                .is_some_and(|(_, r)| r < rule.corner_distance);
            if tight && is_cutting(s.role) && sharp(s.segment.sweep().abs().to_degrees()) {
                windows.push((at - rule.corner_distance, at + len + rule.corner_distance));
            }
            at += len;
            if s.role == Role::Contour {
                end_of_contour = Some(at);
            }
            let Some(next) = steps.get(i + 1) else { break };
            if rule.corner_distance > 0.0 && is_cutting(s.role) && is_cutting(next.role) {
                let (a, b) = (s.segment.tangent_at(1.0), next.segment.tangent_at(0.0));
                // Included angle: 180° straight on, 90° a square corner.
                let turn = (a.x * b.x + a.y * b.y).clamp(-1.0, 1.0).acos().to_degrees();
                if sharp(turn) {
                    windows.push((at - rule.corner_distance, at + rule.corner_distance));
                }
            }
        }
        if let (Some(end), true) = (end_of_contour, rule.end_distance > 0.0) {
            windows.push((end - rule.end_distance, f64::INFINITY));
        }
        crate::sort::sort_by(&mut windows, |x, y| x.0.total_cmp(&y.0));
        let mut merged: Vec<(f64, f64)> = Vec::new();
        for w in windows {
            match merged.last_mut() {
                Some(last) if w.0 <= last.1 => last.1 = last.1.max(w.1),
                _ => merged.push((w.0.max(0.0), w.1)),
            }
        }
        for (a, b) in merged {
            self.events.push((a, true));
            if b.is_finite() {
                self.events.push((b, false));
            }
        }
    }

    /// `s` (mm) in pieces split where the lock changes, each with the
    /// change after it (Some(true): lock, Some(false): release).
    pub(super) fn pieces(&mut self, s: &Segment) -> Vec<(Segment, Option<bool>)> {
        let len = s.length();
        let (from, to) = (self.at, self.at + len);
        self.at = to;
        let mut out = Vec::new();
        let mut t0 = 0.0;
        while let Some(&(x, lock)) = self.events.get(self.next) {
            if x >= to {
                break;
            }
            self.next += 1;
            let t = if len > 0.0 {
                ((x - from) / len).clamp(0.0, 1.0)
            } else {
                0.0
            };
            if t > t0 {
                out.push((piece(s, t0, t), Some(lock)));
                t0 = t;
            } else if let Some(last) = out.last_mut() {
                // Two changes at one place: the last one holds.
                last.1 = Some(lock);
            } else {
                // At the step's start: the change comes before the move.
                out.push((piece(s, 0.0, 0.0), Some(lock)));
            }
        }
        out.push((piece(s, t0, 1.0), None));
        out
    }

    /// True when the rest of a cut written from `self` and from `o` locks
    /// and releases at the same places: the same changes left, and the
    /// same distance gone when one is left (without, it is never read
    /// before the next cut's [`Height::start`] sets it again).
    pub(super) fn same_course(&self, o: &Height) -> bool {
        let (a, b) = (
            &self.events[self.next.min(self.events.len())..],
            &o.events[o.next.min(o.events.len())..],
        );
        self.locked == o.locked && a == b && (a.is_empty() || self.at == o.at)
    }

    /// No change of the lock is left in this cut (always so without a
    /// lock rule): a step is written whole, and how far the cut has gone
    /// no longer matters (`at` is only read against the changes).
    pub(super) fn idle(&self) -> bool {
        self.next >= self.events.len()
    }

    /// Moves on over `len` mm without writing (a tab crossed).
    pub(super) fn skip(&mut self, len: f64) {
        self.at += len;
    }

    /// The changes passed over since the last call, as the state they
    /// leave (after a tab: whether the lock should now be on).
    pub(super) fn due(&mut self) -> Option<bool> {
        let mut last = None;
        while let Some(&(x, lock)) = self.events.get(self.next) {
            if x > self.at {
                break;
            }
            self.next += 1;
            last = Some(lock);
        }
        last
    }
}
