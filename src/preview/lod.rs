//! Level of detail for the preview's dots (issue 19 item 2): pierce and
//! invalid-vertex dots are drawn full size where they stand apart and smaller
//! where they crowd, so a drawing of a thousand small holes fitted in the
//! window shows its parts and their pierces, not a solid mass of dots.
//!
//! The test of crowding is a grid of cells one dot across: a dot whose cell
//! is already taken would overlap (or nearly touch) another. The largest
//! radius at which at most 1 dot in [`CROWDED`] lands in a taken cell wins.
//! Every dot is still drawn: only its size changes.

use std::collections::HashSet;

/// At most one dot in this many may share its cell with another.
const CROWDED: usize = 20;

/// Radii tried, as fractions of the full radius, largest first.
const STEPS: [f32; 4] = [1.0, 0.625, 0.4, 0.25];

/// The radius (device pixels) to draw dots at `points` (device pixels) with:
/// `full` where they stand apart, down to `min` where they crowd.
pub fn dot_radius(points: &[(f32, f32)], full: f32, min: f32) -> f32 {
    let mut taken = HashSet::with_capacity(points.len());
    for f in STEPS {
        let r = (full * f).max(min);
        let cell = 2.0 * r + 1.0; // a dot's diameter and a pixel of white between two
        taken.clear();
        let crowded = points
            .iter()
            .filter(|(x, y)| !taken.insert(((x / cell).floor() as i64, (y / cell).floor() as i64)))
            .count();
        if crowded * CROWDED <= points.len() || r <= min {
            return r;
        }
    }
    min
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize, step: f32) -> Vec<(f32, f32)> {
        (0..n * n)
            .map(|i| ((i % n) as f32 * step + 0.3, (i / n) as f32 * step + 0.3))
            .collect()
    }

    #[test]
    fn dots_far_apart_are_drawn_full_size() {
        assert_eq!(dot_radius(&grid(30, 40.0), 4.0, 1.0), 4.0);
        assert_eq!(dot_radius(&[], 4.0, 1.0), 4.0);
        assert_eq!(dot_radius(&[(5.0, 5.0)], 4.0, 1.0), 4.0);
    }

    #[test]
    fn crowded_dots_shrink_until_they_stand_apart() {
        // 7 px apart: full dots (9 px cells) overlap; 2.5 px dots (6 px cells) do not.
        let r = dot_radius(&grid(30, 7.0), 4.0, 1.0);
        assert_eq!(r, 2.5);
        // Whatever the radius chosen, two neighbours' dots leave a gap between them.
        assert!(2.0 * r < 7.0);
        // 2 px apart: as small as allowed, never gone.
        assert_eq!(dot_radius(&grid(30, 2.0), 4.0, 1.0), 1.0);
    }

    #[test]
    fn a_few_crowded_dots_among_many_apart_keep_the_full_size() {
        let mut points = grid(30, 40.0); // 900 apart
        points.extend((0..20).map(|i| (1000.0 + i as f32, 1000.0))); // 20 in a clump
        assert_eq!(dot_radius(&points, 4.0, 1.0), 4.0);
    }
}
