//! Butting a copy against its neighbours at the spacing (paper 001 §6.2's
//! MOVEPECA: "translate a part so adjacent edges end up at the desired
//! final distance"): the copy slides left as far as it can, then down,
//! again until it moves no more. Copies lying in its holes go with it.
//!
//! How far a polygon slides along `d` before it touches another: the
//! contacts of two polygons moving apart along a line happen where a
//! vertex of one meets an edge of the other, so the candidate distances
//! are the rays from each moving vertex along `d` to the fixed edges and
//! from each fixed vertex along `−d` to the moving edges (the translational
//! "sliding" of no-fit polygon constructions, e.g. Burke et al.,
//! Operations Research 2006, §3). Between two successive candidates the
//! copy is either free all the way or blocked all the way; the exact test
//! ([`super::collide`]) decides it at each stretch's middle, so the slide
//! stops where the grown polygons touch: the parts are then exactly the
//! spacing apart.

use super::collide::{overlaps, within, Shape};
use super::edit::{Checker, Placed};
use super::Placement;
use crate::geom::Point;

/// Most left-then-down rounds of one snap.
const ROUNDS: usize = 16;

/// Distances along `d` (a unit vector) at which a vertex of `moving` meets
/// an edge of `fixed` or a vertex of `fixed` meets an edge of `moving`.
fn contacts(moving: &Shape, fixed: &Shape, d: Point, out: &mut Vec<f64>) {
    let ray = |o: Point, dir: Point, a: Point, b: Point| -> Option<f64> {
        let e = b.sub(a);
        let den = dir.cross(e);
        if den.abs() < 1e-12 {
            return None;
        }
        let w = a.sub(o);
        let t = w.cross(e) / den;
        let s = w.cross(dir) / den;
        (t >= 0.0 && (-1e-9..=1.0 + 1e-9).contains(&s)).then_some(t)
    };
    let edges = |s: &Shape| {
        let p = s.poly.pts.clone();
        let n = p.len();
        (0..n)
            .map(move |i| (p[i], p[(i + 1) % n]))
            .collect::<Vec<_>>()
    };
    let (fe, me) = (edges(fixed), edges(moving));
    let back = d.scale(-1.0);
    for &v in &moving.poly.pts {
        out.extend(fe.iter().filter_map(|&(a, b)| ray(v, d, a, b)));
    }
    for &v in &fixed.poly.pts {
        out.extend(me.iter().filter_map(|&(a, b)| ray(v, back, a, b)));
    }
}

impl Checker {
    /// How far copy `i` (with the copies in its holes, `group`) slides along
    /// the unit vector `d` through free positions, mm.
    fn slide(&self, placements: &[Placement], group: &[usize], i: usize, d: Point) -> f64 {
        let Some(me) = self.placed(&placements[i]) else {
            return 0.0;
        };
        let host_i = self.check(placements).1[i];
        let host = host_i.and_then(|h| self.placed(&placements[h]));
        // Its hole's room when it lies in one (the walls it slides within,
        // in place of its host's outline).
        let hole = host.as_ref().and_then(|h| {
            h.rooms
                .iter()
                .find(|r| within(r, &me.grown, self.eps))
                .cloned()
        });
        let others: Vec<Placed> = placements
            .iter()
            .enumerate()
            .filter(|&(j, p)| {
                p.sheet == placements[i].sheet
                    && !group.contains(&j)
                    && (hole.is_none() || host_i != Some(j))
            })
            .filter_map(|(_, p)| self.placed(p))
            .collect();
        let sheet = placements[i].sheet;
        let room = self.room(sheet);
        let free = |t: f64| -> bool {
            let s = me.grown.moved(d.scale(t));
            (hole.is_some() || self.on_sheet(&s, sheet))
                && hole.as_ref().is_none_or(|r| within(r, &s, self.eps))
                && !others.iter().any(|o| overlaps(&o.grown, &s, self.eps))
        };
        let mut ts = Vec::new();
        for o in &others {
            contacts(&me.grown, &o.grown, d, &mut ts);
        }
        for o in room.obstacles.iter().chain(&room.bound).chain(&hole) {
            contacts(&me.grown, o, d, &mut ts);
        }
        // The box's walls.
        let (b, r) = (me.grown.bbox(), room.bounds);
        for (gap, dir) in [
            (b.min.x - r[0], -d.x),
            (r[2] - b.max.x, d.x),
            (b.min.y - r[1], -d.y),
            (r[3] - b.max.y, d.y),
        ] {
            if dir > 1e-12 && gap.is_finite() {
                ts.push(gap.max(0.0) / dir);
            }
        }
        ts.retain(|t| t.is_finite());
        ts.sort_by(f64::total_cmp);
        let mut at = 0.0;
        for t in ts {
            if t <= at + self.eps {
                continue;
            }
            if !free((at + t) / 2.0) {
                break;
            }
            at = t;
        }
        at
    }

    /// Copy `i` butted left, then down, until it moves no more (with the
    /// copies in its holes): the translation it moved by.
    pub fn snap(&self, placements: &mut [Placement], i: usize) -> Point {
        let mut total = Point::default();
        if i >= placements.len() {
            return total;
        }
        let group = guests(self, placements, i);
        for _ in 0..ROUNDS {
            let mut moved = 0.0;
            for d in [Point::new(-1.0, 0.0), Point::new(0.0, -1.0)] {
                let t = self.slide(placements, &group, i, d);
                if t > self.eps {
                    for &g in &group {
                        let p = &mut placements[g].translation;
                        *p = p.add(d.scale(t));
                    }
                    total = total.add(d.scale(t));
                    moved += t;
                }
            }
            if moved <= self.eps {
                break;
            }
        }
        total
    }
}

/// Copy `i` and every copy lying in its holes, and in theirs.
pub fn guests(c: &Checker, placements: &[Placement], i: usize) -> Vec<usize> {
    let (_, host) = c.check(placements);
    let mut group = vec![i];
    let mut k = 0;
    while k < group.len() {
        let h = group[k];
        let more: Vec<usize> = (0..placements.len())
            .filter(|&j| host[j] == Some(h) && !group.contains(&j))
            .collect();
        group.extend(more);
        k += 1;
    }
    group
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::edit::tests::{at, job};

    #[test]
    fn snap_butts_at_the_spacing_left_then_down() {
        let job = job();
        let c = Checker::new(&job);
        // A plate at the margin; the second one far off to the upper right
        // slides left onto it (stopping at 4 mm), then down to the margin.
        let mut ps = vec![at(0, 0, 10.0, 10.0), at(0, 1, 250.0, 30.0)];
        let moved = c.snap(&mut ps, 1);
        let t = ps[1].translation;
        assert!(
            (t.x - 114.0).abs() < 1e-6 && (t.y - 10.0).abs() < 1e-6,
            "{t:?}"
        );
        assert!((moved.x + 136.0).abs() < 1e-6 && (moved.y + 20.0).abs() < 1e-6);
        assert_eq!(c.check(&ps).0, vec![]);
        // Above the first one: down to 4 mm over it, then left to the margin.
        let mut ps = vec![at(0, 0, 10.0, 10.0), at(0, 1, 60.0, 120.0)];
        c.snap(&mut ps, 1);
        let t = ps[1].translation;
        assert!(
            (t.x - 10.0).abs() < 1e-6 && (t.y - 64.0).abs() < 1e-6,
            "{t:?}"
        );
        // Snapped again, it stays.
        assert_eq!(c.snap(&mut ps, 1), Point::default());
    }

    #[test]
    fn a_copy_in_a_hole_butts_on_the_hole_and_a_host_takes_its_guests_along() {
        let job = job();
        let c = Checker::new(&job);
        let mut ps = vec![at(0, 0, 60.0, 80.0), at(1, 0, 110.0, 100.0)];
        assert_eq!(c.check(&ps).1, vec![None, Some(0)]);
        c.snap(&mut ps, 1);
        // The hole is x 80..140, y 90..120: the tab stops 4 mm inside.
        let t = ps[1].translation;
        assert!(
            (t.x - 84.0).abs() < 1e-6 && (t.y - 94.0).abs() < 1e-6,
            "{t:?}"
        );
        // The plate butts on the sheet's margin; the tab comes along.
        c.snap(&mut ps, 0);
        assert_eq!(ps[0].translation, Point::new(10.0, 10.0));
        assert_eq!(ps[1].translation, Point::new(34.0, 24.0));
        assert_eq!(c.check(&ps), (vec![], vec![None, Some(0)]));
    }
}
