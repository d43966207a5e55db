//! Lead-ins and lead-outs: from a pierce point in scrap to the contour's
//! start, and past it at the end.
//!
//! Paper 001 §2.2 (L1066–L1095) defines the entry "vectors": tangential (TV,
//! outer contours only, continuing the first edge backwards), perpendicular
//! (PV, the only one for circles) and bisector (BV, along the bisector of the
//! corner's two edges); the lead length is measured to the *compensated*
//! contour point (annex E/G check in the notes). We add the arc lead-in
//! (a quarter circle ending tangent to the first edge), lead-outs
//! (overcut), and what the thesis leaves to the user's eye: a lead must
//! stay in scrap — it may not cross any part, and its pierce point keeps a
//! clearance of one kerf from every part. A lead that does not fit is
//! shortened, a small hole is pierced at its centre (paper 001 L1476: "small
//! inner cut-outs where the entry point would be too close to an edge"), and
//! when nothing fits the contour is pierced on its start point, with a
//! warning.

use super::clearance::Obstacles;
use super::{LeadKind, LeadOptions};
use crate::geom::{path_bbox, Point, Segment};

/// Where a lead-in ended up.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// The pierce point.
    pub pierce: Point,
    /// The lead-in move from the pierce point to the contour's start
    /// (none: pierced on the start; one line or arc, held in place: a
    /// vector was an allocation a contour).
    pub lead: Option<Segment>,
    /// The lead is shorter than asked, or another kind than asked.
    pub changed: bool,
}

/// What a lead is placed against.
pub struct LeadSite<'a> {
    /// The contour's loop, oriented for cutting, starting at its start point.
    pub path: &'a [Segment],
    /// Scrap is on the left of the direction of travel.
    pub scrap_left: bool,
    /// True for a hole (no tangential leads; centre pierce allowed).
    pub hole: bool,
}

/// The side normal pointing into scrap for travel direction `t`.
fn scrap_normal(t: Point, scrap_left: bool) -> Point {
    if scrap_left {
        t.perp()
    } else {
        t.perp().scale(-1.0)
    }
}

/// The lead of `kind` and `length` ending at the path's start (one line or
/// arc: no vector made for a try that may not fit), or None when that kind
/// has no meaning there.
fn shape(site: &LeadSite, kind: LeadKind, length: f64) -> Option<Segment> {
    let first = site.path.first()?;
    let last = site.path.last()?;
    let s = first.a;
    let t_out = first.tangent_at(0.0);
    let n_out = scrap_normal(t_out, site.scrap_left);
    let line = |dir: Point| Some(Segment::line(s.add(dir.scale(length)), s));
    match kind {
        LeadKind::None => None,
        LeadKind::Perpendicular => line(n_out),
        LeadKind::Tangential if site.hole || !first.is_line() => None,
        LeadKind::Tangential => line(t_out.scale(-1.0)),
        LeadKind::Bisector => {
            let n_in = scrap_normal(last.tangent_at(1.0), site.scrap_left);
            let b = n_in.add(n_out);
            if b.norm() < 1e-6 {
                return None;
            }
            line(b.unit())
        }
        LeadKind::Arc => {
            // Centre one lead length into scrap from the start; the arc
            // runs a quarter turn from behind the start to it, arriving
            // along the first edge's tangent.
            let c = s.add(n_out.scale(length));
            let p = c.sub(t_out.scale(length));
            let bulge = (std::f64::consts::FRAC_PI_2 / 4.0).tan();
            Some(Segment {
                a: p,
                b: s,
                bulge: if site.scrap_left { bulge } else { -bulge },
            })
        }
    }
}

/// Finds a lead-in that stays in scrap. `clearance` is how far the pierce
/// point keeps from every drawn contour (one kerf: the pierce hole is about
/// twice the kerf wide). A hole may be pierced at its centre (the middle of
/// its path's box), placed only when that try comes (most leads fit
/// before it; the box of every hole's arcs was a tenth of the cuts' time
/// on a 137k-contour sheet).
pub fn lead_in(
    site: &LeadSite,
    options: &LeadOptions,
    obstacles: &Obstacles,
    clearance: f64,
) -> Entry {
    let start = site.path.first().map_or(Point::default(), |s| s.a);
    let asked_len = if site.hole {
        options.hole_length
    } else {
        options.outer_length
    };
    let on_contour = Entry {
        pierce: start,
        lead: None,
        changed: options.kind != LeadKind::None && asked_len > 0.0,
    };
    if options.kind == LeadKind::None || asked_len <= 0.0 {
        return on_contour;
    }
    let fits = |lead: &Segment| {
        let p = lead.a;
        p.is_finite()
            && obstacles.clear_of(p, clearance)
            && obstacles.path_is_clear(std::slice::from_ref(lead), &[start])
    };
    // Each try is a lead of some kind and length, or (None) a hole's centre
    // pierce; at most 10, in an array (a vector a contour was 137k
    // allocations on a big sheet).
    let mut tries = [None; 12];
    let mut n = 0;
    let mut push = |t: Option<(LeadKind, f64)>| {
        tries[n] = t;
        n += 1;
    };
    for k in [1.0, 0.5, 0.25] {
        push(Some((options.kind, asked_len * k)));
        if options.kind != LeadKind::Bisector {
            // At a corner the bisector has the most room (paper 001's BV).
            push(Some((LeadKind::Bisector, asked_len * k)));
        }
        if site.hole && k == 1.0 {
            // The centre pierce, tried after the full-length leads.
            push(None);
        }
        if options.kind != LeadKind::Perpendicular {
            push(Some((LeadKind::Perpendicular, asked_len * k)));
        }
    }
    for (i, attempt) in tries.into_iter().take(n).enumerate() {
        let lead = match attempt {
            Some((kind, len)) => match shape(site, kind, len) {
                Some(l) => l,
                None => continue,
            },
            None => {
                let b = path_bbox(site.path);
                let c = b.centre();
                if c.dist(start) > clearance {
                    Segment::line(c, start)
                } else {
                    continue;
                }
            }
        };
        if fits(&lead) {
            return Entry {
                pierce: lead.a,
                lead: Some(lead),
                changed: i > 0,
            };
        }
    }
    on_contour
}

/// The first `length` mm of a loop, for an overcut (the lead-out cuts past
/// the start again, so the slug drops free with no nib left).
pub fn overcut(path: &[Segment], length: f64) -> Vec<Segment> {
    let mut left = length;
    let mut out = Vec::new();
    for s in path {
        if left <= 0.0 {
            break;
        }
        let l = s.length();
        if l <= left {
            out.push(*s);
            left -= l;
            continue;
        }
        out.push(prefix(s, left / l));
        break;
    }
    out
}

/// The part of `s` from its start to parameter `t` (arcs by angle).
pub fn prefix(s: &Segment, t: f64) -> Segment {
    let t = t.clamp(0.0, 1.0);
    let b = s.point_at(t);
    if s.is_line() {
        return Segment::line(s.a, b);
    }
    Segment {
        a: s.a,
        b,
        bulge: (s.sweep() * t / 4.0).tan(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contour::extract;
    use crate::dxf::{Drawing, Entity};

    fn square(x0: f64, y0: f64, w: f64, ccw: bool) -> Vec<Segment> {
        let p = [
            Point::new(x0, y0),
            Point::new(x0 + w, y0),
            Point::new(x0 + w, y0 + w),
            Point::new(x0, y0 + w),
        ];
        let mut v: Vec<Segment> = (0..4)
            .map(|i| Segment::line(p[i], p[(i + 1) % 4]))
            .collect();
        if !ccw {
            v = v.iter().rev().map(Segment::reversed).collect();
        }
        v
    }

    fn obstacles(loops: &[Vec<Segment>]) -> Obstacles {
        let d = Drawing {
            entities: loops
                .iter()
                .map(|l| Entity {
                    kind: "LWPOLYLINE",
                    layer: 0,
                    place: crate::dxf::Place::Line(1),
                    segments: l.clone(),
                    closed: true,
                    source: None,
                    insert: None,
                })
                .collect(),
            ..Drawing::default()
        };
        Obstacles::new(&extract(&d, crate::geom::Tolerance(1e-3), 0.05), 1e-3)
    }

    #[test]
    fn a_perpendicular_lead_goes_into_scrap_outside_an_outer_contour() {
        // Outer contour cut clockwise: scrap on the left.
        let path = square(0.0, 0.0, 100.0, false);
        let obs = obstacles(&[square(0.0, 0.0, 100.0, true)]);
        let site = LeadSite {
            path: &path,
            scrap_left: true,
            hole: false,
        };
        let e = lead_in(&site, &LeadOptions::DEFAULT, &obs, 1.0);
        assert!(!e.changed);
        // Clockwise from (0,0) the first edge goes up the left side; scrap is at x < 0.
        assert!((e.pierce.x + 5.0).abs() < 1e-9 && e.pierce.y.abs() < 1e-9);
    }

    #[test]
    fn a_lead_that_would_hit_a_neighbour_is_shortened_or_turned() {
        let path = square(0.0, 0.0, 100.0, false);
        // A neighbour 3 mm to the left.
        let obs = obstacles(&[
            square(0.0, 0.0, 100.0, true),
            square(-53.0, -20.0, 50.0, true),
        ]);
        let site = LeadSite {
            path: &path,
            scrap_left: true,
            hole: false,
        };
        let e = lead_in(&site, &LeadOptions::DEFAULT, &obs, 1.0);
        assert!(e.changed);
        assert!(obs.distance(e.pierce, 10.0) >= 1.0);
        assert!(obs.path_is_clear(e.lead.as_slice(), &[path[0].a]));
    }

    #[test]
    fn a_small_hole_is_pierced_at_its_centre() {
        // A 4 mm square hole cut counter-clockwise: scrap (the slug) on the left.
        let path = square(0.0, 0.0, 4.0, true);
        let obs = obstacles(&[
            square(-50.0, -50.0, 106.0, true),
            square(0.0, 0.0, 4.0, true),
        ]);
        let site = LeadSite {
            path: &path,
            scrap_left: true,
            hole: true,
        };
        let opts = LeadOptions {
            hole_length: 5.0,
            ..LeadOptions::DEFAULT
        };
        let e = lead_in(&site, &opts, &obs, 1.5);
        assert_eq!(e.pierce, Point::new(2.0, 2.0));
        // The lead runs from the centre to the path's start, inside the hole,
        // and is no longer than the way there (the asked 5 mm would not fit).
        let lead: &[Segment] = e.lead.as_slice();
        assert!(!lead.is_empty(), "a lead from the centre to the path");
        assert_eq!(lead[0].a, Point::new(2.0, 2.0));
        assert_eq!(lead[lead.len() - 1].b, path[0].a);
        let len: f64 = lead.iter().map(Segment::length).sum();
        assert!(len <= Point::new(2.0, 2.0).dist(path[0].a) + 1e-9, "{len}");
        for s in lead {
            for t in [0.0, 0.5, 1.0] {
                let p = s.point_at(t);
                assert!(
                    (-1e-9..=4.0 + 1e-9).contains(&p.x) && (-1e-9..=4.0 + 1e-9).contains(&p.y),
                    "{p:?} leaves the hole"
                );
            }
        }
    }

    #[test]
    fn arc_lead_ends_tangent_to_the_first_edge() {
        let path = square(0.0, 0.0, 100.0, false);
        let site = LeadSite {
            path: &path,
            scrap_left: true,
            hole: false,
        };
        let lead = shape(&site, LeadKind::Arc, 5.0).unwrap();
        let t = lead.tangent_at(1.0);
        let t0 = path[0].tangent_at(0.0);
        assert!(t.sub(t0).norm() < 1e-9, "{t:?} {t0:?}");
        assert!(lead.point_at(0.5).x < 0.0);
    }

    #[test]
    fn overcut_takes_the_first_millimetres_of_lines_and_arcs() {
        let path = square(0.0, 0.0, 10.0, true);
        let o = overcut(&path, 12.0);
        assert_eq!(o.len(), 2);
        assert!((o.iter().map(Segment::length).sum::<f64>() - 12.0).abs() < 1e-9);
        let arc = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let p = prefix(&arc, 0.5);
        assert!((p.b.x).abs() < 1e-9 && (p.b.y - 10.0).abs() < 1e-9);
        assert!((p.length() - arc.length() / 2.0).abs() < 1e-9);
    }
}
