//! Open contours (markings, open cuts), cut on the drawn line before
//! any part is cut free: their order and their cuts.

use super::{Cut, PlanInput, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};

/// Open contours, nearest end next from `from`.
pub fn order(input: &PlanInput, from: Point) -> Vec<usize> {
    let mut left: Vec<usize> = (0..input.contours.contours.len())
        .filter(|&c| input.contours.contours[c].kind == ContourKind::Open)
        .collect();
    let mut at = from;
    let mut out = Vec::with_capacity(left.len());
    while !left.is_empty() {
        let ends = |c: usize| {
            let k = &input.contours.contours[c];
            (k.start(), k.segments.last().map_or(k.start(), |s| s.b))
        };
        let Some((i, _)) = left
            .iter()
            .enumerate()
            .map(|(i, &c)| {
                let (a, b) = ends(c);
                (i, a.dist(at).min(b.dist(at)))
            })
            .min_by(|x, y| x.1.total_cmp(&y.1))
        else {
            break;
        };
        let c = left.swap_remove(i);
        let (a, b) = ends(c);
        at = if a.dist(at) <= b.dist(at) { b } else { a };
        out.push(c);
    }
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
