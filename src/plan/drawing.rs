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
use crate::text;
use crate::warning::{dec, Warning};

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
        small_hole: false,
        comp: None,
    }
}

/// Plans the drawing order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let tol = input.tolerance.max(0.0);
    let d = input.file;
    let mut warnings = Vec::new();
    if input.process.kerf > 0.0 {
        let w = input.process.kerf;
        warnings.push(Warning::new(
            "kerf-not-compensated",
            text!("the drawing order cuts on the drawn lines: the kerf width {w} mm is not compensated";
                  "a ordem do desenho corta sobre as linhas desenhadas: a sangria de {} mm não é compensada", dec(w)),
        ));
    }
    warnings.extend(freed_before_holes(input));
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
        common_line: Vec::new(),
        arc_fit: None,
        origin: options.origin,
        order: Order::Drawing,
        cuts,
        warnings,
        tour: None,
    }
}

/// Parts this order cuts free before all their holes: it follows the file,
/// so a part whose outline comes before one of its holes in the file is
/// loose (it may drop or shift on the slats) while that hole is cut.
fn freed_before_holes(input: &PlanInput) -> Option<Warning> {
    let cs = &input.contours.contours;
    let last = |i: usize| cs[i].entities.iter().copied().max();
    let mut parts: Vec<usize> = cs
        .iter()
        .enumerate()
        .filter(|(_, h)| h.kind == ContourKind::Hole)
        .filter_map(|(i, h)| {
            let outer = h
                .parent
                .filter(|&o| cs.get(o).is_some_and(|c| c.kind == ContourKind::Outer))?;
            (last(i)? > last(outer)?).then_some(h.part?)
        })
        .collect();
    crate::sort::sort_indices(&mut parts);
    parts.dedup();
    let (n, first) = (parts.len(), *parts.first()?);
    Some(Warning::new(
        "part-freed-before-holes",
        text!("the drawing order cuts {n} part(s) free before all their holes (part {first} first): the part may drop or shift before its holes are cut; the contour and chained orders cut holes first";
              "a ordem do desenho solta {n} peça(s) antes de cortar todos os seus furos (a peça {first} primeiro): a peça pode cair ou se mover antes do corte dos furos; as ordens contorno a contorno e encadeada cortam os furos primeiro"),
    ))
}

#[cfg(test)]
mod tests {
    use crate::geom::Point;
    use crate::plan::Order;

    fn line(a: (f64, f64), b: (f64, f64)) -> String {
        format!(
            "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
            a.0, a.1, b.0, b.1
        )
    }

    #[test]
    fn touching_entities_share_a_cut_and_points_keep_their_place() {
        let dxf = format!(
            "0\nSECTION\n2\nENTITIES\n{}{}0\nPOINT\n8\n0\n10\n5\n20\n5\n{}0\nENDSEC\n0\nEOF\n",
            line((0.0, 0.0), (10.0, 0.0)),
            // Drawn backwards: started from its end at (10, 0), torch kept on.
            line((20.0, 0.0), (10.0, 0.0)),
            line((40.0, 0.0), (30.0, 0.0)),
        );
        let mut s = crate::Settings::new(1.0, 0.001, 1000.0).unwrap();
        s.plan.order = Order::Drawing;
        let out = crate::run(dxf.as_bytes(), &s).unwrap();
        let p = &out.plan;
        assert_eq!(p.order, Order::Drawing);
        assert_eq!(p.cuts.len(), 3);
        assert_eq!(p.cuts[0].steps.len(), 2);
        assert_eq!(p.cuts[0].end(), Point::new(20.0, 0.0));
        assert!(p.cuts[1].spot);
        assert_eq!(p.cuts[1].pierce, Point::new(5.0, 5.0));
        // From the spot at (5, 5), (30, 0) is the nearer end.
        assert_eq!(p.cuts[2].pierce, Point::new(30.0, 0.0));
        // On the drawn lines: the kerf is not applied, and the user is told.
        assert!(p.warnings.iter().any(|w| w.message().contains("kerf")));
        assert!(!p
            .warnings
            .iter()
            .any(|w| w.code == "part-freed-before-holes"));
    }

    #[test]
    fn an_outline_drawn_before_its_hole_is_said_to_free_the_part_first() {
        let square = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n100\n10\n0\n20\n100\n";
        let hole = "0\nCIRCLE\n8\n0\n10\n50\n20\n50\n40\n10\n";
        let run = |body: String| {
            let dxf = format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n");
            let mut s = crate::Settings::new(1.0, 0.001, 1000.0).unwrap();
            s.plan.order = Order::Drawing;
            crate::run(dxf.as_bytes(), &s).unwrap().plan.warnings
        };
        let w = run(format!("{square}{hole}"));
        let freed: Vec<_> = w
            .iter()
            .filter(|w| w.code == "part-freed-before-holes")
            .collect();
        assert_eq!(freed.len(), 1, "{w:?}");
        assert!(freed[0]
            .message()
            .contains("1 part(s) free before all their holes (part 1 first)"));
        // Hole first, as the file should be: nothing to say.
        let w = run(format!("{hole}{square}"));
        assert!(
            !w.iter().any(|w| w.code == "part-freed-before-holes"),
            "{w:?}"
        );
    }
}
