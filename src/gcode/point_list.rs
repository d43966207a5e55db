//! Paper 002's point-list program (Richetti & da Silva, "Programa CN"):
//! one `x;y` row per point, `D` (desliga) on a row moved to with the torch
//! off, `L` (liga) on the first row cut after the torch goes on, a bare `L`
//! for a spot, a bare `D` at the end. The stepper driver only interpolates
//! lines, so arcs and circles are split into n = floor(arc length /
//! resolution) equal pieces (the paper's "resolução", 10 mm in its example).

use crate::geom::{flatten_count, Point, Segment};
use crate::plan::CutPlan;

use super::number::Grid;
use super::post::Post;

/// A run of feed moves as a line or an arc made of consecutive co-circular
/// arcs (a DXF circle is two half arcs: the paper splits the whole circle).
#[derive(Clone, Copy, Debug)]
enum Run {
    Line(Point),
    Arc {
        c: Point,
        r: f64,
        start: f64,
        sweep: f64,
        end: Point,
    },
}

fn runs(segs: &[Segment]) -> Vec<Run> {
    let mut out: Vec<Run> = Vec::with_capacity(segs.len());
    for s in segs {
        let Some((c, r)) = s.arc_center() else {
            out.push(Run::Line(s.b));
            continue;
        };
        let a0 = s.a.sub(c);
        let sweep = s.sweep();
        if let Some(Run::Arc {
            c: pc,
            r: pr,
            sweep: ps,
            end,
            ..
        }) = out.last_mut()
        {
            let eps = 1e-6 * pr.max(1.0);
            if pc.dist(c) <= eps && (*pr - r).abs() <= eps && (*ps > 0.0) == (sweep > 0.0) {
                *ps += sweep;
                *end = s.b;
                continue;
            }
        }
        out.push(Run::Arc {
            c,
            r,
            start: a0.y.atan2(a0.x),
            sweep,
            end: s.b,
        });
    }
    out
}

/// The points a straight-line machine visits along `segs` (the start not
/// included): lines as they are, arcs in n equal pieces, n =
/// floor(length / `segment_length`) when that is set, else from the chord
/// tolerance (paper 004).
pub(crate) fn points(segs: &[Segment], segment_length: f64, chord: f64) -> Vec<Point> {
    let mut out = Vec::new();
    for run in runs(segs) {
        match run {
            Run::Line(p) => out.push(p),
            Run::Arc {
                c,
                r,
                start,
                sweep,
                end,
            } => {
                let n = if segment_length > 0.0 {
                    ((r * sweep.abs() / segment_length).floor() as usize).clamp(1, 100_000)
                } else {
                    flatten_count(r, sweep.abs(), chord)
                };
                for k in 1..n {
                    let a = start + sweep * k as f64 / n as f64;
                    out.push(Point::new(c.x + r * a.cos(), c.y + r * a.sin()));
                }
                out.push(end);
            }
        }
    }
    out
}

/// Writes the point list.
pub(crate) fn write(plan: &CutPlan, post: &Post) -> String {
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let k = super::emit::unit_scale(post);
    let mut out = String::new();
    let mut row = |p: Option<(i64, i64)>, code: &str| {
        if let Some(q) = p {
            out.push_str(&format!("{};{}", grid.fmt(q.0), grid.fmt(q.1)));
            if !code.is_empty() {
                out.push(' ');
            }
        }
        out.push_str(code);
        out.push('\n');
    };
    let mut pos: Option<(i64, i64)> = None;
    for c in &plan.cuts {
        let q = grid.snap(c.pierce.scale(k));
        // Torch off and move; already there: torch off in place.
        row((pos != Some(q)).then_some(q), "D");
        pos = Some(q);
        if c.spot {
            row(None, "L");
            continue;
        }
        let segs: Vec<Segment> = c.steps.iter().map(|s| s.segment).collect();
        let mut code = "L";
        for p in points(&segs, post.segment_length, post.chord) {
            let q = grid.snap(p.scale(k));
            if Some(q) == pos {
                continue;
            }
            row(Some(q), code);
            code = "";
            pos = Some(q);
        }
    }
    row(None, "D");
    out
}
