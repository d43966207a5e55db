//! Nearest-neighbour construction respecting precedence: a site becomes
//! available once all its children are visited; the tool goes to the nearest
//! candidate point of any available site (the baseline of issue 4 §3).

use super::grid::Grid;
use super::Inst;
use crate::geom::Point;

/// Items per grid cell: about one site's worth of nearby points.
const PER_CELL: f64 = 4.0;

/// The empty grid [`nearest_neighbour`] fills, over all of `inst`'s
/// candidates: made once for both of a tour's constructions (the same
/// points; the second one's cells were found again, two divisions a
/// point).
pub(super) fn grid(inst: &Inst) -> Grid {
    Grid::new(inst.pts.items(), PER_CELL)
}

/// The nearest-neighbour sequence of visitable sites and each site's chosen
/// candidate (index into `inst.pts[site]`; 0 for sites not visited), in
/// `grid`, an empty [`grid`] of `inst` (or of an instance with the same
/// candidates).
pub(super) fn nearest_neighbour(
    inst: &Inst,
    origin: Point,
    mut grid: Grid,
) -> (Vec<usize>, Vec<usize>) {
    let n = inst.pts.len();
    // All candidate points, site after site (the instance keeps them so):
    // item `id` is candidate `id - first[s]` of site `site_of[id]`.
    let first = inst.pts.offsets();
    let all: &[Point] = inst.pts.items();
    let mut site_of: Vec<u32> = Vec::with_capacity(all.len());
    for s in 0..n {
        site_of.extend(std::iter::repeat_n(s as u32, first[s + 1] - first[s]));
    }
    let point = |id: u32| all[id as usize];
    let mut waiting: Vec<usize> = inst.kids.iter().map(<[usize]>::len).collect();
    let mut done = vec![false; n];
    let open = |s: usize, grid: &mut Grid| {
        for id in first[s]..first[s + 1] {
            grid.insert_nth(id);
        }
    };
    for &s in &inst.active {
        if waiting[s] == 0 {
            open(s, &mut grid);
        }
    }
    let mut seq = Vec::with_capacity(inst.active.len());
    let mut at = vec![0usize; n];
    let mut here = origin;
    while seq.len() < inst.active.len() {
        let alive = |id: u32| !done[site_of[id as usize] as usize];
        let Some((id, _)) = grid.nearest(here, point, alive) else {
            break; // cannot happen on a forest; never loop
        };
        let s = site_of[id as usize] as usize;
        let c = id as usize - first[s];
        done[s] = true;
        seq.push(s);
        at[s] = c;
        here = all[id as usize];
        if let Some(u) = inst.up[s] {
            waiting[u] = waiting[u].saturating_sub(1);
            if waiting[u] == 0 {
                open(u, &mut grid);
            }
        }
    }
    (seq, at)
}
