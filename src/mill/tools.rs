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

/// One tool's layers at one depth: what [`plan_tools`] mills as a job of
/// its own (a tool's layers at several depths are several, one after the
/// other, with no change between).
#[derive(Clone, Debug)]
pub struct Work {
    /// The tool, its feed and the layers' direction ([`crate::process::Tool::climb`]).
    pub tool: MillTool,
    /// The layers' pockets, engravings and holes.
    pub geometry: MillGeometry,
    /// Their depth and passes.
    pub passes: Passes,
    /// The layers' names, for the report.
    pub layers: Vec<String>,
}

/// Layers milled at one depth with one tool (issue 43 §1), in the order
/// they are machined: what the report says of each layer's depth.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthShare {
    /// The layers.
    pub layers: Vec<String>,
    /// Their tool's number.
    pub tool: u32,
    /// Their depth and deepest pass (`passes.count()` passes).
    pub passes: Passes,
    /// Climb (true) or conventional finishing passes.
    pub climb: bool,
}

/// How each tool's milling is finished before the next one's.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    /// Arc-fit each tool's moves (the job's `--fit-arcs`).
    pub fit_arcs: bool,
    /// Sweep each tool's disc along its pockets (`--verify`).
    pub verify: bool,
}

/// Mills `works` in their order from `from`: each as a job of its own,
/// from where the one before ended, at its own depth; the moves joined
/// with a tool change where the tool differs from the one before (the
/// first included, unless it is the job's own, `job_tool`), the reports
/// added up per tool.
pub fn plan_tools(
    works: &[Work],
    job_tool: u32,
    h: Heights,
    from: Point,
    finish: Finish,
) -> Milled {
    let mut out = Milled::default();
    out.toolpath.start = from;
    let mut at = from;
    let mut current = job_tool;
    for w in works {
        let (t, g) = (&w.tool, &w.geometry);
        let mut m = plan(g, &t.tool, w.passes, h, at);
        if finish.fit_arcs {
            m.fit_arcs(h.tolerance, h.retract);
        }
        if finish.verify {
            m.verify(t.tool.radius(), w.passes.depth, h.retract, h.tolerance);
        }
        at = m.toolpath.end();
        let change = t.tool.number != current;
        match out.tools.last_mut() {
            Some(s) if !change => {
                s.pockets += m.pockets.len();
                s.engravings += g.engraves.len();
                s.holes += m.holes;
                s.stats = s.stats.plus(&m.stats);
            }
            _ => out.tools.push(ToolShare {
                tool: *t,
                pockets: m.pockets.len(),
                engravings: g.engraves.len(),
                holes: m.holes,
                stats: m.stats,
            }),
        }
        current = t.tool.number;
        if !w.layers.is_empty() {
            out.depths.push(DepthShare {
                layers: w.layers.clone(),
                tool: t.tool.number,
                passes: w.passes,
                climb: t.tool.climb,
            });
        }
        join(&mut out, m, change.then_some(*t));
    }
    // The job's own tool alone (layers at several depths): no tool list.
    if out.tools.len() == 1 && current == job_tool {
        out.tools.clear();
    }
    out.stats = out.toolpath.stats(from, h.retract);
    out
}

/// `m` (one tool's milling) after what `out` holds, with the change to
/// `tool` before its moves when it is one.
fn join(out: &mut Milled, m: Milled, tool: Option<MillTool>) {
    let notes = super::notes(&out.toolpath);
    out.toolpath.moves.extend(tool.map(MillMove::ToolChange));
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
