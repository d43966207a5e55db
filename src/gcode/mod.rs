//! Stage 5: [`CutPlan`] → RS274/NGC program text for LinuxCNC.
//!
//! # Output contract
//! - G21 G90 G17 G40 G91.1 (mm, absolute, XY plane, no cutter compensation —
//!   the kerf is already in the path —, arc centres I/J relative to the arc
//!   start); G0 rapids, G1 lines, G2/G3 arcs; M3 torch on, M5 torch off, an
//!   optional G4 pierce delay; F from the settings; M2 at the end.
//! - Every coordinate is rounded to a fixed grid of `decimals` places, and
//!   the machine position is tracked on that grid, so what the program says
//!   is where the machine is. Each arc's rounded centre is chosen among the
//!   grid points around the true centre so that the start and end radii agree
//!   to within one grid step: LinuxCNC never reports "radius to end of arc
//!   differs". An arc whose rounded ends coincide would read as a full circle,
//!   and is never written; an arc too flat to tell from its chord is a G1.
//! - Arcs are at most 180° (the plan's segments are), never full circles.
//! - Comments carry only our own words and numbers, sanitised ([`comment`]).

mod number;

use crate::contour::ContourKind;
use crate::geom::Segment;
use crate::plan::{CutPlan, Move};
use number::Grid;

/// Program settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GcodeOptions {
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Decimal places of every coordinate (1..=6).
    pub decimals: u32,
    /// Dwell after torch on, seconds (0 = none).
    pub pierce_delay: f64,
    /// Kerf width, for the header comment.
    pub kerf: f64,
}

impl GcodeOptions {
    /// 2000 mm/min, 3 decimals, no pierce delay.
    pub const DEFAULT: GcodeOptions = GcodeOptions {
        feed: 2000.0,
        decimals: 3,
        pierce_delay: 0.0,
        kerf: 0.0,
    };
}

/// Text safe inside `( )`: no parentheses, no `;`, no line breaks or other
/// control characters, ASCII only (some controllers choke on anything else).
pub fn comment(text: &str) -> String {
    let clean: String = text
        .chars()
        .map(|c| match c {
            '(' | ')' | ';' | '%' => ' ',
            c if c.is_ascii_graphic() || c == ' ' => c,
            _ => '?',
        })
        .take(120)
        .collect();
    format!("({})", clean.trim())
}

/// Writes the program.
pub fn emit(plan: &CutPlan, options: &GcodeOptions) -> String {
    let grid = Grid::new(options.decimals);
    let mut out =
        String::with_capacity(64 + plan.cuts.iter().map(|c| c.steps.len() * 32).sum::<usize>());
    let mut line = |s: &str| {
        out.push_str(s);
        out.push('\n');
    };
    let holes = plan
        .cuts
        .iter()
        .filter(|c| c.kind == ContourKind::Hole)
        .count();
    line("%");
    line(&comment(&format!(
        "kerfcam {} - LinuxCNC",
        env!("CARGO_PKG_VERSION")
    )));
    line(&comment(&format!(
        "cuts {}: outer {}, holes {}, kerf {} mm, feed {} mm/min",
        plan.cuts.len(),
        plan.cuts.len() - holes,
        holes,
        grid.fmt_mm(options.kerf),
        grid.fmt_mm(options.feed)
    )));
    line("G21 G90 G17 G40 G91.1");
    line(&format!("F{}", grid.fmt_mm(options.feed)));
    let mut pos = grid.snap(plan.origin);
    for m in plan.moves() {
        match m {
            Move::Rapid(p) => {
                let q = grid.snap(p);
                line(&format!("G0 X{} Y{}", grid.fmt(q.0), grid.fmt(q.1)));
                pos = q;
            }
            Move::Pierce(i) => {
                if let Some(c) = plan.cuts.get(i) {
                    let what = match c.kind {
                        ContourKind::Hole => "hole",
                        _ => "outer",
                    };
                    line(&comment(&format!(
                        "cut {} part {} {} contour {}",
                        i + 1,
                        c.part.map_or("-".to_string(), |p| p.to_string()),
                        what,
                        c.contours.first().map_or(0, |k| k + 1)
                    )));
                }
                line("M3 S1");
                if options.pierce_delay > 0.0 {
                    line(&format!("G4 P{}", grid.fmt_mm(options.pierce_delay)));
                }
            }
            Move::Feed(step) => {
                for block in cut_blocks(&grid, &mut pos, &step.segment) {
                    line(&block);
                }
            }
            Move::TorchOff => line("M5"),
            Move::Spot(_) => {
                line("M3 S1");
                if options.pierce_delay > 0.0 {
                    line(&format!("G4 P{}", grid.fmt_mm(options.pierce_delay)));
                }
                line("M5");
            }
        }
    }
    line("M2");
    line("%");
    out
}

/// Blocks for one cutting segment from the grid position `pos` (updated).
fn cut_blocks(grid: &Grid, pos: &mut (i64, i64), s: &Segment) -> Vec<String> {
    let end = grid.snap(s.b);
    if end == *pos {
        // Shorter than the grid: nothing the machine can do.
        return vec![];
    }
    if let Some((c, r)) = s.arc_center() {
        let sagitta = r * (1.0 - (s.sweep().abs() / 2.0).cos());
        if sagitta > grid.step() / 2.0 {
            if let Some((i, j)) = grid.arc_center(*pos, end, c) {
                let g = if s.is_ccw() { "G3" } else { "G2" };
                *pos = end;
                return vec![format!(
                    "{g} X{} Y{} I{} J{}",
                    grid.fmt(end.0),
                    grid.fmt(end.1),
                    grid.fmt(i),
                    grid.fmt(j)
                )];
            }
            // No grid centre fits both ends: cut the arc as short lines within half a grid step.
            return linearise(grid, pos, s, r);
        }
    }
    *pos = end;
    vec![format!("G1 X{} Y{}", grid.fmt(end.0), grid.fmt(end.1))]
}

fn linearise(grid: &Grid, pos: &mut (i64, i64), s: &Segment, r: f64) -> Vec<String> {
    let max_err = grid.step() / 2.0;
    let step = 2.0 * (1.0 - max_err / r).clamp(-1.0, 1.0).acos();
    let n = ((s.sweep().abs() / step.max(1e-3)).ceil() as usize).clamp(1, 10_000);
    let mut blocks = Vec::with_capacity(n);
    for k in 1..=n {
        let q = grid.snap(s.point_at(k as f64 / n as f64));
        if q != *pos {
            blocks.push(format!("G1 X{} Y{}", grid.fmt(q.0), grid.fmt(q.1)));
            *pos = q;
        }
    }
    blocks
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;

    #[test]
    fn comments_cannot_break_out_or_inject_blocks() {
        let c = comment("layer (x)\nG0 X0; M3");
        assert_eq!(c, "(layer  x ?G0 X0  M3)");
        assert_eq!(c.matches('(').count(), 1);
        assert_eq!(c.matches(')').count(), 1);
        assert!(!c.contains('\n') && !c.contains(';'));
    }

    #[test]
    fn a_half_circle_is_one_g3_with_a_consistent_centre() {
        let grid = Grid::new(3);
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let mut pos = grid.snap(s.a);
        let b = cut_blocks(&grid, &mut pos, &s);
        assert_eq!(b, vec!["G3 X-10 Y0 I-10 J0".to_string()]);
    }

    #[test]
    fn an_arc_shorter_than_the_grid_is_not_written() {
        let grid = Grid::new(3);
        let s = Segment {
            a: Point::new(0.0, 0.0),
            b: Point::new(0.0002, 0.0),
            bulge: 0.5,
        };
        let mut pos = grid.snap(s.a);
        assert!(cut_blocks(&grid, &mut pos, &s).is_empty());
    }
}
