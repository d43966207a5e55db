//! Cut order: everything inside a contour before the contour itself,
//! nearest-next among siblings.
//!
//! The containment tree (parts → holes → islands → their holes …) is walked
//! depth first with an explicit stack, so a file of thousands of nested
//! contours cannot overflow the (small, in wasm) call stack. Among the
//! children of one contour, the one whose path box is nearest the tool goes
//! next. This is the nearest-neighbour construction; better tours are a
//! later stage's job.

use crate::geom::{path_bbox, BBox, Point};
use crate::kerf::KerfPaths;

/// Squared distance from `p` to a box (0 inside); squared, as only the order matters.
fn box_dist(b: &BBox, p: Point) -> f64 {
    let dx = (b.min.x - p.x).max(0.0).max(p.x - b.max.x);
    let dy = (b.min.y - p.y).max(0.0).max(p.y - b.max.y);
    dx * dx + dy * dy
}

/// Path indices in cutting order.
///
/// `parents[c]` is the smallest closed contour containing contour `c`.
pub fn holes_first_nearest(
    paths: &KerfPaths,
    parents: &[Option<usize>],
    origin: Point,
) -> Vec<usize> {
    let n = parents.len();
    let mut path_of: Vec<Option<usize>> = vec![None; n];
    for (k, p) in paths.paths.iter().enumerate() {
        if p.contour < n {
            path_of[p.contour] = Some(k);
        }
    }
    // Boxes of contours; a contour without a path (a hole that vanished under the kerf)
    // still orders its islands, so it gets the union of theirs.
    let boxes: Vec<BBox> = paths.paths.iter().map(|p| path_bbox(&p.segments)).collect();
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut roots = Vec::new();
    // Only contours that have a path, or hold one, take part.
    let mut relevant = vec![false; n];
    let with_path: Vec<(usize, usize)> = path_of
        .iter()
        .enumerate()
        .filter_map(|(c, k)| k.map(|k| (c, k)))
        .collect();
    for &(c, _) in &with_path {
        let mut x = Some(c);
        while let Some(i) = x {
            if relevant[i] && i != c {
                break;
            }
            relevant[i] = true;
            x = parents[i];
        }
    }
    for c in (0..n).filter(|&c| relevant[c]) {
        match parents[c] {
            Some(p) if p < n => children[p].push(c),
            _ => roots.push(c),
        }
    }
    let mut contour_box = vec![BBox::EMPTY; n];
    for &(c, k) in &with_path {
        let mut x = Some(c);
        while let Some(i) = x {
            contour_box[i].union(&boxes[k]);
            x = parents[i];
        }
    }

    let mut order = Vec::with_capacity(paths.paths.len());
    let mut at = origin;
    // Frame: (contour to cut when its children are done, children left).
    let mut stack: Vec<(Option<usize>, Vec<usize>)> = vec![(None, roots)];
    while let Some((contour, remaining)) = stack.last_mut() {
        if remaining.is_empty() {
            if let Some(k) = contour.and_then(|c| path_of[c]) {
                order.push(k);
                // The planner pierces at the vertex nearest the tool, and the loop ends there.
                if let Some(v) = paths.paths[k]
                    .segments
                    .iter()
                    .map(|s| s.a)
                    .min_by(|a, b| a.dist(at).total_cmp(&b.dist(at)))
                {
                    at = v;
                }
            }
            stack.pop();
            continue;
        }
        let best = (0..remaining.len())
            .min_by(|&i, &j| {
                box_dist(&contour_box[remaining[i]], at)
                    .total_cmp(&box_dist(&contour_box[remaining[j]], at))
            })
            .unwrap_or(0);
        let next = remaining.swap_remove(best);
        let grandchildren = std::mem::take(&mut children[next]);
        stack.push((Some(next), grandchildren));
    }
    order
}
