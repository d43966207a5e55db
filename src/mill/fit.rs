//! Arc fitting of the milling (issue 43 §5, paper 004 §2.12): runs of
//! flat cutting moves at one height — a pocket's zig-zag chains and their
//! links, its offsets and finishing passes, an engraving of a polyline —
//! become the fewest lines and arcs within the job's tolerance
//! ([`crate::geom::fit_path`]), as the plan's feed moves do
//! ([`crate::plan::fit_arcs`]). Done on the [`Toolpath`] before anything
//! reads it, so the program, Play, the SVG, the preview and the time read
//! the same path.
//!
//! A run ends at any other move: a rapid, a plunge, a note, or a cut that
//! changes height (a ramp or a helix, kept as planned: its Z is spread
//! over its own moves).

use super::{MillMove, Toolpath};
use crate::geom::{fit_path, Segment};
use crate::plan::ArcFit;

fn count(t: &Toolpath) -> (usize, usize) {
    let (mut lines, mut arcs) = (0, 0);
    for m in &t.moves {
        if let MillMove::Cut { seg, .. } = m {
            if seg.is_line() {
                lines += 1;
            } else {
                arcs += 1;
            }
        }
    }
    (lines, arcs)
}

/// Fits `t`'s flat cutting runs within `tol` mm, in place; the counts of
/// cutting moves before and after.
pub fn fit_arcs(t: &mut Toolpath, tol: f64) -> ArcFit {
    let (lines_before, arcs_before) = count(t);
    let moves = std::mem::take(&mut t.moves);
    let mut out = Vec::with_capacity(moves.len());
    // The run being gathered: its height and segments.
    let mut run: Vec<Segment> = Vec::new();
    let mut run_z = f64::NAN;
    // Height before each move (the toolpath starts at the retract height,
    // above any cut: the first cut is never taken as flat by mistake).
    let mut z = f64::NAN;
    let flush = |run: &mut Vec<Segment>, run_z: f64, out: &mut Vec<MillMove>| {
        if run.is_empty() {
            return;
        }
        out.extend(
            fit_path(run, tol)
                .into_iter()
                .map(|seg| MillMove::Cut { seg, z: run_z }),
        );
        run.clear();
    };
    for m in moves {
        match m {
            MillMove::Cut { seg, z: h } if h == z => {
                if h != run_z {
                    flush(&mut run, run_z, &mut out);
                    run_z = h;
                }
                run.push(seg);
            }
            other => {
                flush(&mut run, run_z, &mut out);
                run_z = f64::NAN;
                z = match &other {
                    MillMove::RapidZ(h) | MillMove::Plunge(h) | MillMove::Cut { z: h, .. } => *h,
                    _ => z,
                };
                out.push(other);
            }
        }
    }
    flush(&mut run, run_z, &mut out);
    t.moves = out;
    let (lines_after, arcs_after) = count(t);
    ArcFit {
        lines_before,
        arcs_before,
        lines_after,
        arcs_after,
        tolerance: tol,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;

    #[test]
    fn flat_runs_are_fitted_and_ramps_and_rapids_kept() {
        let p = |x: f64, y: f64| Point::new(x, y);
        let mut t = Toolpath::default();
        t.moves.push(MillMove::Rapid(p(0.0, 0.0)));
        t.moves.push(MillMove::Plunge(-1.0));
        // 10 collinear moves at Z-1, a note, 10 more.
        for k in 0..10 {
            let seg = Segment::line(p(k as f64, 0.0), p(k as f64 + 1.0, 0.0));
            t.moves.push(MillMove::Cut { seg, z: -1.0 });
        }
        t.moves.push(MillMove::Note("x".into()));
        for k in 10..20 {
            let seg = Segment::line(p(k as f64, 0.0), p(k as f64 + 1.0, 0.0));
            t.moves.push(MillMove::Cut { seg, z: -1.0 });
        }
        // A ramp down along the same line in two moves: kept.
        for k in 20..22 {
            let seg = Segment::line(p(k as f64, 0.0), p(k as f64 + 1.0, 0.0));
            t.moves.push(MillMove::Cut {
                seg,
                z: -1.0 - (k - 19) as f64,
            });
        }
        // Then flat at Z-3: 5 collinear moves.
        for k in 22..27 {
            let seg = Segment::line(p(k as f64, 0.0), p(k as f64 + 1.0, 0.0));
            t.moves.push(MillMove::Cut { seg, z: -3.0 });
        }
        let f = fit_arcs(&mut t, 0.01);
        assert_eq!((f.lines_before, f.lines_after), (27, 5));
        let cuts: Vec<(f64, f64, f64)> = (t.moves.iter())
            .filter_map(|m| match m {
                MillMove::Cut { seg, z } => Some((seg.a.x, seg.b.x, *z)),
                _ => None,
            })
            .collect();
        assert_eq!(
            cuts,
            [
                (0.0, 10.0, -1.0),
                (10.0, 20.0, -1.0),
                (20.0, 21.0, -2.0),
                (21.0, 22.0, -3.0),
                (22.0, 27.0, -3.0)
            ]
        );
        assert!(matches!(t.moves[3], MillMove::Note(_)));
    }
}
