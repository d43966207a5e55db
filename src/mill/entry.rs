//! Getting the tool down into a pocket's material at each depth (issue 43
//! §3): straight down, down a ramp back and forth along the start of the
//! path, or down a helix beside it. A ramp or a helix spreads the cut
//! over a length instead of drilling with the end mill's centre.

use super::region::Region;
use super::toolpath::Builder;
use crate::geom::{Point, Segment};
use crate::process::{Entry, Tool};

/// What an entry did, when it could not do what was asked.
pub(crate) enum Missed {
    /// The helix found no room in the region at this point: plunged.
    NoHelixRoom(Point),
}

/// The tool, above `top` (clear of material) at `path[0]`, goes down to
/// `z` as `tool.entry` says and ends at `path[0]` at `z`. `region` is the
/// tool-centre region: a ramp stays on the path, a helix inside it.
pub(crate) fn enter(
    b: &mut Builder,
    path: &[Point],
    top: f64,
    z: f64,
    tool: &Tool,
    region: &Region,
    eps: f64,
) -> Option<Missed> {
    let start = path[0];
    let drop = top - z;
    let slope = tool.ramp_angle_deg.to_radians().tan().max(1e-3);
    match tool.entry {
        Entry::Plunge => b.plunge(z),
        Entry::Ramp => {
            // A leg along the path's start, walked forth and back (an even
            // number of times: back at the start), each a share of the drop.
            let want = drop / slope;
            let leg = prefix(path, want.min(4.0 * tool.diameter));
            let len: f64 = leg.windows(2).map(|w| w[0].dist(w[1])).sum();
            if len < eps.max(1e-3) {
                b.plunge(z);
                return None;
            }
            let mut legs = (want / len).ceil().max(2.0) as usize;
            legs += legs % 2;
            let per = drop / legs as f64;
            let mut h = top;
            for k in 0..legs {
                let pts: Vec<Point> = if k % 2 == 0 {
                    leg.clone()
                } else {
                    leg.iter().rev().copied().collect()
                };
                let goal = top - per * (k + 1) as f64;
                let mut walked = 0.0;
                for w in pts.windows(2) {
                    walked += w[0].dist(w[1]);
                    let hz = if k + 1 == legs && walked >= len {
                        z
                    } else {
                        h - per * walked / len
                    };
                    b.cut(Segment::line(w[0], w[1]), hz.max(z));
                }
                h = goal;
            }
            b.plunge(z);
        }
        Entry::Helix => {
            let rh = tool.helix() / 2.0;
            let dirs = (0..16).map(|k| {
                let a = k as f64 * std::f64::consts::PI / 8.0;
                Point::new(a.cos(), a.sin())
            });
            // A centre whose circle through the start stays in the region.
            let centre = (dirs.map(|u| start.add(u.scale(rh))))
                .find(|&c| region.contains(c) && fits(region, c, rh, eps));
            let Some(c) = centre else {
                b.plunge(z);
                return Some(Missed::NoHelixRoom(start));
            };
            // Half turns (each an arc of bulge 1), an even number.
            let per_half = std::f64::consts::PI * rh * slope;
            let mut halves = (drop / per_half).ceil().max(2.0) as usize;
            halves += halves % 2;
            let opposite = c.add(c.sub(start));
            for k in 0..halves {
                let (a, e) = if k % 2 == 0 {
                    (start, opposite)
                } else {
                    (opposite, start)
                };
                let hz = top - drop * (k + 1) as f64 / halves as f64;
                b.cut(
                    Segment {
                        a,
                        b: e,
                        bulge: 1.0,
                    },
                    hz,
                );
            }
            // One flat turn at the bottom: the helix's floor is level.
            b.cut(
                Segment {
                    a: start,
                    b: opposite,
                    bulge: 1.0,
                },
                z,
            );
            b.cut(
                Segment {
                    a: opposite,
                    b: start,
                    bulge: 1.0,
                },
                z,
            );
        }
    }
    None
}

/// True when the circle of radius `r` around `c` stays in the region
/// (sampled every few degrees).
fn fits(region: &Region, c: Point, r: f64, eps: f64) -> bool {
    (0..64).all(|k| {
        let a = k as f64 * std::f64::consts::TAU / 64.0;
        let p = c.add(Point::new(a.cos(), a.sin()).scale(r));
        region.contains(p) || region.wall_dist(p) <= eps
    })
}

/// The start of the path, `len` long (cut at that length).
fn prefix(path: &[Point], len: f64) -> Vec<Point> {
    let mut out = vec![path[0]];
    let mut left = len;
    for w in path.windows(2) {
        let d = w[0].dist(w[1]);
        if d >= left {
            if d > 0.0 {
                out.push(w[0].add(w[1].sub(w[0]).scale(left / d)));
            }
            return out;
        }
        left -= d;
        out.push(w[1]);
    }
    out
}
