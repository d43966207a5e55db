//! Holes too small to cut (issue 20 §3): below the kerf, or below the
//! small-hole rule's limit, a torch cannot make a round hole — the arc
//! blows a pierce crater wider than it. They are centre-spotted instead (to
//! be drilled), and said so, never left out in silence.

use crate::contour::{ContourKind, Contours};
use crate::geom::Point;
use crate::kerf::KerfPaths;
use crate::text;
use crate::warning::{dec, Warning};

/// With the process's small-hole rule on, takes the holes narrower than
/// max(limit, its kerf) out of `kerf` (their paths, if the kerf left one) and
/// returns their centres to spot; a warning in `kerf.warnings` names how
/// many and the first.
pub fn spot_too_small(
    contours: &Contours,
    kerf: &mut KerfPaths,
    process: &super::Process,
) -> Vec<Point> {
    let rule = &process.small_hole;
    if rule.diameter <= 0.0 {
        return Vec::new();
    }
    let limit = rule.min_diameter.max(process.kerf);
    let mut spots = Vec::new();
    let mut tiny = vec![false; contours.contours.len()];
    for (i, c) in contours.contours.iter().enumerate() {
        let b = c.bbox;
        let width = (b.max.x - b.min.x).min(b.max.y - b.min.y);
        if c.kind == ContourKind::Hole && width < limit {
            tiny[i] = true;
            spots.push(Point::new(
                (b.min.x + b.max.x) / 2.0,
                (b.min.y + b.max.y) / 2.0,
            ));
        }
    }
    kerf.paths
        .retain(|p| !tiny.get(p.contour).copied().unwrap_or(false));
    if let Some(&first) = spots.first() {
        let n = spots.len();
        kerf.warnings.push(Warning::at(
            "holes-spotted",
            text!("{n} hole(s) narrower than {limit:.3} mm (the kerf or the small-hole limit) cannot be cut round: centre-spotted instead, to be drilled";
                  "{n} furo(s) mais estreito(s) que {} mm (a sangria ou o limite de furo pequeno) não pode(m) ser cortado(s) redondo(s): marcado(s) com ponto no centro, para furar", dec(limit)),
            first,
        ));
    }
    spots
}
