//! Arc fitting of the plan's feed moves (issue 43 §5, paper 004 §2.12):
//! runs of short moves of one role on one contour become the fewest lines
//! and arcs within the job's tolerance ([`crate::geom::fit_path`]). Done
//! on the plan, before anything reads it, so the preview, the program,
//! the time estimate and the report all see the same fitted path.
//!
//! A run ends where the role or the contour changes (a lead-in meets its
//! contour, a tab begins), so pierces, tabs and leads stay where the
//! planner put them.

use super::{ArcFit, CutPlan, Step};
use crate::geom::fit_path;

fn count(plan: &CutPlan) -> (usize, usize) {
    let steps = plan.cuts.iter().flat_map(|c| &c.steps);
    let lines = steps.clone().filter(|s| s.segment.is_line()).count();
    (lines, steps.count() - lines)
}

/// Fits `plan`'s feed moves within `tol` mm, in place; the counts are
/// kept in [`CutPlan::arc_fit`].
pub fn fit_arcs(plan: &mut CutPlan, tol: f64) {
    let (lines_before, arcs_before) = count(plan);
    for cut in &mut plan.cuts {
        if cut.steps.len() < 2 {
            continue;
        }
        let steps = std::mem::take(&mut cut.steps);
        let mut out = Vec::with_capacity(steps.len());
        let mut segs = Vec::new();
        for run in steps.chunk_by(|a, b| a.role == b.role && a.contour == b.contour) {
            if run.len() < 2 {
                out.extend_from_slice(run);
                continue;
            }
            segs.clear();
            segs.extend(run.iter().map(|s| s.segment));
            let (role, contour) = (run[0].role, run[0].contour);
            out.extend(fit_path(&segs, tol).into_iter().map(|segment| Step {
                segment,
                role,
                contour,
            }));
        }
        cut.steps = out;
    }
    let (lines_after, arcs_after) = count(plan);
    plan.arc_fit = Some(ArcFit {
        lines_before,
        arcs_before,
        lines_after,
        arcs_after,
        tolerance: tol,
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Point, Segment};
    use crate::plan::{Cut, Role};

    #[test]
    fn runs_are_fitted_within_their_role_and_contour_only() {
        // A lead-in of 10 collinear moves, then a contour of 10 moves on
        // the same line: two lines, the lead-in's end kept.
        let p = |x: f64| Point::new(x, 0.0);
        let seg = |k: usize| Segment::line(p(k as f64), p(k as f64 + 1.0));
        let mut steps: Vec<Step> = (0..10)
            .map(|k| Step {
                segment: seg(k),
                role: Role::LeadIn,
                contour: Some(0),
            })
            .collect();
        steps.extend((10..20).map(|k| Step {
            segment: seg(k),
            role: Role::Contour,
            contour: Some(0),
        }));
        let mut cut = Cut::loose(p(0.0), Vec::new(), Role::Contour);
        cut.steps = steps;
        let mut plan = CutPlan {
            cuts: vec![cut],
            ..CutPlan::default()
        };
        fit_arcs(&mut plan, 0.001);
        let steps = &plan.cuts[0].steps;
        assert_eq!(steps.len(), 2);
        assert_eq!((steps[0].role, steps[0].segment.b), (Role::LeadIn, p(10.0)));
        assert_eq!(
            (steps[1].role, steps[1].segment.b),
            (Role::Contour, p(20.0))
        );
        let fit = plan.arc_fit.unwrap();
        assert_eq!(
            (fit.lines_before, fit.lines_after, fit.arcs_after),
            (20, 2, 0)
        );
    }
}
