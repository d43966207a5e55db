//! A nest adjusted by hand (paper 001 §6.2: insert, rotate, move, mirror;
//! `../shared/seeds/notes-001-ebisui-1993.md`), checked again after every
//! change: which copies break the rules, and why.
//!
//! The rules are the nester's own, with the same models ([`super::shape`],
//! [`super::collide`]): every copy's polygon grown by half the spacing lies
//! inside the sheet less its margin (a remnant's outline shrunk by it, its
//! no-go zones grown by it) and overlaps no other copy's grown polygon,
//! unless it lies within the room of one of that copy's holes (shrunk by
//! half the spacing: part-in-part). A broken rule is then told apart on
//! the parts themselves (polygons grown by nothing): parts that overlap
//! from parts closer than the spacing, a copy off the sheet from one in its
//! margin or on a no-go zone.
//!
//! The figures of an edited nest are in [`super::figures`]; snapping a
//! copy to its neighbours is in [`super::snap`].

mod room;

use super::collide::{overlaps, within, Shape};
use super::shape::{collision_polygon, room_polygon, Polygon};
use super::{NestJob, Placement, Sheets};
pub(super) use room::Room;
use room::{inside_box, room};

/// Why a copy breaks the rules.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Why {
    /// Its part overlaps the part of copy `with` (an index into the placements).
    Overlap {
        /// The other copy.
        with: usize,
    },
    /// Closer to copy `with` than the spacing, not overlapping.
    Spacing {
        /// The other copy.
        with: usize,
    },
    /// Its part lies (partly) off the sheet.
    OffSheet,
    /// On the sheet, but inside the margin of its edge or of a no-go zone.
    Margin,
    /// On a no-go zone (a remnant's hole or defect).
    NoGo,
}

/// One broken rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conflict {
    /// The copy (index into the placements).
    pub copy: usize,
    /// Why.
    pub why: Why,
}

/// One part's models at the origin, as drawn: grown by half the spacing
/// and as it is (`None` when its outline encloses nothing), and the rooms
/// of its holes likewise.
struct Model {
    grown: Option<Polygon>,
    raw: Option<Polygon>,
    rooms: Vec<Polygon>,
    raw_rooms: Vec<Polygon>,
}

/// A copy where it lies.
pub(super) struct Placed {
    pub(super) grown: Shape,
    raw: Shape,
    pub(super) rooms: Vec<Shape>,
    raw_rooms: Vec<Shape>,
}

/// The rules of one job, ready to check placements against.
pub struct Checker {
    models: Vec<Model>,
    /// Each size of sheet's room and how many sheets of it, in order.
    rooms: Vec<(Room, usize)>,
    pub(super) eps: f64,
}

impl Checker {
    /// The models of every part of `job` and its sheet.
    pub fn new(job: &NestJob) -> Checker {
        let s = &job.settings;
        let (grow, tol) = (s.spacing / 2.0, s.tolerance);
        let models = job
            .parts
            .iter()
            .map(|p| Model {
                grown: collision_polygon(&p.outer, grow, tol),
                raw: collision_polygon(&p.outer, 0.0, tol),
                rooms: p
                    .holes
                    .iter()
                    .filter_map(|h| room_polygon(h, grow, tol))
                    .collect(),
                raw_rooms: p
                    .holes
                    .iter()
                    .filter_map(|h| room_polygon(h, 0.0, tol))
                    .collect(),
            })
            .collect();
        // One room per size of sheet (a list of sizes has several).
        let rooms = match &job.sheets {
            Sheets::Mixed(v) => v
                .iter()
                .map(|z| (room(job, &Sheets::rects(vec![*z])), z.count))
                .collect(),
            one => vec![(room(job, one), one.count())],
        };
        Checker {
            models,
            rooms,
            eps: s.touch(),
        }
    }

    /// Copy `p` where it lies, or None for a part that encloses nothing
    /// (or a placement naming no part).
    pub(super) fn placed(&self, p: &Placement) -> Option<Placed> {
        let m = self.models.get(p.part)?;
        let put = |q: &Polygon| Shape::new(q.placed(p.rotation, p.mirror, p.translation));
        Some(Placed {
            grown: put(m.grown.as_ref()?),
            raw: put(m.raw.as_ref()?),
            rooms: m.rooms.iter().map(put).collect(),
            raw_rooms: m.raw_rooms.iter().map(put).collect(),
        })
    }

    /// The room of sheet `k` (past the last: the last's).
    pub(super) fn room(&self, k: usize) -> &Room {
        let mut left = k;
        for (r, n) in &self.rooms {
            if left < *n {
                return r;
            }
            left -= n;
        }
        &self.rooms[self.rooms.len() - 1].0
    }

    /// True when a grown shape lies on sheet `k`, clear of its margin and
    /// no-go zones.
    pub(super) fn on_sheet(&self, s: &Shape, k: usize) -> bool {
        let r = self.room(k);
        inside_box(s, r.bounds, self.eps)
            && r.bound.as_ref().is_none_or(|b| within(b, s, self.eps))
            && !r.obstacles.iter().any(|o| overlaps(o, s, self.eps))
    }

    /// Why copy `c` is not on the sheet, if it is not.
    fn sheet_rule(&self, c: &Placed, k: usize) -> Option<Why> {
        if self.on_sheet(&c.grown, k) {
            return None;
        }
        let (r, eps) = (self.room(k), self.eps);
        let on = inside_box(&c.raw, r.raw_bounds, eps)
            && r.raw_bound.as_ref().is_none_or(|b| within(b, &c.raw, eps));
        Some(if !on {
            Why::OffSheet
        } else if r.raw_obstacles.iter().any(|o| overlaps(o, &c.raw, eps)) {
            Why::NoGo
        } else {
            Why::Margin
        })
    }

    /// The smallest room of `host` holding `guest` (grown), with its area.
    fn room_of(&self, host: &Placed, guest: &Placed) -> Option<f64> {
        host.rooms
            .iter()
            .filter(|r| within(r, &guest.grown, self.eps))
            .map(|r| r.poly.area())
            .min_by(f64::total_cmp)
    }

    /// Every broken rule of `placements` (each pair said for both copies),
    /// and for each copy the copy whose hole it lies in (an index).
    pub fn check(&self, placements: &[Placement]) -> (Vec<Conflict>, Vec<Option<usize>>) {
        let eps = self.eps;
        let placed: Vec<Option<Placed>> = placements.iter().map(|p| self.placed(p)).collect();
        let mut conflicts = Vec::new();
        let mut host: Vec<Option<(usize, f64)>> = vec![None; placements.len()];
        for (i, c) in placed.iter().enumerate() {
            let Some(c) = c else { continue };
            if let Some(why) = self.sheet_rule(c, placements[i].sheet) {
                conflicts.push(Conflict { copy: i, why });
            }
        }
        for i in 0..placed.len() {
            let Some(a) = &placed[i] else { continue };
            for j in i + 1..placed.len() {
                let Some(b) = &placed[j] else { continue };
                if placements[i].sheet != placements[j].sheet || !overlaps(&a.grown, &b.grown, eps)
                {
                    continue;
                }
                let mut keep = |guest: usize, h: usize, area: f64| {
                    if host[guest].is_none_or(|(_, a)| area < a) {
                        host[guest] = Some((h, area));
                    }
                };
                if let Some(area) = self.room_of(a, b) {
                    keep(j, i, area);
                    continue;
                }
                if let Some(area) = self.room_of(b, a) {
                    keep(i, j, area);
                    continue;
                }
                let in_raw_hole =
                    |h: &Placed, g: &Placed| h.raw_rooms.iter().any(|r| within(r, &g.raw, eps));
                let overlap =
                    overlaps(&a.raw, &b.raw, eps) && !in_raw_hole(a, b) && !in_raw_hole(b, a);
                let why = |with| {
                    if overlap {
                        Why::Overlap { with }
                    } else {
                        Why::Spacing { with }
                    }
                };
                conflicts.push(Conflict {
                    copy: i,
                    why: why(j),
                });
                conflicts.push(Conflict {
                    copy: j,
                    why: why(i),
                });
            }
        }
        conflicts.sort_by_key(|c| c.copy);
        (
            conflicts,
            host.into_iter().map(|h| h.map(|(i, _)| i)).collect(),
        )
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::geom::{Point, Segment};
    use crate::nest::{NestSettings, Part, Rotations};

    pub(crate) fn rect(x0: f64, y0: f64, w: f64, h: f64) -> Vec<Segment> {
        let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| Point::new(x + x0, y + y0));
        (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
            .collect()
    }

    /// A 100 × 50 plate with a 60 × 30 hole, and a 20 × 10 tab, on a
    /// 400 × 200 sheet, spacing 4, margin 10.
    pub(crate) fn job() -> NestJob {
        let part = |name: &str, outer, holes| Part {
            name: name.into(),
            outer,
            holes,
            quantity: 2,
            rotations: Rotations::Quarter,
            mirror: false,
        };
        NestJob {
            parts: vec![
                part(
                    "plate",
                    rect(0.0, 0.0, 100.0, 50.0),
                    vec![rect(20.0, 10.0, 60.0, 30.0)],
                ),
                part("tab", rect(0.0, 0.0, 20.0, 10.0), Vec::new()),
            ],
            sheets: Sheets::Rect {
                width: 400.0,
                height: 200.0,
                count: 1,
            },
            settings: NestSettings {
                spacing: 4.0,
                margin: 10.0,
                ..NestSettings::default()
            },
        }
    }

    pub(crate) fn at(part: usize, copy: usize, x: f64, y: f64) -> Placement {
        Placement {
            part,
            copy,
            sheet: 0,
            rotation: 0.0,
            mirror: false,
            translation: Point::new(x, y),
            in_hole_of: None,
        }
    }

    #[test]
    fn spacing_is_held_to_the_millimetre_and_overlaps_are_told_from_near_misses() {
        let job = job();
        let c = Checker::new(&job);
        // 4 mm apart: fine; 3.9 mm: too close; 1 mm into it: overlap.
        let (ok, _) = c.check(&[at(0, 0, 10.0, 10.0), at(0, 1, 114.0, 10.0)]);
        assert_eq!(ok, vec![]);
        let (near, _) = c.check(&[at(0, 0, 10.0, 10.0), at(0, 1, 113.9, 10.0)]);
        assert_eq!(
            near,
            vec![
                Conflict {
                    copy: 0,
                    why: Why::Spacing { with: 1 }
                },
                Conflict {
                    copy: 1,
                    why: Why::Spacing { with: 0 }
                }
            ]
        );
        let (over, _) = c.check(&[at(0, 0, 10.0, 10.0), at(0, 1, 109.0, 10.0)]);
        assert_eq!(over[0].why, Why::Overlap { with: 1 });
        // Turned by 90° about its corner: the plate then spans x −50..0.
        let mut turned = at(0, 1, 164.0, 10.0);
        turned.rotation = 90.0;
        assert_eq!(c.check(&[at(0, 0, 10.0, 10.0), turned]).0, vec![]);
        turned.translation.x = 163.0;
        assert!(matches!(
            c.check(&[at(0, 0, 10.0, 10.0), turned]).0[0].why,
            Why::Spacing { .. }
        ));
    }

    #[test]
    fn the_sheet_its_margin_and_a_part_in_a_hole() {
        let job = job();
        let c = Checker::new(&job);
        let why = |p: Placement| c.check(&[p]).0.first().map(|c| c.why);
        assert_eq!(why(at(0, 0, 10.0, 10.0)), None);
        assert_eq!(why(at(0, 0, 9.0, 10.0)), Some(Why::Margin));
        assert_eq!(why(at(0, 0, 250.0, 145.0)), Some(Why::Margin));
        assert_eq!(why(at(0, 0, 250.0, 160.0)), Some(Why::OffSheet));
        assert_eq!(why(at(0, 0, -1.0, 10.0)), Some(Why::OffSheet));
        // A tab in the plate's hole, 2 mm from its walls (half the spacing
        // each side is the rule: 4 mm from the hole's edge).
        let plate = at(0, 0, 10.0, 10.0);
        let (ok, host) = c.check(&[plate, at(1, 0, 34.0, 24.0)]);
        assert_eq!((ok, host), (vec![], vec![None, Some(0)]));
        let (near, _) = c.check(&[plate, at(1, 0, 33.0, 24.0)]);
        assert!(matches!(near[0].why, Why::Spacing { with: 1 }), "{near:?}");
        let (over, _) = c.check(&[plate, at(1, 0, 25.0, 24.0)]);
        assert!(matches!(over[0].why, Why::Overlap { with: 1 }), "{over:?}");
    }
}
