//! Zig-zag clearing (paper 004 §2.7, thesis L893, L1022–L1024): parallel
//! passes a stepover apart at a chosen angle, alternating direction, the
//! tool kept down from the end of one pass to the start of the next
//! wherever the link stays in the tool-centre region — straight across,
//! or along the wall between them. Where an island blocks the way the
//! pass is diverted to the next one reachable and what was left behind
//! is picked up after, from a new start: only there does the tool lift.

use super::region::Region;
use crate::geom::Point;

/// Passes linked into chains; the tool lifts between chains.
pub fn chains(region: &Region, stepover: f64, angle_deg: f64, eps: f64) -> Vec<Vec<Point>> {
    if region.is_empty() || stepover.is_nan() || stepover <= 0.0 {
        return Vec::new();
    }
    let (sin, cos) = angle_deg.to_radians().sin_cos();
    // Into the frame where passes run along X, and back.
    let to = |p: Point| Point::new(p.x * cos + p.y * sin, -p.x * sin + p.y * cos);
    let back = |p: Point| Point::new(p.x * cos - p.y * sin, p.x * sin + p.y * cos);
    let loops: Vec<Vec<Point>> = (region.loops.iter())
        .map(|l| l.points.iter().map(|&p| to(p)).collect())
        .collect();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in loops.iter().flatten() {
        lo = lo.min(p.y);
        hi = hi.max(p.y);
    }
    // The first and last passes just inside the extremes (a pass along a
    // tangent would be a point); the rest evenly, at most a stepover apart.
    let inset = (stepover / 10.0).min(10.0 * eps).min((hi - lo) / 2.0);
    let span = (hi - lo - 2.0 * inset).max(0.0);
    let n = (span / stepover).ceil().max(0.0) as usize;
    let rows: Vec<(f64, Vec<(f64, f64)>)> = (0..=n)
        .map(|k| {
            let y = if n == 0 {
                (lo + hi) / 2.0
            } else {
                lo + inset + span * k as f64 / n as f64
            };
            (y, intervals(&loops, y, eps))
        })
        .collect();
    let mut done: Vec<Vec<bool>> = rows.iter().map(|(_, iv)| vec![false; iv.len()]).collect();
    let mut out: Vec<Vec<Point>> = Vec::new();
    let mut at: Option<Point> = None;
    // A new start: the lowest row with a pass left, the end nearest the tool.
    while let Some(k0) = (0..rows.len()).find(|&k| done[k].iter().any(|d| !d)) {
        let (y0, iv0) = &rows[k0];
        let pick = (0..iv0.len())
            .filter(|&i| !done[k0][i])
            .flat_map(|i| [(i, true), (i, false)])
            .min_by(|a, b| {
                let end = |(i, fwd): (usize, bool)| {
                    let x = if fwd { iv0[i].0 } else { iv0[i].1 };
                    at.map_or(if fwd { 0.0 } else { 1.0 }, |t| {
                        back(Point::new(x, *y0)).dist(t)
                    })
                };
                end(*a).total_cmp(&end(*b))
            });
        let Some((mut i, mut fwd)) = pick else { break };
        let mut k = k0;
        let mut chain: Vec<Point> = Vec::new();
        loop {
            let (y, iv) = &rows[k];
            let (x0, x1) = if fwd { iv[i] } else { (iv[i].1, iv[i].0) };
            let (a, b) = (back(Point::new(x0, *y)), back(Point::new(x1, *y)));
            if chain.last() != Some(&a) {
                chain.push(a);
            }
            chain.push(b);
            done[k][i] = true;
            // The next pass: on the next row, entered from the end nearest
            // this one's, back the other way.
            let Some((ny, niv)) = rows.get(k + 1) else {
                break;
            };
            let mut best: Option<(usize, Vec<Point>, f64)> = None;
            for j in (0..niv.len()).filter(|&j| !done[k + 1][j]) {
                let sx = if fwd { niv[j].1 } else { niv[j].0 };
                let s = back(Point::new(sx, *ny));
                let link = if region.holds_line(b, s, eps) {
                    Some(vec![b, s])
                } else {
                    region
                        .walk(b, s, eps)
                        .filter(|w| path_len(w) <= 3.0 * stepover + b.dist(s))
                };
                if let Some(w) = link {
                    let l = path_len(&w);
                    if best.as_ref().is_none_or(|(_, _, bl)| l < *bl) {
                        best = Some((j, w, l));
                    }
                }
            }
            let Some((j, w, _)) = best else { break };
            chain.extend(w.into_iter().skip(1));
            k += 1;
            i = j;
            fwd = !fwd;
        }
        at = chain.last().copied();
        out.push(chain);
    }
    out
}

fn path_len(w: &[Point]) -> f64 {
    w.windows(2).map(|p| p[0].dist(p[1])).sum()
}

/// The stretches of the line at height `y` inside the loops (even-odd),
/// longer than `eps`, from left to right.
fn intervals(loops: &[Vec<Point>], y: f64, eps: f64) -> Vec<(f64, f64)> {
    let mut xs = Vec::new();
    for l in loops {
        let n = l.len();
        for i in 0..n {
            let (a, b) = (l[i], l[(i + 1) % n]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.chunks_exact(2)
        .map(|c| (c[0], c[1]))
        .filter(|(a, b)| b - a > eps)
        .collect()
}
