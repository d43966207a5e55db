//! Open contours (markings, open cuts), cut on the drawn line before
//! any part is cut free: their order and their cuts.

use super::{nearest, Cut, PlanInput, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};

/// Open contours, nearest end next from `from` (the tool leaving each at
/// its other end).
pub fn order(input: &PlanInput, from: Point) -> Vec<usize> {
    let contours = &input.contours.contours;
    let open: Vec<usize> = (0..contours.len())
        .filter(|&c| contours[c].kind == ContourKind::Open)
        .collect();
    let ends = |c: usize| {
        let k = &contours[c];
        (k.start(), k.segments.last().map_or(k.start(), |s| s.b))
    };
    let mut points = Vec::with_capacity(2 * open.len());
    let mut owners = Vec::with_capacity(2 * open.len());
    for (i, &c) in open.iter().enumerate() {
        let (a, b) = ends(c);
        points.extend([a, b]);
        owners.extend([i, i]);
    }
    let mut out = Vec::with_capacity(open.len());
    let mut at = from;
    nearest::visit_nearest(&points, &owners, open.len(), from, |i| {
        let c = open[i];
        let (a, b) = ends(c);
        at = if a.dist(at) <= b.dist(at) { b } else { a };
        out.push(c);
        at
    });
    out
}

/// Open contour `c` cut on the line, from its end nearest `near`.
pub fn cut(input: &PlanInput, c: usize, near: Point) -> Option<Cut> {
    let contour = input.contours.contours.get(c)?;
    let (first, last) = (contour.segments.first()?, contour.segments.last()?);
    let steps: Vec<Segment> = if last.b.dist(near) < first.a.dist(near) {
        contour
            .segments
            .iter()
            .rev()
            .map(Segment::reversed)
            .collect()
    } else {
        contour.segments.clone()
    };
    Some(Cut {
        pierce: steps[0].a,
        steps: steps
            .into_iter()
            .map(|segment| Step {
                segment,
                role: Role::Contour,
                contour: Some(c),
            })
            .collect(),
        contours: vec![c],
        part: None,
        kind: ContourKind::Open,
        spot: false,
        small_hole: false,
        comp: None,
    })
}
