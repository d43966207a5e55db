//! Paper 003's tangential-knife program (Vidal Filho et al., table 1b):
//! relative rows `z Δx Δy Δθ`. The knife is turned in place before each
//! straight move (a row `0 0 0 Δθ`, as the paper's table writes turns), then
//! moved (`1 Δx Δy 0` cutting, `0 Δx Δy 0` travelling); arcs become straight
//! moves within the chord tolerance. Every Δ is a difference of grid points,
//! so the rows add up exactly to the absolute positions (no drift).

use crate::geom::Segment;
use crate::plan::CutPlan;

use super::flatten::points;
use super::number::Grid;
use super::post::Post;

struct Knife {
    grid: Grid,
    out: String,
    pos: (i64, i64),
    /// Heading in grid units of a degree.
    heading: i64,
}

impl Knife {
    fn go(&mut self, q: (i64, i64), z: u8) {
        let (dx, dy) = (q.0 - self.pos.0, q.1 - self.pos.1);
        if (dx, dy) == (0, 0) {
            return;
        }
        let scale = self.grid.scale();
        let full = (360.0 * scale).round() as i64;
        let want = ((dy as f64).atan2(dx as f64).to_degrees() * scale).round() as i64;
        let mut turn = (want - self.heading).rem_euclid(full);
        if turn > full / 2 {
            turn -= full;
        }
        let g = &self.grid;
        if turn != 0 {
            self.out
                .push_str(&format!("0 {} {} {}\n", g.fmt(0), g.fmt(0), g.fmt(turn)));
            self.heading = (self.heading + turn).rem_euclid(full);
        }
        self.out
            .push_str(&format!("{z} {} {} {}\n", g.fmt(dx), g.fmt(dy), g.fmt(0)));
        self.pos = q;
    }
}

/// Writes the relative rows (the knife starts at the plan's origin, heading 0°).
pub(crate) fn write(plan: &CutPlan, post: &Post) -> String {
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let k = post.unit_scale();
    let mut kn = Knife {
        grid,
        out: String::new(),
        pos: grid.snap(plan.origin.scale(k)),
        heading: 0,
    };
    for c in &plan.cuts {
        kn.go(grid.snap(c.pierce.scale(k)), 0);
        let segs: Vec<Segment> = c.steps.iter().map(|s| s.segment).collect();
        for p in points(&segs, post.segment_length, post.chord) {
            kn.go(grid.snap(p.scale(k)), 1);
        }
    }
    kn.out
}
