//! The turns a part may take ([`Rotations`]), by the names the CLI and the
//! page give them.
//!
//! Free rotation is any angle. The placer and the separator try a set of
//! turns per part ([`Rotations::angles_for`]): steps of 15°, and the turns
//! that lay each of the longest edges of the part's convex hull along x
//! (with their quarter turns). Those are the turns at which a part lies
//! flush with the sheet's edges and with copies of itself; the smallest
//! box around a polygon has one of its sides on a hull edge (Freeman &
//! Shapira, CACM 1975), so it is among them. A part drawn at 10° is tried
//! at −10°, which no step of 15° reaches.

use crate::geom::{Point, Segment};

/// Steps used for free (continuous) rotation: 15°, beside the turns of the
/// part's own hull edges ([`FREE_EDGES`]). Each turn is a variant the
/// placer tries: more cost time linearly.
pub const FREE_STEPS: u32 = 24;
/// Hull edges, longest first, whose turns free rotation adds (4 turns each).
pub const FREE_EDGES: usize = 4;

/// Turns a part may take.
#[derive(Clone, Debug, PartialEq)]
pub enum Rotations {
    /// As drawn.
    None,
    /// 0° and 180°.
    Half,
    /// Steps of 90°.
    Quarter,
    /// N equal steps of 360°/N.
    Steps(u32),
    /// Any angle (tried in [`FREE_STEPS`] steps and at the turns of the
    /// part's hull edges, [`Rotations::angles_for`]).
    Free,
    /// These angles, degrees.
    List(Vec<f64>),
}

impl Rotations {
    /// From the CLI's and the page's names: none, 180, 90, free, or a
    /// number of equal steps 1..=360.
    pub fn from_name(name: &str) -> Option<Rotations> {
        Some(match name {
            "none" | "0" => Rotations::None,
            "180" => Rotations::Half,
            "90" => Rotations::Quarter,
            "free" => Rotations::Free,
            n => match n.parse::<u32>() {
                Ok(k) if (1..=360).contains(&k) => Rotations::Steps(k),
                _ => return None,
            },
        })
    }

    /// The angles tried, degrees.
    pub fn angles(&self) -> Vec<f64> {
        let steps = |n: u32| {
            (0..n.max(1))
                .map(|k| 360.0 * k as f64 / n.max(1) as f64)
                .collect()
        };
        match self {
            Rotations::None => vec![0.0],
            Rotations::Half => vec![0.0, 180.0],
            Rotations::Quarter => steps(4),
            Rotations::Steps(n) => steps(*n),
            Rotations::Free => steps(FREE_STEPS),
            Rotations::List(v) if v.is_empty() => vec![0.0],
            Rotations::List(v) => v.clone(),
        }
    }

    /// The angles tried for a part with outline `outer` (drawing
    /// coordinates), mirrored x → −x first when `mirror`: [`Self::angles`],
    /// and for free rotation also the turns laying each of its
    /// [`FREE_EDGES`] longest hull edges along x, and their quarter turns.
    pub fn angles_for(&self, outer: &[Segment], mirror: bool) -> Vec<f64> {
        let mut out = self.angles();
        if *self != Rotations::Free {
            return out;
        }
        let pts: Vec<Point> = outer
            .iter()
            .flat_map(|s| [s.a, s.point_at(0.5)])
            .map(|p| if mirror { Point::new(-p.x, p.y) } else { p })
            .collect();
        let hull = convex_hull(pts);
        let n = hull.len();
        let mut edges: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let d = hull[(i + 1) % n].sub(hull[i]);
                (d.norm(), d.y.atan2(d.x).to_degrees())
            })
            .filter(|e| e.0 > 0.0 && e.1.is_finite())
            .collect();
        edges.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.total_cmp(&b.1)));
        for &(_, theta) in edges.iter().take(FREE_EDGES) {
            for k in 0..4 {
                let a = (-theta + 90.0 * k as f64).rem_euclid(360.0);
                let a = if a >= 360.0 - 1e-9 { 0.0 } else { a };
                let near = |b: &f64| {
                    let d = (a - b).rem_euclid(360.0);
                    d.min(360.0 - d) < 1e-6
                };
                if !out.iter().any(near) {
                    out.push(a);
                }
            }
        }
        out
    }
}

/// The convex hull of `pts`, counter-clockwise, collinear points dropped
/// (Andrew's monotone chain, 1979).
fn convex_hull(mut pts: Vec<Point>) -> Vec<Point> {
    pts.retain(|p| p.is_finite());
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let turn = |o: Point, a: Point, b: Point| a.sub(o).cross(b.sub(o));
    let mut h: Vec<Point> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = h.len();
        let it: Box<dyn Iterator<Item = &Point>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &p in it {
            while h.len() >= start + 2 && turn(h[h.len() - 2], h[h.len() - 1], p) <= 0.0 {
                h.pop();
            }
            h.push(p);
        }
        h.pop();
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_at(deg: f64) -> Vec<Segment> {
        let (s, c) = deg.to_radians().sin_cos();
        let p = [(0.0, 0.0), (100.0, 0.0), (100.0, 50.0), (0.0, 50.0)]
            .map(|(x, y)| Point::new(c * x - s * y, s * x + c * y));
        (0..4)
            .map(|i| Segment::line(p[i], p[(i + 1) % 4]))
            .collect()
    }

    #[test]
    fn free_rotation_tries_the_turns_that_lay_hull_edges_flat() {
        let r = Rotations::Free;
        let a = r.angles_for(&square_at(10.0), false);
        // The 24 steps, and −10° with its quarter turns.
        assert_eq!(a.len(), 28, "{a:?}");
        for want in [350.0, 80.0, 170.0, 260.0] {
            assert!(a.iter().any(|x| (x - want).abs() < 1e-9), "{want} in {a:?}");
        }
        // Mirrored, the rectangle leans the other way: +10°.
        let m = r.angles_for(&square_at(10.0), true);
        assert!(m.iter().any(|x| (x - 10.0).abs() < 1e-9), "{m:?}");
        // Edges already on a step add nothing; other kinds are their angles.
        assert_eq!(r.angles_for(&square_at(0.0), false).len(), 24);
        assert_eq!(
            Rotations::Quarter.angles_for(&square_at(10.0), false).len(),
            4
        );
    }

    #[test]
    fn the_hull_of_an_l_skips_its_notch() {
        let p = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ]
        .map(|(x, y)| Point::new(x, y));
        let h = convex_hull(p.to_vec());
        assert_eq!(h.len(), 5, "{h:?}");
        assert!(!h.contains(&Point::new(1.0, 1.0)));
    }
}
