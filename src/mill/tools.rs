//! A job with several tools (issue 43 §1): each tool's layers milled as
//! one tool's job ([`super::plan`]), fitted and verified at its own
//! radius, one tool after the other — all the work of one tool, then the
//! change ([`MillMove::ToolChange`] before each tool's moves, the first's
//! too: the program's header takes it).

use super::{plan, Heights, MillMove, Milled};
use crate::geom::Point;
use crate::process::layers::MillGeometry;
use crate::process::{MillTool, Passes};

/// What one tool of a job machines.
#[derive(Clone, Debug, PartialEq)]
pub struct ToolShare {
    /// The tool and its feed.
    pub tool: MillTool,
    /// Pockets it cleared.
    pub pockets: usize,
    /// Paths it engraved.
    pub engravings: usize,
    /// Holes it drilled.
    pub holes: usize,
    /// Its moves' lengths (from the retract height where the tool before
    /// left it), what its time is counted from at its own feeds.
    pub stats: super::MillStats,
}

/// How each tool's milling is finished before the next one's.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    /// Arc-fit each tool's moves (the job's `--fit-arcs`).
    pub fit_arcs: bool,
    /// Sweep each tool's disc along its pockets (`--verify`).
    pub verify: bool,
}

/// Mills `works` in their order from `from`: each tool's geometry as a
/// job of its own, from where the tool before ended; the moves joined
/// with a tool change before each tool's, the reports added up.
pub fn plan_tools(
    works: &[(MillTool, MillGeometry)],
    passes: Passes,
    h: Heights,
    from: Point,
    finish: Finish,
) -> Milled {
    let mut out = Milled::default();
    out.toolpath.start = from;
    let mut at = from;
    for (t, g) in works {
        let mut m = plan(g, &t.tool, passes, h, at);
        if finish.fit_arcs {
            m.fit_arcs(h.tolerance, h.retract);
        }
        if finish.verify {
            m.verify(t.tool.radius(), passes.depth, h.retract, h.tolerance);
        }
        at = m.toolpath.end();
        out.tools.push(ToolShare {
            tool: *t,
            pockets: m.pockets.len(),
            engravings: g.engraves.len(),
            holes: m.holes,
            stats: m.stats,
        });
        join(&mut out, m, *t);
    }
    out.stats = out.toolpath.stats(from, h.retract);
    out
}

/// `m` (one tool's milling) after what `out` holds, with the change to
/// `tool` before its moves.
fn join(out: &mut Milled, m: Milled, tool: MillTool) {
    let notes = super::notes(&out.toolpath);
    out.toolpath.moves.push(MillMove::ToolChange(tool));
    out.toolpath.moves.extend(m.toolpath.moves);
    out.toolpath.lifts += m.toolpath.lifts;
    out.pockets.extend(m.pockets);
    out.holes += m.holes;
    out.drawn.extend(m.drawn);
    out.warnings.extend(m.warnings);
    out.engraving = out.engraving.or(m.engraving);
    out.spans
        .extend(m.spans.into_iter().map(|s| super::sweep::PocketSpan {
            first: s.first + notes,
            end: s.end + notes,
            ..s
        }));
    if let Some(f) = m.arc_fit {
        let sum = out.arc_fit.get_or_insert(crate::plan::ArcFit {
            tolerance: f.tolerance,
            ..Default::default()
        });
        sum.lines_before += f.lines_before;
        sum.arcs_before += f.arcs_before;
        sum.lines_after += f.lines_after;
        sum.arcs_after += f.arcs_after;
    }
    if let Some(s) = m.swept {
        let sum = out.swept.get_or_insert(super::sweep::Swept {
            cell: s.cell,
            ..Default::default()
        });
        sum.gouge_mm2 += s.gouge_mm2;
        sum.gouge_at = sum.gouge_at.or(s.gouge_at);
        sum.left_mm2 += s.left_mm2;
        sum.left_at = sum.left_at.or(s.left_at);
        sum.unreachable_mm2 += s.unreachable_mm2;
        sum.cell = sum.cell.min(s.cell);
    }
}
