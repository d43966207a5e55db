//! Order "drawing" (paper 002, Richetti & da Silva, "Programa CN"): the
//! DXF's entities in the file's own order, each started from the end nearest
//! the current point (an entity is reversed as needed; a closed one starts at
//! its vertex nearest the current point), the torch kept on while the next
//! entity starts where the last ended and switched off and on across a gap,
//! POINTs as spots where they come in the file. Cuts are on the drawn lines:
//! the kerf is not compensated (welding, marking, the paper's XY table).

use super::{Cut, CutPlan, Order, PlanInput, PlanOptions, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};
use crate::warning::Warning;

/// An entity's segments, travelled from the end nearest `at`.
fn oriented(segs: &[Segment], closed: bool, at: Point, tol: f64) -> Vec<Segment> {
    let (Some(first), Some(last)) = (segs.first(), segs.last()) else {
        return Vec::new();
    };
    if closed || first.a.dist(last.b) <= tol {
        let k = segs
            .iter()
            .enumerate()
            .min_by(|(_, x), (_, y)| x.a.dist(at).total_cmp(&y.a.dist(at)))
            .map_or(0, |(i, _)| i);
        let mut v = segs.to_vec();
        v.rotate_left(k);
        return v;
    }
    if at.dist(last.b) < at.dist(first.a) {
        segs.iter().rev().map(Segment::reversed).collect()
    } else {
        segs.to_vec()
    }
}

fn new_cut(pierce: Point, spot: bool) -> Cut {
    Cut {
        pierce,
        steps: Vec::new(),
        contours: Vec::new(),
        part: None,
        kind: ContourKind::Open,
        spot,
    }
}

/// Plans the drawing order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let tol = input.tolerance.max(0.0);
    let d = input.drawing;
    let mut warnings = Vec::new();
    if input.kerf_width > 0.0 {
        warnings.push(Warning::new(format!(
            "the drawing order cuts on the drawn lines: the kerf width {} mm is not compensated",
            input.kerf_width
        )));
    }
    let mut cuts: Vec<Cut> = Vec::new();
    let mut open: Option<Cut> = None;
    let mut at = options.origin;
    let mut spots = d.spots.iter().peekable();
    for (e, entity) in d.entities.iter().enumerate() {
        while let Some(s) = spots.next_if(|s| s.after_entities <= e) {
            cuts.extend(open.take());
            cuts.push(new_cut(s.at, true));
            at = s.at;
        }
        for seg in oriented(&entity.segments, entity.closed, at, tol) {
            let touches = open.as_ref().is_some_and(|c| c.end().dist(seg.a) <= tol);
            if !touches {
                // A gap: torch off, move, torch on (paper 002's rule).
                cuts.extend(open.take());
                open = Some(new_cut(seg.a, false));
            }
            if let Some(c) = open.as_mut() {
                c.steps.push(Step {
                    segment: seg,
                    role: Role::Contour,
                    contour: None,
                });
            }
            at = seg.b;
        }
    }
    cuts.extend(open.take());
    for s in spots {
        cuts.push(new_cut(s.at, true));
    }
    CutPlan {
        origin: options.origin,
        order: Order::Drawing,
        cuts,
        warnings,
    }
}
