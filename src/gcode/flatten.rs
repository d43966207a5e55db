//! Arcs as the points a line-only machine visits: the flattening shared by
//! the point-list program (paper 002, `point_list.rs`) and the tangential
//! knife (paper 003, `knife.rs`), neither of which owns it.

use crate::geom::{flatten_count, Point, Segment};

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
pub(super) fn points(segs: &[Segment], segment_length: f64, chord: f64) -> Vec<Point> {
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
